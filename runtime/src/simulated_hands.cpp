#include "kumite/runtime/simulated_hands.h"

#include "kumite/core/smoothstep.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace kumite {

void SimulatedHands::set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest) {
    m_opponent_head = head;
    m_opponent_chest = chest;
    m_has_opponent = true;
}

Eigen::Vector3d SimulatedHands::guard(int side, const Eigen::Vector3d& head) const {
    // Facing the opponent on the floor (or -Z, towards a fighter at the origin, before one is known).
    Eigen::Vector3d forward = m_has_opponent ? Eigen::Vector3d(m_opponent_head - head) : Eigen::Vector3d(0.0, 0.0, -1.0);
    forward.y() = 0.0;
    forward = forward.norm() > 1e-6 ? forward.normalized() : Eigen::Vector3d(0.0, 0.0, -1.0);
    const Eigen::Vector3d left = Eigen::Vector3d::UnitY().cross(forward); // the user's left
    return head + 0.25 * forward - 0.22 * Eigen::Vector3d::UnitY() + (side == 0 ? 0.17 : -0.17) * left;
}

void SimulatedHands::punch(double t_s, int side, bool at_head, double speed_mps) {
    if (!m_has_opponent || !(speed_mps > 0.0)) return;
    m_punch.active = true;
    m_punch.side = side;
    m_punch.start_s = t_s;
    m_punch.to = at_head ? m_opponent_head : m_opponent_chest;
    m_punch.from = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()); // the guard when it starts
    m_punch.out_s = -speed_mps;                                                          // resolved at the first frame
}

UserHands SimulatedHands::hands(double t_s, const Eigen::Vector3d& head) {
    UserHands out;
    for (int side = 0; side < 2; ++side) {
        out.present[side] = true;
        out.world[side] = guard(side, head);
    }
    if (!m_punch.active || t_s < m_punch.start_s) return out;
    Punch& punch = m_punch;
    if (punch.out_s < 0.0) { // the start's guard is fixed at the first frame that sees the punch
        punch.from = out.world[punch.side];
        punch.out_s = (punch.to - punch.from).norm() / -punch.out_s;
    }
    const double since = t_s - punch.start_s;
    const Eigen::Vector3d rest = out.world[punch.side];
    if (since <= punch.out_s) {
        out.world[punch.side] = punch.from + (punch.to - punch.from) * (since / std::max(1e-6, punch.out_s)); // steady speed
    } else if (since <= punch.out_s + k_hold_s) {
        out.world[punch.side] = punch.to;
    } else if (since <= punch.out_s + k_hold_s + k_retract_s) {
        out.world[punch.side] = punch.to + (rest - punch.to) * smoothstep((since - punch.out_s - k_hold_s) / k_retract_s);
    } else {
        punch.active = false;
    }
    return out;
}

} // namespace kumite
