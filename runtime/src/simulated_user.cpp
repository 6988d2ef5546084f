#include "kumite/runtime/simulated_user.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

double smoothstep(double s) {
    s = std::clamp(s, 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

} // namespace

std::optional<SimulatedKind> simulated_kind_from_name(std::string_view name) {
    if (name == "still") return SimulatedKind::still;
    if (name == "wander") return SimulatedKind::wander;
    if (name == "dodge") return SimulatedKind::dodge;
    return std::nullopt;
}

SimulatedUser::SimulatedUser(SimulatedKind kind, std::uint64_t seed) : m_kind(kind), m_random{seed} {}

void SimulatedUser::on_order(double t_s) {
    if (m_kind != SimulatedKind::dodge) return;
    m_dodge_start_s = t_s + 0.25;
    ++m_dodges;
}

Eigen::Vector3d SimulatedUser::head(double t_s) {
    const Eigen::Vector3d start = start_position();
    switch (m_kind) {
    case SimulatedKind::still: return start;
    case SimulatedKind::wander: {
        constexpr double speed = 0.4;
        while (t_s >= m_leg_end_s) {
            m_from = m_to;
            m_to = Eigen::Vector3d(m_random.uniform(-1.5, 1.5), k_head_height_m, start.z() + m_random.uniform(-1.0, 1.5));
            m_leg_start_s = m_leg_end_s;
            m_leg_end_s = m_leg_start_s + std::max(0.5, (m_to - m_from).norm() / speed);
        }
        const double s = (t_s - m_leg_start_s) / (m_leg_end_s - m_leg_start_s);
        return m_from + (m_to - m_from) * s;
    }
    case SimulatedKind::dodge: {
        const double since = t_s - m_dodge_start_s;
        if (since < 0.0 || since > 1.3) return start;
        // Out over 0.15 s, hold, back over 0.15 s.
        const double amount = since < 0.15 ? smoothstep(since / 0.15) : since < 1.15 ? 1.0 : 1.0 - smoothstep((since - 1.15) / 0.15);
        const Eigen::Vector3d away = m_dodges % 2 == 1 ? Eigen::Vector3d(0.0, -0.45, 0.0) : Eigen::Vector3d(0.5, 0.0, 0.0);
        return start + amount * away;
    }
    }
    return start;
}

} // namespace kumite
