#pragma once
// The user's hands as the room tracks them, and a simulated user's hands that punch: a straight punch at the
// fighter's head or chest (latched when the punch starts) from `distance` away: the hand draws back from its guard
// to that distance over 0.25 s (slowly, on the line to the target), thrusts at a steady speed, holds, and returns
// to the guard. The guard: each hand 0.25 m in front of the head (towards the fighter), 0.22 m below it, 0.17 m to
// its side, facing the fighter's head as it was when last in its guard (a person does not swivel the guard after the
// fighter's head as it lunges into a strike).

#include <Eigen/Core>

#include <array>

namespace kumite {

// [left, right]: each present this frame or not, world metres.
struct UserHands {
    std::array<bool, 2> present{};
    std::array<Eigen::Vector3d, 2> world{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
};

class SimulatedHands {
public:
    // Where the fighter's head and chest are, and whether it is in its guard (the bout tells it every frame).
    void set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding = true);
    // A straight punch of hand `side` (0 left, 1 right) from its guard at the opponent's head (else chest), as they
    // are now, at `speed_mps` along the way; a punch under way is replaced.
    void punch(double t_s, int side, bool at_head, double speed_mps, double distance_m = 0.8);
    // The hands at t (non-decreasing) for a user whose head is at `head`.
    UserHands hands(double t_s, const Eigen::Vector3d& head);
    bool has_opponent() const { return m_has_opponent; }

    static constexpr double k_draw_s = 0.25;    // back to the punch's start
    static constexpr double k_hold_s = 0.05;    // at full extension
    static constexpr double k_retract_s = 0.3;  // back to the guard

private:
    Eigen::Vector3d guard(int side, const Eigen::Vector3d& head) const;

    bool m_has_opponent = false;
    Eigen::Vector3d m_opponent_head = Eigen::Vector3d::Zero(), m_opponent_chest = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_faced_head = Eigen::Vector3d::Zero(); // the guard faces it: the fighter's head when last guarding
    struct Punch {
        bool active = false;
        int side = 0;
        double start_s = 0.0, out_s = 0.0; // when it starts (the draw back), how long the thrust takes
        double speed_mps = 0.0, distance_m = 0.8;
        bool drawn = false;                 // the guard it draws back from is fixed at the first frame
        Eigen::Vector3d guard = Eigen::Vector3d::Zero(), from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
    } m_punch;
};

} // namespace kumite
