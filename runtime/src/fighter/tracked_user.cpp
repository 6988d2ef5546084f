#include "fighter/tracked_user.h"

#include <algorithm>
#include <cmath>

namespace kumite {

TrackedUser::Change TrackedUser::take_head(double t_s, const Eigen::Vector3d* head, double timeout_s, EventLog& log) {
    if (head) {
        // A tracker slower than the bout (a headset's runtime at 20 Hz) hands the same head to several steps: only a
        // new one is a sample of its motion (the same one again a step later would read as a head that stopped, then
        // jumped). The same head for 0.1 s or more is a head that holds still (a simulated one, a held pose).
        const bool new_sample = !m_have_head || !m_tracking || *head != m_head || t_s - m_last_sample_s >= 0.1;
        m_head = *head;
        m_last_head_s = t_s;
        if (new_sample) {
            m_head_motion.update(t_s, m_head);
            m_last_sample_s = t_s;
        }
        const bool back = !m_tracking && m_have_head;
        if (back) log.push(EventLog::at(FighterEvent::Type::tracker_back, t_s));
        m_have_head = m_tracking = true;
        return back ? Change::back : Change::none;
    }
    if (m_tracking && t_s - m_last_head_s > timeout_s) {
        m_tracking = false;
        m_head_motion.reset();
        log.push(EventLog::at(FighterEvent::Type::tracker_lost, t_s));
        return Change::lost;
    }
    return Change::none;
}

double TrackedUser::distance_from(const Eigen::Vector3d& origin) const {
    const Eigen::Vector3d to_user = m_head - origin;
    return Eigen::Vector2d(to_user.x(), to_user.z()).norm();
}

HeadingFrame TrackedUser::facing(const HeadingFrame& heading) const {
    HeadingFrame facing = heading;
    if (m_tracking) {
        const Eigen::Vector3d to_user = m_head - facing.origin;
        // At most k_max_turn_rad (90 degrees) per clip: a user who walks round (or, recorded, through) the fighter is followed
        // over a few clips. A larger turn at once, blended over blend_s, twists the trunk (hips and chest slerped
        // separately take different ways round near 180 degrees) and reads as a spin.
        constexpr double k_max_turn_rad = 90.0 * 3.14159265358979 / 180.0;
        if (Eigen::Vector2d(to_user.x(), to_user.z()).norm() > 0.05) {
            const double wanted = std::atan2(to_user.x(), to_user.z());
            const double turn = std::remainder(wanted - facing.yaw_rad, 2.0 * 3.14159265358979);
            facing.yaw_rad += std::clamp(turn, -k_max_turn_rad, k_max_turn_rad);
        }
    }
    return facing;
}

void TrackedUser::update_guard(const Eigen::Vector3d& fighter_origin) {
    if (!m_tracking || !m_guard.settings().enabled) return;
    Eigen::Vector3d facing = fighter_origin - m_head;
    facing.y() = 0.0;
    m_guard.update(m_head, m_hands, facing.norm() > 1e-6 ? Eigen::Vector3d(facing.normalized()) : Eigen::Vector3d(0.0, 0.0, -1.0));
}

} // namespace kumite
