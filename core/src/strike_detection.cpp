#include "kumite/core/strike_detection.h"

#include "strike_covers.h"
#include "strike_swings.h"

#include "kumite/core/root_from_feet.h"

#include "kumite/core/contact_point.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_min_gap_s = 0.3;
constexpr double k_span_s = 1.0;
constexpr double k_kick_extension = 0.85;  // leg straightness (hip-ankle over leg length) that makes a raised foot a kick
constexpr double k_knee_rise = 0.3;        // knee above its standing height, in leg lengths, for a knee strike
constexpr double k_knee_speed = 3.5;       // leg lengths per second the knee reaches within 0.3 s before a knee strike's hit
constexpr double k_block_above_head = 0.3; // a hand this far (arm lengths) above the head is blocking, not punching
constexpr double k_elbow_rise = 0.8;       // how far an elbow strike lifts the elbow (upper-arm lengths) within 0.6 s
constexpr double k_elbow_folded_deg = 84.0; // an elbow opened wider than this, its wrist up by the head, is a rising block
// How far out a punch's fist gets from the chest (StrikeThresholds::punch_reach): a straight punch thrusts it away
// (CMU 14's jabs and crosses 0.86-1.16, the kata's 0.86-1.10); an arm opened with the fist still by the body (a
// kata's chambers and middle blocks, 0.60-0.77) is not thrown at anything.
constexpr double k_straight_arm_deg = 165.0; // an elbow opened this far is a straight arm (a punch at head height, not a block on its way up)
constexpr double k_thrust_window_s = 0.1;  // how long before the hit a punch's fist is seen travelling along its forearm
constexpr double k_punch_thrust = 0.2;     // cosine between that travel and the forearm, at least
constexpr double k_punch_forearm_down = -0.45; // sine of the forearm's slope below which it points down (27 degrees): a low sweep
// A hand raised this close to a punch of its own is the punch's wind-up or return to the guard, and this close to
// the other hand's punch the guard kept up behind it (a boxer's uppercuts and straights): not a cover.
constexpr double k_cover_own_strike_s = 0.75;
constexpr double k_cover_other_strike_s = 0.5;

using LimbTrack = std::vector<std::array<Eigen::Vector3d, k_limb_count>>; // [frame][limb] one joint of each limb

// The fastest `track`'s joint of `limb` moves over the `window` frames up to `frame`, in `length`s per second.
double fastest_over(const LimbTrack& track, int limb, int frame, int window, double dt, double length) {
    double fastest = 0.0;
    for (int f = std::max(1, frame - window); f <= frame; ++f) fastest = std::max(fastest, (track[f][limb] - track[f - 1][limb]).norm() / dt / length);
    return fastest;
}

// The angle at the middle joint, degrees: 180 straight, 0 folded.
double bend_deg(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity) {
    const Eigen::Vector3d upper = root - middle, lower = extremity - middle;
    return std::acos(std::clamp(upper.normalized().dot(lower.normalized()), -1.0, 1.0)) * 180.0 / 3.14159265358979;
}

// Whether `strikes` already holds one of `semantics` by `part` within `within` frames of `hit`: a second peak of
// the same strike.
bool already_found(const std::vector<StrikeSuggestion>& strikes, StrikeSemantics semantics, BodyPart part, int hit, int within) {
    return std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& other) {
        return other.semantics == semantics && other.segment == part && std::abs(other.hit_frame - hit) < within;
    });
}

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
    case StrikeSemantics::knee: return "knee";
    case StrikeSemantics::elbow: return "elbow";
    case StrikeSemantics::block: return "block";
    case StrikeSemantics::reach: return "reach";
    }
    return "reach";
}

std::vector<StrikeSuggestion> strikes_detect(const Clip& clip, const RestAnatomy& anatomy, std::optional<BodyPart> segment,
                                             const StrikeThresholds& thresholds) {
    if (root_is_pinned(clip)) {
        // Read as the bake reads it: the root follows the foot the body stands on (root_from_feet.h), so that
        // heights are over the floor and not over a foot that hangs under pinned hips.
        Clip moved = clip;
        root_motion_from_feet(moved, anatomy.limbs[int(Limb::leg_l)].extremity, anatomy.limbs[int(Limb::leg_r)].extremity);
        return strikes_detect(moved, anatomy, segment, thresholds);
    }
    const Skeleton& skeleton = clip.skeleton;
    const BodyMap& map = anatomy.body_map;
    const int frames = clip.frame_count();
    if (!clip.has_frame_rate()) return {}; // speeds need the rate: callers refuse clips without one first
    const double dt = clip.frame_time_s;
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    // Per frame: each limb's extension and reach, its extremity's and middle joint's positions; the head's height.
    std::vector<std::array<double, k_limb_count>> extension(frames), reach(frames), ahead(frames);
    LimbTrack extremity(frames), middle(frames), root(frames);
    std::vector<double> head_y(frames, 0.0), part_distance(frames, 0.0);
    std::vector<Eigen::Vector3d> hips_forward(frames, Eigen::Vector3d::UnitZ()); // on the floor plane
    std::vector<Eigen::Vector3d> pelvis_position(frames), head_position(frames);
    const int pelvis = map.joint(BodyPart::pelvis);
    const int chest = map.joint(BodyPart::chest);
    const int head = map.joint(BodyPart::head);
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
                // A kick goes forward, sideways or round: how far the ankle is from the hip on the floor plane, and
                // how far ahead along the hips' heading (a leg swung back is negative).
                Eigen::Vector3d away = offset, forward = pelvis_forward;
                away.y() = 0.0;
                forward.y() = 0.0;
                reach[frame][limb] = away.norm() / chain.length();
                ahead[frame][limb] = forward.norm() > 1e-9 ? offset.dot(forward.normalized()) / chain.length() : 0.0;
            }
            extremity[frame][limb] = positions[chain.extremity];
            middle[frame][limb] = positions[chain.middle];
            root[frame][limb] = positions[chain.root];
        }
        head_y[frame] = positions[head].y();
        head_position[frame] = positions[head];
        pelvis_position[frame] = positions[pelvis];
        hips_forward[frame] = Eigen::Vector3d(pelvis_forward.x(), 0.0, pelvis_forward.z()).normalized();
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

    const int speed_window = std::max(1, static_cast<int>(0.3 / dt));
    // Elbow strikes: the elbow driven up from below its shoulder to above it, fast, with the forearm folded so
    // that the fist stays by the head; hit where the rise stops (over the shoulder: after its fastest frame, the
    // first frame whose rise falls under a fifth of the fastest's). A
    // rising block (age-uke) raises the elbow too, but opens the arm above the head: an elbow opened past
    // k_elbow_folded_deg with the wrist up at the head's height is a block.
    auto detect_elbow_strikes = [&](int limb, Side side, BodyPart part) {
        const LimbChain& chain = anatomy.limbs[limb];
        std::vector<double> lift(frames);
        for (int frame = 0; frame < frames; ++frame) lift[frame] = (middle[frame][limb].y() - root[frame][limb].y()) / chain.upper_length;
        const int rise_window = std::max(1, static_cast<int>(0.6 / dt));
        const auto peaks = local_maxima(lift, half_window, min_gap, [&](int frame) {
            if (lift[frame] < 0.0) return false; // not above the shoulder
            const int low = valley(lift, frame, -1, rise_window);
            if (lift[frame] - lift[low] < k_elbow_rise) return false;
            return fastest_over(middle, limb, frame, speed_window, dt, chain.upper_length) >= 2.0;
        });
        for (int peak : peaks) {
            // Where the rise stops: after its fastest frame, the first whose rise is under a fifth of that.
            const int low = valley(lift, peak, -1, rise_window);
            int fastest = low + 1;
            for (int f = low + 1; f <= peak; ++f) {
                if (lift[f] - lift[f - 1] > lift[fastest] - lift[fastest - 1]) fastest = f;
            }
            int hit = fastest;
            while (hit < peak && lift[hit + 1] - lift[hit] >= 0.2 * (lift[fastest] - lift[fastest - 1])) ++hit;
            // How the arm ends up at the top of the rise: a block opens there.
            const double folded_deg = bend_deg(root[peak][limb], middle[peak][limb], extremity[peak][limb]);
            const bool wrist_up = extremity[peak][limb].y() > head_y[peak] - 0.04;
            const bool wrist_above = extremity[peak][limb].y() > head_y[peak] + 0.1;
            if ((folded_deg >= k_elbow_folded_deg && wrist_up) || wrist_above) continue; // a rising block
            if (folded_deg >= 110.0) continue;                          // an arm raised open: a wave, a reach
            // Driven forward, at what is in front: an elbow swung back behind its shoulder (along the hips'
            // heading) is pulled back (a kata's hikite), not striking.
            if ((middle[hit][limb] - root[hit][limb]).dot(hips_forward[hit]) < 0.0) continue;
            if (already_found(strikes, StrikeSemantics::elbow, part, hit, 2 * min_gap)) continue; // a second top of one rise
            // A hook raises the elbow fast too, but its fist swings ahead: the punch found there is the strike.
            if (already_found(strikes, StrikeSemantics::punch, limb_parts(static_cast<Limb>(limb))[2], hit, 2 * min_gap)) continue;
            add(StrikeSemantics::elbow, part, side, hit, lift, 0.5 + 0.5 * std::min(1.0, (lift[peak] - lift[valley(lift, peak, -1, rise_window)] - k_elbow_rise) / 0.5));
        }
    };
    // Blocks: the forearm's contact point (a third of the way from the wrist to the elbow) sweeps fast across the
    // body's front and stops there, the arm not thrust out at a target: hit where the sweep stops (after its
    // fastest frame, the first frame under a fifth of that speed). Rising (age-uke): it stops above the head with the
    // elbow over the shoulder and the forearm across, not upright. Downward (gedan-barai): the wrist came down at
    // least 0.15 arm length, fast (3.5 arm lengths per second at its fastest: an arm lowered to rest after a
    // technique is slower), the arm straight (0.85) and stopping low in front (the wrist 0.6 arm length under its shoulder and 0.25 ahead of it
    // along the hips' heading: an arm hanging by the side or pulled back to the hip is not out in front).
    auto detect_blocks = [&](int limb, Side side, BodyPart part) {
        const LimbChain& chain = anatomy.limbs[limb];
        const double length = chain.length();
        std::vector<double> speed(frames, 0.0);
        std::vector<Eigen::Vector3d> contact(frames);
        for (int frame = 0; frame < frames; ++frame) {
            contact[frame] = extremity[frame][limb] + k_block_contact_fraction * (middle[frame][limb] - extremity[frame][limb]);
        }
        // Speed over +-0.025 s: one-frame jumps of an inertial suit are not sweeps.
        const int smooth = std::max(1, static_cast<int>(std::lround(0.025 / dt)));
        for (int frame = 0; frame < frames; ++frame) {
            const int from = std::max(0, frame - smooth), to = std::min(frames - 1, frame + smooth);
            if (to > from) speed[frame] = (contact[to] - contact[from]).norm() / ((to - from) * dt) / length;
        }
        const auto peaks = local_maxima(speed, half_window, min_gap, [&](int frame) { return speed[frame] >= 1.5; });
        for (int peak : peaks) {
            int hit = peak, start = peak;
            while (hit + 1 < frames && speed[hit] >= 0.2 * speed[peak]) ++hit;
            while (start > 0 && peak - start < span && speed[start] >= 0.2 * speed[peak]) --start;
            const Eigen::Vector3d sweep = (contact[hit] - contact[start]) / length;
            const Eigen::Vector3d wrist = extremity[hit][limb] - root[hit][limb];
            const double out = std::hypot(wrist.x(), wrist.z()) / length;
            const double forearm_tilt = std::abs(extremity[hit][limb].y() - middle[hit][limb].y()) / chain.lower_length;
            const bool rising = sweep.y() > 0.2 && contact[hit].y() > head_y[hit] && middle[hit][limb].y() > root[hit][limb].y() &&
                                forearm_tilt < 0.85 && extension[hit][limb] < 0.9;
            const double wrist_drop = (extremity[hit][limb].y() - extremity[start][limb].y()) / length;
            // Out in front: the other hand, pulled back to the hip as the block sweeps (hikite), comes down too.
            const double ahead_of_shoulder = wrist.dot(hips_forward[hit]) / length;
            const bool downward = wrist_drop < -0.15 && wrist.y() < -0.6 * length && out > 0.3 && ahead_of_shoulder > 0.25 &&
                                  extension[hit][limb] >= 0.85 && speed[peak] >= 3.5;
            if (!rising && !downward) continue;
            if (already_found(strikes, StrikeSemantics::punch, limb_parts(static_cast<Limb>(limb))[2], hit, min_gap)) continue; // a low punch
            if (already_found(strikes, StrikeSemantics::block, part, hit, min_gap)) continue;
            // A rising elbow strike lifts the forearm over the head too: the elbow found there is the strike.
            if (already_found(strikes, StrikeSemantics::elbow, part, hit, 2 * min_gap)) continue;
            const double strength = rising ? std::min(1.0, (contact[hit].y() - head_y[hit]) / (0.2 * length)) : std::min(1.0, (-wrist_drop - 0.15) / 0.3);
            add(StrikeSemantics::block, part, side, hit, speed, 0.5 + 0.5 * strength);
            StrikeSuggestion& block = strikes.back();
            block.first_frame = std::max(0, start - half_window);
            block.last_frame = std::min(frames - 1, hit + (hit - start));
        }
    };
    // A punch drives the fist along the forearm: over the last k_thrust_window_s before the hit the fist travels
    // within ~78 degrees of where the forearm points (cosine k_punch_thrust). A knife-hand, a back-fist or a block
    // that circles over the head swings the fist across the forearm instead.
    const int thrust_window = std::max(1, static_cast<int>(std::lround(k_thrust_window_s / dt)));
    auto thrust_along_forearm = [&](int limb, int hit) {
        const int from = std::max(0, hit - thrust_window);
        const Eigen::Vector3d travel = extremity[hit][limb] - extremity[from][limb];
        Eigen::Vector3d forearm = Eigen::Vector3d::Zero();
        for (int f = from; f <= hit; ++f) forearm += (extremity[f][limb] - middle[f][limb]).normalized();
        if (travel.norm() < 1e-9 || forearm.norm() < 1e-9) return false;
        return travel.normalized().dot(forearm.normalized()) >= k_punch_thrust;
    };
    auto arm_track = [&](int limb) {
        ArmTrack track;
        track.upper_length = anatomy.limbs[limb].upper_length;
        track.lower_length = anatomy.limbs[limb].lower_length;
        for (int frame = 0; frame < frames; ++frame) {
            track.shoulder.push_back(root[frame][limb]);
            track.elbow.push_back(middle[frame][limb]);
            track.wrist.push_back(extremity[frame][limb]);
        }
        return track;
    };
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const bool arm = limb < 2;
        const Side side = limb % 2 == 0 ? Side::left : Side::right;
        const std::array<BodyPart, 3> parts = limb_parts(static_cast<Limb>(limb));
        const LimbChain& chain = anatomy.limbs[limb];
        const double length = chain.length();
        if (arm) {
            std::vector<double> signal(frames);
            for (int frame = 0; frame < frames; ++frame) signal[frame] = extension[frame][limb];
            const int settle = std::max(1, static_cast<int>(std::lround(0.1 / dt)));
            const auto peaks = local_maxima(signal, half_window, min_gap, [&](int frame) {
                // A punch lands before the arm locks: 0.78 of the arm's length from the shoulder is a boxer's
                // straight from a bladed guard (CMU 14); a karateka's reaches full extension.
                if (signal[frame] < 0.78 || reach[frame][limb] < thresholds.punch_reach) return false;
                // The capture must go on a little after a hit: a hand still extending as the file ends may not
                // have arrived.
                if (frame + settle >= frames) return false;
                // A hand above the head at full extension is a rising block (age-uke), not a punch; so is one at
                // the head's height under an elbow raised well over the shoulder with the arm still bent (the block
                // on its way up; a straight punch at the head of a taller opponent raises the elbow too).
                if (extremity[frame][limb].y() > head_y[frame] + k_block_above_head * length) return false;
                if (extremity[frame][limb].y() > head_y[frame] - 0.05 &&
                    middle[frame][limb].y() - root[frame][limb].y() > 0.35 * chain.upper_length &&
                    bend_deg(root[frame][limb], middle[frame][limb], extremity[frame][limb]) < k_straight_arm_deg) return false;
                // A punch is thrown: the arm extends from bent within the last moments. An arm held out in a guard
                // (karate's kamae) or settling into it stays extended.
                if (signal[frame] - signal[valley(signal, frame, -1, speed_window * 2)] < thresholds.punch_rise) return false;
                return fastest_over(extremity, limb, frame, speed_window, dt, length) >= 1.5;
            });
            for (int peak : peaks) {
                // The fist meets a target as it arrives: the first frame within 2 cm of the peak extension (a punch
                // held out, as a kata's, peaks late in the hold; one that plateaus, after it has stopped).
                int hit = peak;
                while (hit > 0 && signal[hit - 1] >= signal[peak] - 0.02 / length) --hit;
                if (already_found(strikes, StrikeSemantics::punch, parts[2], hit, min_gap)) continue; // a second peak of one held punch
                if (!thrust_along_forearm(limb, hit)) continue;
                // A forearm pointing steeply down at the hit sweeps low (a downward block), it is not thrust at a target.
                const Eigen::Vector3d forearm = extremity[hit][limb] - middle[hit][limb];
                if (forearm.y() < k_punch_forearm_down * forearm.norm()) continue;
                const double strength = std::min((signal[peak] - 0.78) / 0.22, (reach[peak][limb] - thresholds.punch_reach) / 0.4);
                add(StrikeSemantics::punch, parts[2], side, hit, signal, 0.5 + 0.5 * strength);
            }
            // Hooks and uppercuts land with the elbow bent: found by the fist's swing (strike_swings.h).
            const int other_limb = limb ^ 1;
            for (const SwingPunch& swing : swing_punches_detect(arm_track(limb), arm_track(other_limb), pelvis_position, hips_forward, head_y, side == Side::left, dt,
                                                                     thresholds)) {
                if (already_found(strikes, StrikeSemantics::punch, parts[2], swing.hit_frame, min_gap)) continue;
                add(StrikeSemantics::punch, parts[2], side, swing.hit_frame, signal, 0.5 + 0.5 * swing.strength);
                strikes.back().first_frame = swing.first_frame;
                strikes.back().last_frame = std::min(frames - 1, swing.hit_frame + (swing.hit_frame - swing.first_frame));
            }
            detect_elbow_strikes(limb, side, parts[1]);
            detect_blocks(limb, side, parts[1]);
            continue;
        }
        // Legs: the ankle raised above its standing height. Straightened at the top (the foot thrust out to a
        // target) it is a kick, hit where the leg is straightest (its highest such frame); folded with the knee
        // driven up it is a knee strike, hit where the knee is highest.
        std::vector<double> raised(frames), knee_rise(frames);
        const double standing_knee_y = anatomy.rest_positions[chain.middle].y();
        for (int frame = 0; frame < frames; ++frame) {
            raised[frame] = (extremity[frame][limb].y() - anatomy.floor_y - anatomy.ankle_height) / anatomy.leg_length;
            knee_rise[frame] = (middle[frame][limb].y() - standing_knee_y) / anatomy.leg_length;
        }
        const auto peaks = local_maxima(raised, half_window, min_gap, [&](int frame) { return raised[frame] >= 0.35; });
        for (int peak : peaks) {
            // The raised interval around the peak: where the ankle stays above half the peak's height.
            int first = peak, last = peak;
            while (first > 0 && raised[first - 1] >= 0.5 * raised[peak]) --first;
            while (last + 1 < frames && raised[last + 1] >= 0.5 * raised[peak]) ++last;
            double straightest = 0.0;
            for (int f = first; f <= last; ++f) straightest = std::max(straightest, extension[f][limb]);
            if (straightest >= k_kick_extension) {
                int hit = -1;
                for (int f = first; f <= last; ++f) {
                    if (extension[f][limb] >= straightest - 0.02 && (hit < 0 || raised[f] > raised[hit])) hit = f;
                }
                if (reach[hit][limb] < 0.3) continue; // straight up and down: not at anything
                if (ahead[hit][limb] < -0.3) continue; // swung back (a step, a follow-through), not thrust out
                if (already_found(strikes, StrikeSemantics::kick, parts[2], hit, 1)) continue; // two peaks of one raised interval
                const double strength = std::min((raised[hit] - 0.35) / 0.35, (reach[hit][limb] - 0.3) / 0.3);
                add(StrikeSemantics::kick, parts[2], side, hit, raised, 0.5 + 0.5 * strength);
                continue;
            }
            int hit = first;
            for (int f = first; f <= last; ++f) {
                if (knee_rise[f] > knee_rise[hit]) hit = f;
            }
            if (knee_rise[hit] < k_knee_rise) continue; // a high step, not a strike
            // A knee strike is driven up fast; a knee lifted into a stance (a kata's crane, a turn) rises slowly.
            if (fastest_over(middle, limb, hit, speed_window, dt, anatomy.leg_length) < k_knee_speed) continue;
            add(StrikeSemantics::knee, parts[1], side, hit, knee_rise, 0.5 + 0.5 * std::min(1.0, (knee_rise[hit] - k_knee_rise) / 0.3));
        }
    }
    // Covers and middle blocks (strike_covers.h), once both arms' punches are known: not around a punch of either
    // hand (k_cover_own_strike_s, k_cover_other_strike_s), nor where an elbow strike or a sweeping block was found.
    const int own_strike_gap = std::max(1, static_cast<int>(std::lround(k_cover_own_strike_s / dt)));
    const int other_strike_gap = std::max(1, static_cast<int>(std::lround(k_cover_other_strike_s / dt)));
    for (int limb = 0; limb < 2; ++limb) {
        const Side side = limb == 0 ? Side::left : Side::right;
        const std::array<BodyPart, 3> parts = limb_parts(static_cast<Limb>(limb));
        const std::array<BodyPart, 3> other_parts = limb_parts(static_cast<Limb>(limb ^ 1));
        for (const CoverBlock& cover : cover_blocks_detect(arm_track(limb), head_position, hips_forward, side == Side::left, dt, thresholds)) {
            const int hit = cover.hit_frame;
            if (already_found(strikes, StrikeSemantics::punch, parts[2], hit, own_strike_gap) ||
                already_found(strikes, StrikeSemantics::punch, other_parts[2], hit, other_strike_gap) ||
                already_found(strikes, StrikeSemantics::elbow, parts[1], hit, 2 * min_gap) ||
                already_found(strikes, StrikeSemantics::block, parts[1], hit, min_gap)) continue;
            StrikeSuggestion block;
            block.semantics = StrikeSemantics::block;
            block.segment = parts[1];
            block.side = side;
            block.hit_frame = hit;
            block.first_frame = cover.first_frame;
            block.last_frame = std::min(frames - 1, hit + (hit - cover.first_frame));
            block.confidence = std::clamp(0.5 + 0.5 * cover.strength, 0.0, 1.0);
            strikes.push_back(block);
        }
    }
    // Both arms thrust out together (a two-handed push, a dance, a wave) within thresholds.both_arms_s: neither is a
    // punch. A one-two combination lands its punches one after the other.
    const int together = static_cast<int>(std::lround(thresholds.both_arms_s / dt));
    std::vector<StrikeSuggestion> single;
    for (const StrikeSuggestion& strike : strikes) {
        const bool paired = strike.semantics == StrikeSemantics::punch && std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& other) {
                                return other.semantics == StrikeSemantics::punch && other.side != strike.side &&
                                       std::abs(other.hit_frame - strike.hit_frame) <= together;
                            });
        if (!paired) single.push_back(strike);
    }
    strikes = std::move(single);
    // Arms fly out for balance during a kick, and reach for the opponent's head to pull it onto a knee (from up
    // to 0.6 s before it): an arm peak then is not a punch.
    const int grab_lead = static_cast<int>(std::lround(0.6 / dt));
    std::vector<StrikeSuggestion> kept;
    for (const StrikeSuggestion& strike : strikes) {
        const bool arm_strike = strike.semantics == StrikeSemantics::punch || strike.semantics == StrikeSemantics::elbow ||
                                strike.semantics == StrikeSemantics::block;
        const bool during_leg_strike = arm_strike && std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& leg) {
                                           const int from = leg.semantics == StrikeSemantics::knee ? std::min(leg.first_frame, leg.hit_frame - grab_lead)
                                                                                                   : leg.first_frame;
                                           return (leg.semantics == StrikeSemantics::kick || leg.semantics == StrikeSemantics::knee) &&
                                                  strike.hit_frame >= from && strike.hit_frame <= leg.last_frame;
                                       });
        if (!during_leg_strike) kept.push_back(strike);
    }
    std::sort(kept.begin(), kept.end(), [](const StrikeSuggestion& a, const StrikeSuggestion& b) { return a.hit_frame < b.hit_frame; });
    for (StrikeSuggestion& strike : kept) {
        strike.labels = strike_labels_propose(clip, anatomy, strike_semantics_name(strike.semantics), strike.segment, strike.first_frame, strike.hit_frame);
    }
    return kept;
}

} // namespace kumite
