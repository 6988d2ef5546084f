#include "kumite/runtime/head_motion_filter.h"

#include <algorithm>

namespace kumite {

void HeadMotionFilter::update(double t_s, const Eigen::Vector3d& head) {
    const double dt = t_s - m_last_s;
    if (m_samples == 0 || dt > m_settings.gap_reset_s || dt < 0.0) {
        m_position = head;
        m_velocity.setZero();
        m_residual_mps = 0.0;
        m_last_s = t_s;
        m_samples = 1;
        return;
    }
    if (dt <= 1e-6) { // a repeated sample: take the position, keep the velocity
        m_position += m_settings.alpha * (head - m_position);
        return;
    }
    if (m_samples == 1) { // the first pair gives the velocity outright
        m_velocity = (head - m_position) / dt;
        m_position = head;
    } else {
        const Eigen::Vector3d predicted = m_position + m_velocity * dt;
        const Eigen::Vector3d residual = head - predicted;
        // Horizontal only, like the prediction; averaged over about six samples.
        const double residual_mps = Eigen::Vector2d(residual.x(), residual.z()).norm() / dt;
        m_residual_mps += (residual_mps - m_residual_mps) * std::min(1.0, dt / 0.1);
        m_position = predicted + m_settings.alpha * residual;
        m_velocity += (m_settings.beta / dt) * residual;
    }
    m_last_s = t_s;
    ++m_samples;
}

Eigen::Vector3d HeadMotionFilter::velocity() const {
    if (!ready()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d horizontal(m_velocity.x(), 0.0, m_velocity.z());
    const double speed = horizontal.norm();
    if (speed > m_settings.max_speed_mps) horizontal *= m_settings.max_speed_mps / speed;
    return horizontal;
}

Eigen::Vector3d HeadMotionFilter::predict(double after_s) const {
    const double horizon = std::clamp(after_s, 0.0, m_settings.max_horizon_s);
    Eigen::Vector3d point = m_position + velocity() * horizon;
    point.x() = std::clamp(point.x(), m_settings.room_min.x(), m_settings.room_max.x());
    point.z() = std::clamp(point.z(), m_settings.room_min.y(), m_settings.room_max.y());
    return point;
}

} // namespace kumite
