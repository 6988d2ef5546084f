#include "strike_covers.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_peak_half_window_s = 0.15; // the wrist's highest point over this long either side is one cover
constexpr double k_min_gap_s = 0.3;           // two covers of one arm this close are one
constexpr double k_rise_window_s = 0.6;       // how far back the rise is looked for
constexpr double k_head_height = 0.0;         // the wrist at least this high over the head joint (arm lengths): at the face or above
constexpr double k_bent_arm = 0.85;           // shoulder-to-wrist over the arm's length, at most: a straighter arm is thrust out, not covering
constexpr double k_in_front = 0.1;            // the wrist this far ahead of the head along the hips' heading, at least
constexpr double k_lowered_within_s = 2.0;    // a cover is let down again within this long (half its rise, at least):
                                              // a hand raised into a new stance and kept there is not a block

} // namespace

std::vector<CoverBlock> cover_blocks_detect(const ArmTrack& arm, const std::vector<Eigen::Vector3d>& head,
                                            const std::vector<Eigen::Vector3d>& hips_forward, bool left, double dt,
                                            const StrikeThresholds& thresholds) {
    const int frames = static_cast<int>(arm.wrist.size());
    const double length = arm.upper_length + arm.lower_length;
    if (frames < 3 || length <= 0.0 || arm.lower_length <= 0.0) return {};
    // The wrist from the head in the hips' heading frame, in arm lengths: forward, outward (to the arm's own side), up.
    std::vector<Eigen::Vector3d> wrist_from_head(frames);
    for (int frame = 0; frame < frames; ++frame) {
        const Eigen::Vector3d offset = (arm.wrist[frame] - head[frame]) / length;
        const Eigen::Vector3d& forward = hips_forward[frame];
        const Eigen::Vector3d to_left = Eigen::Vector3d::UnitY().cross(forward);
        wrist_from_head[frame] = {offset.dot(forward), left ? offset.dot(to_left) : -offset.dot(to_left), offset.y()};
    }
    // Where this hand usually is (each coordinate's median over the capture): a boxer's guard, a karateka's ready
    // stance. A cover raises the hand above it; a boxer's guard alone already has the glove by the chin.
    std::array<double, 3> usual{};
    std::vector<double> values(frames);
    for (int axis = 0; axis < 3; ++axis) {
        for (int frame = 0; frame < frames; ++frame) values[frame] = wrist_from_head[frame][axis];
        std::nth_element(values.begin(), values.begin() + frames / 2, values.end());
        usual[axis] = values[frames / 2];
    }
    const int half_window = std::max(1, static_cast<int>(std::lround(k_peak_half_window_s / dt)));
    const int min_gap = std::max(1, static_cast<int>(std::lround(k_min_gap_s / dt)));
    const int rise_window = std::max(1, static_cast<int>(std::lround(k_rise_window_s / dt)));
    const int lowered_within = std::max(1, static_cast<int>(std::lround(k_lowered_within_s / dt)));
    std::vector<CoverBlock> covers;
    for (int frame = 0; frame < frames; ++frame) {
        const double height = wrist_from_head[frame].z();
        bool highest = true;
        for (int other = std::max(0, frame - half_window); other <= std::min(frames - 1, frame + half_window) && highest; ++other) {
            highest = wrist_from_head[other].z() < height || (wrist_from_head[other].z() == height && other >= frame);
        }
        if (!highest || height < k_head_height) continue;
        int low = frame;
        for (int other = frame; other >= std::max(0, frame - rise_window); --other) {
            if (wrist_from_head[other].z() < wrist_from_head[low].z()) low = other;
        }
        const double rise = height - wrist_from_head[low].z();
        const double over_usual = height - usual[2];
        if (rise < thresholds.cover_rise || over_usual < thresholds.cover_rise) continue;
        // The forearm upright (the wrist over the elbow), the arm bent, the hand before the head.
        const Eigen::Vector3d forearm = arm.wrist[frame] - arm.elbow[frame];
        if (forearm.y() < thresholds.cover_upright * forearm.norm()) continue;
        if ((arm.wrist[frame] - arm.shoulder[frame]).norm() > k_bent_arm * length) continue;
        if (wrist_from_head[frame].x() < k_in_front) continue;
        bool lowered = false;
        for (int after = frame + 1; after < std::min(frames, frame + lowered_within + 1) && !lowered; ++after) {
            lowered = height - wrist_from_head[after].z() >= 0.5 * rise;
        }
        if (!lowered) continue;
        CoverBlock cover;
        cover.first_frame = low;
        cover.hit_frame = frame;
        cover.strength = std::min(1.0, std::min(rise, over_usual) / thresholds.cover_rise - 1.0);
        if (!covers.empty() && frame - covers.back().hit_frame < min_gap) {
            if (height > wrist_from_head[covers.back().hit_frame].z()) covers.back() = cover;
            continue;
        }
        covers.push_back(cover);
    }
    return covers;
}

} // namespace kumite
