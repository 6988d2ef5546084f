#pragma once
// The user's guard as the fighter's strikes meet it (world metres): a glove, a sphere around each tracked hand point
// (the fist's centre), a forearm, a capsule from the wrist back to the elbow, the head, a sphere around the tracked
// head, and the trunk, a capsule under it. Without a tracked elbow the elbow is estimated from the hand, the head
// and the way the user faces (estimate_elbow). first_contact() tells which of them a moving sphere (the fighter's
// fist, foot, knee or elbow) meets first along its path this frame. No allocation.

#include "kumite/runtime/simulated_hands.h"

#include <Eigen/Core>

#include <array>

namespace kumite {

// A fist's centre (the hand point of a tracked or recorded user, and the fighter's knuckles) past the wrist, along
// the forearm: half a closed hand.
constexpr double k_fist_centre_past_wrist_m = 0.08;

struct UserGuardSettings {
    bool enabled = true;               // the user's gloves and forearms stop the fighter's strikes that meet them first
                                       // (off: the head alone decides, at the contact)
    double glove_radius_m = 0.10;      // a boxing glove around the tracked hand point
    double forearm_radius_m = 0.05;
    double head_radius_m = 0.11;
    double trunk_radius_m = 0.15;
    double striking_radius_m = 0.05;   // the fighter's fist, foot, knee or elbow
    double knuckles_past_wrist_m = k_fist_centre_past_wrist_m; // the fist's centre, along the forearm past the wrist
    bool aim_at_openings = false;      // an order that leaves the height open aims at the highest part (head, chin, chest,
                                       // solar plexus) whose strike the guard as it is would not meet first (off: the
                                       // fighter lands more, and is hit more: docs/design.md, "The user's guard")
};

enum class GuardPart { none, head, trunk, glove_l, glove_r, forearm_l, forearm_r };
const char* guard_part_name(GuardPart part);
inline bool guard_part_blocks(GuardPart part) { return part >= GuardPart::glove_l; } // a glove or forearm: the user's block

struct GuardContact {
    GuardPart part = GuardPart::none;
    double share = 1.0; // how far along the path (0: where it began, 1: where it ends) the sphere first touches it
    Eigen::Vector3d sphere_at_touch = Eigen::Vector3d::Zero(); // the moving sphere's centre there
};

// The point of the segment a-b nearest `point`.
Eigen::Vector3d nearest_on_segment(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// The user's right on the floor (unit): along the line from the left hand to the right one when both are tracked
// and it runs within 60 degrees of the facing's right (the shoulders turn with the hands: a boxer's stance), else the
// facing's right (`facing`: unit, on the floor).
Eigen::Vector3d user_right(const Eigen::Vector3d& facing, const UserHands& hands);
// The elbow of an arm (side 0 left, 1 right) whose hand point (the fist's centre) is `hand`, for a user whose head
// is at `head` and whose right is `right` (user_right): the shoulder below and beside the head by a person's
// proportions, the arm's two bones solved between it and the hand, the elbow hanging down and a little out.
Eigen::Vector3d estimate_elbow(const Eigen::Vector3d& head, const Eigen::Vector3d& hand, const Eigen::Vector3d& right, int side);

class UserGuard {
public:
    explicit UserGuard(UserGuardSettings settings = {}) : m_settings(settings) {}

    // This frame's guard: the head, the hands tracked (absent hands guard nothing), the way the user faces (unit,
    // on the floor: towards the fighter). `elbows`: tracked elbows, else null (estimated).
    void update(const Eigen::Vector3d& head, const UserHands& hands, const Eigen::Vector3d& facing,
                const std::array<Eigen::Vector3d, 2>* elbows = nullptr);

    // The first part a sphere of `radius` moving from `from` to `to` meets (GuardPart::none: nothing). A part it
    // is already in at `from` is met at share 0.
    GuardContact first_contact(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius) const;
    // Where the part is now: a glove's or the head's centre, a forearm's middle, the trunk's top.
    Eigen::Vector3d part_centre(GuardPart part) const;
    // The part's core nearest `point` (a glove's or the head's centre, the nearest point of a forearm's or the
    // trunk's axis), and its radius about that core.
    Eigen::Vector3d nearest_core(GuardPart part, const Eigen::Vector3d& point) const;
    double radius(GuardPart part) const;

    const UserGuardSettings& settings() const { return m_settings; }
    bool hand(int side) const { return m_hand[side]; }
    const Eigen::Vector3d& glove(int side) const { return m_glove[side]; }
    const Eigen::Vector3d& wrist(int side) const { return m_wrist[side]; }
    const Eigen::Vector3d& elbow(int side) const { return m_elbow[side]; }

private:
    UserGuardSettings m_settings;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero(), m_chest = Eigen::Vector3d::Zero(), m_pelvis = Eigen::Vector3d::Zero();
    std::array<bool, 2> m_hand{};
    std::array<Eigen::Vector3d, 2> m_glove{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> m_wrist{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> m_elbow{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
};

} // namespace kumite
