#pragma once
// The user's answers to the fighter's blows (user_response.h), watched every frame. Owns: the blows still watched
// (a few at once: a combination's blows overlap their counter windows), the user's head and hands of the last
// frame. Touches: the event log (user_response, once a blow's counter window is over). Reads: this frame's events
// (the strike's start, its contact, the user's strikes and how they ended), the strike under way (its striking
// part and target), the user. Nothing allocates.

#include "fighter/event_log.h"
#include "fighter/tracked_user.h"

#include "kumite/runtime/user_response.h"

#include <Eigen/Core>

#include <array>

namespace kumite {

class ResponseWatch {
public:
    explicit ResponseWatch(const ResponseSettings& settings) : m_settings(settings) {}

    // The blow under way this frame: where its striking part is and what it aims at (world); none between strikes.
    struct Blow {
        bool striking = false;
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        Eigen::Vector3d target = Eigen::Vector3d::Zero();
        Eigen::Vector3d fighter = Eigen::Vector3d::Zero(); // the fighter's pelvis over the floor, striking or not
    };
    // After the frame's strike, defence and moves: reads the frame's events in `log` and adds user_response events.
    void watch(double t_s, const Blow& blow, const TrackedUser& user, EventLog& log);

private:
    enum Channel { head_back, head_off_line, glove_left, glove_right, k_channels };
    struct Watched {
        bool active = false;
        UserResponse response;
        FighterEvent strike;            // the contact's event (once it came): what the blow was and became
        bool have_contact = false;
        bool have_line = false;
        bool line_final = false;        // the blow came within 15 cm of its target: its line is the way it arrives
        Eigen::Vector3d point = Eigen::Vector3d::Zero(), target = Eigen::Vector3d::Zero(); // the blow's path, last seen
                                                                                           // over 15 cm from its target
        Eigen::Vector3d floor_way = Eigen::Vector3d::Zero(); // from the fighter to the user on the floor when it began
        std::array<bool, k_channels> was_below{};   // the channel was under its threshold since the strike began
        std::array<double, k_channels> rising_s{};  // the frame it went over (held one more frame: the answer), or -1
        bool downwards = false;                     // head_off_line: mostly down when it rose
        int glove_side = -1;                        // the glove that answered
        Eigen::Vector3d glove_at_rise = Eigen::Vector3d::Zero(); // that glove when it rose
        bool crossed = false;                       // the glove went on across the line, near it (a parry)
        int counter_hand = -1;                      // the hand of the user's counter
    };

    void follow(double t_s, double dt_s, Watched& watched, const Blow& blow, const TrackedUser& user);
    void answer(Watched& watched, Channel channel, double rose_s, const TrackedUser& user);
    void finish(double t_s, Watched& watched, EventLog& log);

    ResponseSettings m_settings;
    std::array<Watched, 6> m_watched{};
    int m_newest = -1; // the slot of the strike under way or last begun
    bool m_have_previous = false;
    double m_previous_s = 0.0;
    Eigen::Vector3d m_previous_head = Eigen::Vector3d::Zero();
    UserHands m_previous_hands;
    Eigen::Vector3d m_previous_point_from_fighter = Eigen::Vector3d::Zero(); // the striking point, from the fighter's pelvis
    bool m_have_previous_point = false;
};

} // namespace kumite
