#include "kumite/core/strike_detection.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_min_gap_s = 0.3;
constexpr double k_span_s = 1.0;

struct Peak {
    int frame = 0;
    double strength = 0.0; // how far the peak clears its thresholds, 0..1
};

// Frames where `signal` has a local maximum over +-half_window frames and `accept(frame)` holds; peaks closer than
// `min_gap` frames keep the larger.
template <class Accept>
std::vector<int> local_maxima(const std::vector<double>& signal, int half_window, int min_gap, Accept accept) {
    std::vector<int> peaks;
    const int frames = static_cast<int>(signal.size());
    for (int frame = 0; frame < frames; ++frame) {
        bool is_max = true;
        for (int other = std::max(0, frame - half_window); other <= std::min(frames - 1, frame + half_window) && is_max; ++other) {
            is_max = signal[other] < signal[frame] || (signal[other] == signal[frame] && other >= frame);
        }
        if (!is_max || !accept(frame)) continue;
        if (!peaks.empty() && frame - peaks.back() < min_gap) {
            if (signal[frame] > signal[peaks.back()]) peaks.back() = frame;
            continue;
        }
        peaks.push_back(frame);
    }
    return peaks;
}

// The lowest point of `signal` within `reach` frames before (direction -1) or after (+1) `frame`.
int valley(const std::vector<double>& signal, int frame, int direction, int reach) {
    int best = frame;
    for (int other = frame; other >= 0 && other < static_cast<int>(signal.size()) && std::abs(other - frame) <= reach; other += direction) {
        if (signal[other] < signal[best]) best = other;
    }
    return best;
}

} // namespace

const char* strike_semantics_name(StrikeSemantics semantics) {
    switch (semantics) {
    case StrikeSemantics::punch: return "punch";
    case StrikeSemantics::kick: return "kick";
    case StrikeSemantics::reach: return "reach";
    }
    return "reach";
}

std::vector<StrikeSuggestion> strikes_detect(const Clip& clip, const RestAnatomy& anatomy, std::optional<BodyPart> segment) {
    const Skeleton& skeleton = clip.skeleton;
    const BodyMap& map = anatomy.body_map;
    const int frames = clip.frame_count();
    if (!clip.has_frame_rate()) return {}; // speeds need the rate: callers refuse clips without one first
    const double dt = clip.frame_time_s;
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    // Per frame: each limb's extension and forward reach, its extremity's position and height.
    std::vector<std::array<double, k_limb_count>> extension(frames), reach(frames);
    std::vector<std::array<Eigen::Vector3d, k_limb_count>> extremity(frames);
    std::vector<double> part_distance(frames, 0.0);
    const int pelvis = map.joint(BodyPart::pelvis);
    const int chest = map.joint(BodyPart::chest);
    const int part_joint = segment ? map.joint(*segment) : -1;
    const double part_rest_distance = part_joint >= 0 ? (anatomy.rest_positions[part_joint] - anatomy.rest_positions[pelvis]).norm() : 1.0;
    for (int frame = 0; frame < frames; ++frame) {
        forward_kinematics(positions, rotations, skeleton, clip.pose(frame));
        const Eigen::Vector3d pelvis_forward = (rotations[pelvis] * anatomy.rest_frames[pelvis]) * Eigen::Vector3d::UnitZ();
        for (int limb = 0; limb < k_limb_count; ++limb) {
            const LimbChain& chain = anatomy.limbs[limb];
            const Eigen::Vector3d offset = positions[chain.extremity] - positions[chain.root];
            extension[frame][limb] = offset.norm() / chain.length();
            if (limb < 2) {
                // Fighters stand bladed, so a jab need not go where the chest faces: reach is how far the hand is
                // from the chest on the floor plane.
                Eigen::Vector3d away = positions[chain.extremity] - positions[chest];
                away.y() = 0.0;
                reach[frame][limb] = away.norm() / chain.length();
                // A hand well below its shoulder is hanging or swinging, and one behind the shoulder (along the
                // hips' heading) is flung back for balance: neither is punching.
                Eigen::Vector3d heading = pelvis_forward;
                heading.y() = 0.0;
                if (offset.y() < -0.5 * chain.length() || offset.dot(heading.normalized()) < 0.0) {
                    reach[frame][limb] = 0.0;
                }
            } else {
                Eigen::Vector3d forward = pelvis_forward;
                forward.y() = 0.0;
                reach[frame][limb] = offset.dot(forward.normalized()) / chain.length();
            }
            extremity[frame][limb] = positions[chain.extremity];
        }
        if (part_joint >= 0) part_distance[frame] = (positions[part_joint] - positions[pelvis]).norm() / part_rest_distance;
    }

    const int min_gap = std::max(1, static_cast<int>(k_min_gap_s / dt));
    const int span = std::max(1, static_cast<int>(k_span_s / dt));
    const int half_window = std::max(1, static_cast<int>(0.15 / dt));
    std::vector<StrikeSuggestion> strikes;
    auto add = [&](StrikeSemantics semantics, BodyPart part, Side side, int hit, const std::vector<double>& signal, double strength) {
        StrikeSuggestion strike;
        strike.semantics = semantics;
        strike.segment = part;
        strike.side = side;
        strike.hit_frame = hit;
        strike.first_frame = valley(signal, hit, -1, span);
        strike.last_frame = valley(signal, hit, +1, span);
        strike.confidence = std::clamp(strength, 0.0, 1.0);
        strikes.push_back(strike);
    };

    if (segment) {
        if (part_joint < 0) return strikes;
        const auto peaks = local_maxima(part_distance, half_window, min_gap, [&](int frame) {
            const double before = part_distance[valley(part_distance, frame, -1, span)];
            const double after = part_distance[valley(part_distance, frame, +1, span)];
            return part_distance[frame] - std::max(before, after) >= 0.1;
        });
        const std::string_view name = body_part_name(*segment);
        const Side side = name.ends_with("_l") ? Side::left : name.ends_with("_r") ? Side::right : Side::none;
        for (int frame : peaks) add(StrikeSemantics::reach, *segment, side, frame, part_distance, part_distance[frame] - 1.0);
        return strikes;
    }

    for (int limb = 0; limb < k_limb_count; ++limb) {
        const bool arm = limb < 2;
        const Side side = limb % 2 == 0 ? Side::left : Side::right;
        const BodyPart part = limb_parts(static_cast<Limb>(limb))[2];
        const double length = anatomy.limbs[limb].length();
        std::vector<double> signal(frames);
        for (int frame = 0; frame < frames; ++frame) {
            signal[frame] = arm ? extension[frame][limb]
                                : (extremity[frame][limb].y() - anatomy.floor_y - anatomy.ankle_height) / anatomy.leg_length;
        }
        const int speed_window = std::max(1, static_cast<int>(0.3 / dt));
        const auto peaks = local_maxima(signal, half_window, min_gap, [&](int frame) {
            if (arm) {
                if (signal[frame] < 0.85 || reach[frame][limb] < 0.6) return false;
                double fastest = 0.0;
                for (int f = std::max(1, frame - speed_window); f <= frame; ++f) {
                    fastest = std::max(fastest, (extremity[f][limb] - extremity[f - 1][limb]).norm() / dt / length);
                }
                return fastest >= 1.5;
            }
            return signal[frame] >= 0.35 && reach[frame][limb] >= 0.3;
        });
        for (int frame : peaks) {
            const double strength = arm ? std::min((signal[frame] - 0.85) / 0.15, (reach[frame][limb] - 0.6) / 0.6)
                                        : std::min((signal[frame] - 0.35) / 0.35, (reach[frame][limb] - 0.3) / 0.3);
            add(arm ? StrikeSemantics::punch : StrikeSemantics::kick, part, side, frame, signal, 0.5 + 0.5 * strength);
        }
    }
    // Arms fly out for balance during a kick: an arm peak inside a kick's span is not a punch.
    std::vector<StrikeSuggestion> kept;
    for (const StrikeSuggestion& strike : strikes) {
        const bool during_kick = strike.semantics == StrikeSemantics::punch &&
                                 std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& kick) {
                                     return kick.semantics == StrikeSemantics::kick && strike.hit_frame >= kick.first_frame &&
                                            strike.hit_frame <= kick.last_frame;
                                 });
        if (!during_kick) kept.push_back(strike);
    }
    std::sort(kept.begin(), kept.end(), [](const StrikeSuggestion& a, const StrikeSuggestion& b) { return a.hit_frame < b.hit_frame; });
    for (StrikeSuggestion& strike : kept) {
        strike.labels = strike_labels_propose(clip, anatomy, strike_semantics_name(strike.semantics), strike.segment, strike.first_frame, strike.hit_frame);
    }
    return kept;
}

} // namespace kumite
