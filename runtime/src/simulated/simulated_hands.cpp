#include "kumite/runtime/simulated_hands.h"

#include "kumite/core/smoothstep.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace kumite {

void SimulatedHands::set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding) {
    m_opponent_head = head;
    m_opponent_chest = chest;
    if (guarding || !m_has_opponent) m_faced_head = head;
    m_has_opponent = true;
}

Eigen::Vector3d SimulatedHands::guard(int side, const Eigen::Vector3d& head) const {
    // Facing the opponent on the floor (or -Z, towards a fighter at the origin, before one is known).
    Eigen::Vector3d forward = m_has_opponent ? Eigen::Vector3d(m_faced_head - head) : Eigen::Vector3d(0.0, 0.0, -1.0);
    forward.y() = 0.0;
    forward = forward.norm() > 1e-6 ? forward.normalized() : Eigen::Vector3d(0.0, 0.0, -1.0);
    const Eigen::Vector3d left = Eigen::Vector3d::UnitY().cross(forward); // the user's left
    return head + 0.25 * forward - 0.22 * Eigen::Vector3d::UnitY() + (side == 0 ? 0.17 : -0.17) * left;
}

void SimulatedHands::punch(double t_s, int side, bool at_head, double speed_mps, double distance_m) {
    if (!m_has_opponent || !(speed_mps > 0.0)) return;
    m_punch.active = true;
    m_punch.side = side;
    m_punch.start_s = t_s;
    m_punch.to = at_head ? m_opponent_head : m_opponent_chest;
    m_punch.speed_mps = speed_mps;
    m_punch.distance_m = distance_m;
    m_punch.drawn = false;
}

UserHands SimulatedHands::hands(double t_s, const Eigen::Vector3d& head) {
    UserHands out;
    for (int side = 0; side < 2; ++side) {
        out.present[side] = true;
        out.world[side] = guard(side, head);
    }
    if (!m_punch.active || t_s < m_punch.start_s) return out;
    Punch& punch = m_punch;
    const Eigen::Vector3d rest = out.world[punch.side];
    if (!punch.drawn) { // the start: `distance` from the target, on the line through the guard
        punch.drawn = true;
        punch.guard = rest;
        const Eigen::Vector3d back = rest - punch.to;
        punch.from = punch.to + (back.norm() > 1e-6 ? Eigen::Vector3d(back.normalized()) : Eigen::Vector3d::UnitZ()) * punch.distance_m;
        punch.out_s = punch.distance_m / punch.speed_mps;
    }
    const double since = t_s - punch.start_s;
    const double thrust = since - k_draw_s;
    if (thrust < 0.0) {
        out.world[punch.side] = punch.guard + (punch.from - punch.guard) * smoothstep(since / k_draw_s);
    } else if (thrust <= punch.out_s) {
        out.world[punch.side] = punch.from + (punch.to - punch.from) * (thrust / std::max(1e-6, punch.out_s)); // steady speed
    } else if (thrust <= punch.out_s + k_hold_s) {
        out.world[punch.side] = punch.to;
    } else if (thrust <= punch.out_s + k_hold_s + k_retract_s) {
        out.world[punch.side] = punch.to + (rest - punch.to) * smoothstep((thrust - punch.out_s - k_hold_s) / k_retract_s);
    } else {
        punch.active = false;
    }
    return out;
}

} // namespace kumite
