#pragma once
// Foot contacts: when a foot is planted, detected from its ankle's height above the standing ankle height and its
// horizontal speed, with hysteresis so that a contact does not flicker.
//
// Thresholds are fractions of the leg length L (thigh + shin), so they suit any size of actor:
//   enter a contact when height < 0.03 L and speed < 0.2 L/s; leave it when height > 0.05 L or speed > 0.4 L/s.
// For a 0.85 m leg: enter within 2.5 cm of the standing ankle height below 17 cm/s, leave above 4.2 cm or
// 34 cm/s (a planted Bandai foot moves under 7 cm/s; heel-off passes 20 cm/s within two frames). A foot that
// slides more than 0.008 L (7 mm) from where its contact began, as in a fighter's shuffle, ends that contact and
// starts a new one, so a contact is a foot that stays put.

#include "kumite/core/rest_anatomy.h"

#include <vector>

namespace kumite {

struct FootContactThresholds {
    double enter_height = 0.03; // x leg length, above the standing ankle height
    double leave_height = 0.05;
    double enter_speed = 0.2;   // x leg length per second
    double leave_speed = 0.4;
    double max_slide = 0.008;   // x leg length: a foot that slides farther starts a new contact
};

struct ContactInterval {
    int first_frame = 0;
    int last_frame = 0; // inclusive
};

// ankle_positions: [frame] world positions of one ankle, metres; standing_ankle_y: the height of a flat-footed
// ankle in the same world. Returns the planted intervals in frame order (none when frame_time_s is not > 0).
std::vector<ContactInterval> foot_contacts_detect(const std::vector<Eigen::Vector3d>& ankle_positions, double frame_time_s,
                                                  double leg_length, double standing_ankle_y,
                                                  const FootContactThresholds& thresholds = {});

} // namespace kumite
