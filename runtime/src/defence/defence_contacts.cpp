// Where a hand's path meets the fighter (defence.h): the distance between two segments, and the defence's tests
// built on it (a forearm met, the head's and chest's clearances, a course followed past a block).
#include "kumite/runtime/defence.h"

#include <algorithm>

namespace kumite {

double segment_distance(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& b0, const Eigen::Vector3d& b1) {
    // The closest points of the two segments (Ericson, Real-Time Collision Detection 5.1.9), degenerate ones too.
    const Eigen::Vector3d d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0.0, t = 0.0;
    constexpr double tiny = 1e-12;
    if (a <= tiny && e <= tiny) return r.norm();
    if (a <= tiny) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= tiny) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denominator = a * e - b * b;
            s = denominator > tiny ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return ((a0 + d1 * s) - (b0 + d2 * t)).norm();
}

int Defence::forearm_met(const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body) const {
    for (int arm = 0; arm < 2; ++arm) {
        if (segment_distance(before, now, body.elbow[arm], body.wrist[arm]) <= m_settings.block_contact_m) return arm;
    }
    return -1;
}

std::array<double, 2> Defence::part_clearances(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const {
    return {segment_distance(a, b, body.head, body.head) - m_settings.head_radius_m, segment_distance(a, b, body.chest, body.chest) - m_settings.chest_radius_m};
}

double Defence::body_clearance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const {
    const std::array<double, 2> clearance = part_clearances(a, b, body);
    return std::min(clearance[0], clearance[1]);
}

int Defence::met_part(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const {
    const std::array<double, 2> clearance = part_clearances(a, b, body);
    return clearance[0] <= clearance[1] ? 0 : 1;
}

bool Defence::body_met(const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body) const {
    return body_clearance(before, now, body) <= 0.0;
}

double Defence::course_clearance(const Eigen::Vector3d& from, const Eigen::Vector3d& velocity, const DefenderBody& body) const {
    constexpr double k_course_m = 0.5; // a fist's last stretch: a course is not followed past an arm's travel
    const double speed = velocity.norm();
    if (speed <= 1e-9) return 1e9;
    return body_clearance(from, from + velocity * (k_course_m / speed), body);
}

} // namespace kumite
