#include "strike_swings.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_min_path = 1.0;          // arm lengths the fist travels (relative to the pelvis) over the swing
constexpr double k_bent_min_deg = 60.0;     // the elbow at the hit: bent, not folded shut (an elbow strike)...
constexpr double k_bent_max_deg = 135.0;    // ... and not straight (a straight punch, found by its extension)
constexpr double k_fist_ahead = 0.15;       // the fist in front of its shoulder along the hips' heading, arm lengths
constexpr double k_fist_up = 0.05;          // the fist at or over its shoulder's height (a low swing is a sweep)
constexpr double k_fist_overhead = 0.9;     // but not thrown straight up over the shoulder by most of the arm
// The forearm at the hit says which swing it was: across the face and flat, a hook (its fist swung round towards
// the other side); upright, an uppercut, which comes up from below (StrikeThresholds::uppercut_rise). Upright
// without that rise, or pointing forward, the fist was swung across at shoulder height: a middle block, a back-fist.
constexpr double k_hook_across = -0.6;      // the forearm's direction towards the arm's own side, at most (it points across)
constexpr double k_hook_flat = 0.6;         // and its upward component, at most
constexpr double k_uppercut_upright = 0.6;  // an uppercut's forearm's upward component, at least
constexpr double k_block_elbow_up = 0.4;    // upper-arm lengths an elbow over its shoulder lifts a flat forearm into a rising block

double elbow_deg(const Eigen::Vector3d& shoulder, const Eigen::Vector3d& elbow, const Eigen::Vector3d& wrist) {
    const Eigen::Vector3d upper = (shoulder - elbow).normalized(), lower = (wrist - elbow).normalized();
    return std::acos(std::clamp(upper.dot(lower), -1.0, 1.0)) * 180.0 / 3.14159265358979;
}

} // namespace

std::vector<SwingPunch> swing_punches_detect(const ArmTrack& arm, const ArmTrack& other, const std::vector<Eigen::Vector3d>& pelvis,
                                             const std::vector<Eigen::Vector3d>& hips_forward,
                                             const std::vector<double>& head_y, bool left, double dt,
                                             const StrikeThresholds& thresholds) {
    const int frames = static_cast<int>(arm.wrist.size());
    const double length = arm.upper_length + arm.lower_length;
    const double other_length = other.upper_length + other.lower_length;
    // The fist's speed relative to the pelvis (a step is not a swing), over +-0.025 s.
    std::vector<double> speed(frames, 0.0);
    const int smooth = std::max(1, static_cast<int>(std::lround(0.025 / dt)));
    auto relative = [&](int frame) -> Eigen::Vector3d { return arm.wrist[frame] - pelvis[frame]; };
    for (int frame = 0; frame < frames; ++frame) {
        const int from = std::max(0, frame - smooth), to = std::min(frames - 1, frame + smooth);
        if (to > from) speed[frame] = (relative(to) - relative(from)).norm() / ((to - from) * dt) / length;
    }
    const int half_window = std::max(1, static_cast<int>(0.15 / dt));
    const int swing_max = std::max(1, static_cast<int>(std::lround(0.6 / dt)));
    const int stop_max = std::max(1, static_cast<int>(std::lround(0.3 / dt)));
    std::vector<SwingPunch> punches;
    for (int peak = 0; peak < frames; ++peak) {
        if (speed[peak] < thresholds.swing_speed) continue;
        bool is_max = true;
        for (int f = std::max(0, peak - half_window); f <= std::min(frames - 1, peak + half_window) && is_max; ++f) {
            is_max = speed[f] < speed[peak] || (speed[f] == speed[peak] && f >= peak);
        }
        if (!is_max) continue;
        int hit = peak, start = peak;
        while (hit + 1 < frames && hit - peak < stop_max && speed[hit] >= 0.2 * speed[peak]) ++hit;
        if (speed[hit] >= 0.2 * speed[peak]) continue; // still swinging as the capture ends, or not stopping
        while (start > 0 && peak - start < swing_max && speed[start] >= 0.2 * speed[peak]) --start;
        double path = 0.0;
        for (int f = start + 1; f <= hit; ++f) path += (relative(f) - relative(f - 1)).norm() / length;
        if (path < k_min_path) continue;
        const double bend = elbow_deg(arm.shoulder[hit], arm.elbow[hit], arm.wrist[hit]);
        if (bend < k_bent_min_deg || bend > k_bent_max_deg) continue;
        const Eigen::Vector3d fist = (arm.wrist[hit] - arm.shoulder[hit]) / length;
        if (fist.dot(hips_forward[hit]) < k_fist_ahead || fist.y() < k_fist_up || fist.y() > k_fist_overhead) continue;
        const Eigen::Vector3d forearm = (arm.wrist[hit] - arm.elbow[hit]).normalized();
        const Eigen::Vector3d left_of_hips = Eigen::Vector3d::UnitY().cross(hips_forward[hit]);
        const Eigen::Vector3d outward = left ? left_of_hips : Eigen::Vector3d(-left_of_hips);
        // Flat across over the head, under an elbow raised over the shoulder, the forearm is a rising block's.
        const bool rising_block = arm.wrist[hit].y() > head_y[hit] && (arm.elbow[hit].y() - arm.shoulder[hit].y()) / arm.upper_length > k_block_elbow_up;
        const bool hook = forearm.dot(outward) <= k_hook_across && forearm.y() <= k_hook_flat && !rising_block;
        double lowest = arm.wrist[hit].y();
        for (int f = std::max(0, hit - stop_max); f <= hit; ++f) lowest = std::min(lowest, arm.wrist[f].y());
        const bool uppercut = forearm.y() >= k_uppercut_upright && (arm.wrist[hit].y() - lowest) / length >= thresholds.uppercut_rise;
        if (!hook && !uppercut) continue;
        // The other hand: up at the guard, not pulled back to the hip.
        if ((other.wrist[hit].y() - other.shoulder[hit].y()) / other_length < thresholds.swing_guard_height) continue;
        SwingPunch punch;
        punch.first_frame = start;
        punch.hit_frame = hit;
        punch.strength = std::clamp(std::min((speed[peak] - thresholds.swing_speed) / thresholds.swing_speed, (path - k_min_path) / k_min_path), 0.0, 1.0);
        if (!punches.empty() && hit - punches.back().hit_frame < half_window * 2) continue; // a second peak of one swing
        punches.push_back(punch);
    }
    return punches;
}

} // namespace kumite
