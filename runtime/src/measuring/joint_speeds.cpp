#include "kumite/runtime/joint_speeds.h"

#include "kumite/core/mir.h"
#include "kumite/core/strike_adaptation.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace kumite {
namespace {

constexpr Limb k_limbs[4] = {Limb::arm_l, Limb::arm_r, Limb::leg_l, Limb::leg_r};

// How far the limb is bent at its middle joint: the angle between its two bones' directions (0 straight).
double bend_angle_rad(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity) {
    const Eigen::Vector3d upper = middle - root, lower = extremity - middle;
    if (upper.norm() < 1e-9 || lower.norm() < 1e-9) return 0.0;
    return std::acos(std::clamp(upper.normalized().dot(lower.normalized()), -1.0, 1.0));
}

} // namespace

const char* move_kind_name(MoveKind kind) {
    switch (kind) {
    case MoveKind::guard: return "guard";
    case MoveKind::step: return "step";
    case MoveKind::punch: return "punch";
    case MoveKind::kick: return "kick";
    case MoveKind::knee: return "knee";
    case MoveKind::elbow: return "elbow";
    case MoveKind::block: return "block";
    case MoveKind::slip: return "slip";
    case MoveKind::recover: return "recover";
    case MoveKind::hold: return "hold";
    case MoveKind::hit_reaction: return "hit_reaction";
    }
    return "?";
}

MoveKind strike_move_kind(BodyPart segment) {
    const bool arm = limb_of_segment(segment) == int(Limb::arm_l) || limb_of_segment(segment) == int(Limb::arm_r);
    const bool middle = segment_strikes_with_middle(segment);
    return arm ? (middle ? MoveKind::elbow : MoveKind::punch) : (middle ? MoveKind::knee : MoveKind::kick);
}

void JointSpeeds::keep_fastest(const JointSpeeds& other) {
    wrist_mps = std::max(wrist_mps, other.wrist_mps);
    ankle_mps = std::max(ankle_mps, other.ankle_mps);
    elbow_radps = std::max(elbow_radps, other.elbow_radps);
    knee_radps = std::max(knee_radps, other.knee_radps);
    elbow_mps = std::max(elbow_mps, other.elbow_mps);
}

LimbSample LimbSample::of(const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> positions) {
    LimbSample sample;
    for (int k = 0; k < 4; ++k) {
        const LimbChain& limb = anatomy.limbs[int(k_limbs[k])];
        sample.extremity[k] = positions[limb.extremity];
        sample.flexion_rad[k] = bend_angle_rad(positions[limb.root], positions[limb.middle], positions[limb.extremity]);
        if (k < 2) sample.elbow[k] = positions[limb.middle];
    }
    return sample;
}

JointSpeeds joint_speeds(const LimbSample& before, const LimbSample& after, double dt_s) {
    JointSpeeds speeds;
    if (dt_s <= 0.0) return speeds;
    for (int k = 0; k < 2; ++k) {
        speeds.wrist_mps = std::max(speeds.wrist_mps, (after.extremity[k] - before.extremity[k]).norm() / dt_s);
        speeds.ankle_mps = std::max(speeds.ankle_mps, (after.extremity[k + 2] - before.extremity[k + 2]).norm() / dt_s);
        speeds.elbow_radps = std::max(speeds.elbow_radps, std::abs(after.flexion_rad[k] - before.flexion_rad[k]) / dt_s);
        speeds.knee_radps = std::max(speeds.knee_radps, std::abs(after.flexion_rad[k + 2] - before.flexion_rad[k + 2]) / dt_s);
        speeds.elbow_mps = std::max(speeds.elbow_mps, (after.elbow[k] - before.elbow[k]).norm() / dt_s);
    }
    return speeds;
}

JointSpeeds speed_bar(const std::array<JointSpeeds, k_move_kind_count>& library, MoveKind kind) {
    JointSpeeds strikes;
    for (const MoveKind strike : {MoveKind::punch, MoveKind::kick, MoveKind::knee, MoveKind::elbow}) strikes.keep_fastest(library[int(strike)]);
    JointSpeeds bar;
    switch (kind) {
    case MoveKind::guard:
    case MoveKind::hold: // the guard as the fighter keeps it: turning to face the user and shuffling, as steps do
        bar = library[int(MoveKind::guard)];
        bar.keep_fastest(library[int(MoveKind::step)]);
        break;
    case MoveKind::recover: bar = strikes; break;
    default: bar = library[int(kind)]; break;
    }
    if (bar.wrist_mps <= 0.0 && bar.ankle_mps <= 0.0) bar = kind == MoveKind::slip ? library[int(MoveKind::block)] : strikes;
    if (bar.wrist_mps <= 0.0 && bar.ankle_mps <= 0.0) bar = strikes;
    bar.wrist_mps = bar.wrist_mps > 0.0 ? std::min(bar.wrist_mps, k_human_extremity_mps) : k_human_extremity_mps;
    bar.ankle_mps = bar.ankle_mps > 0.0 ? std::min(bar.ankle_mps, k_human_extremity_mps) : k_human_extremity_mps;
    return bar;
}

std::shared_ptr<const LibrarySpeeds> measure_library_speeds(const MotionDatabaseView& db, const std::vector<CharacterRig*>& characters) {
    auto speeds = std::make_shared<LibrarySpeeds>();
    for (const CharacterRig* character : characters) speeds->per_character.push_back(library_joint_speeds(db, character->skeleton(), character->anatomy()));
    return speeds;
}

bool clip_move_kind(const MotionDatabaseView& db, int clip, MoveKind& kind) {
    const DbClip& c = db.clips[clip];
    const std::string_view semantics = db.string(c.semantics);
    if (semantics == "rest") kind = MoveKind::guard;
    else if (semantics.starts_with("step")) kind = MoveKind::step;
    else if (semantics == "block") kind = MoveKind::block;
    else if (semantics == "hit_reaction") kind = MoveKind::hit_reaction;
    else if (db_clip_is_strike(c) && c.segment >= 0 && c.segment < k_body_part_count) kind = strike_move_kind(static_cast<BodyPart>(c.segment));
    else return false;
    return true;
}

std::array<JointSpeeds, k_move_kind_count> library_joint_speeds(const MotionDatabaseView& db, const Skeleton& skeleton, const RestAnatomy& anatomy) {
    std::array<JointSpeeds, k_move_kind_count> fastest{};
    MirDecoder decoder(skeleton, anatomy, {});
    Pose pose;
    MirFrame frame;
    const double dt = db.meta.frame_time_s;
    for (int c = 0; c < int(db.clips.size()); ++c) {
        MoveKind kind;
        if (!clip_move_kind(db, c, kind)) continue;
        const DbClip& clip = db.clips[c];
        // The fastest and second-fastest frame of each measure.
        std::array<std::array<double, 2>, 5> top{};
        LimbSample last;
        for (int f = 0; f < int(clip.frame_count); ++f) {
            db_mir_frame_load(frame, db.mir_frames[clip.first_pose + f]);
            decoder.decode(pose, frame);
            const LimbSample sample = LimbSample::of(anatomy, decoder.model_positions());
            if (f > 0) {
                const JointSpeeds s = joint_speeds(last, sample, dt);
                const double values[5] = {s.wrist_mps, s.ankle_mps, s.elbow_radps, s.knee_radps, s.elbow_mps};
                for (int m = 0; m < 5; ++m) {
                    if (values[m] > top[m][0]) top[m] = {values[m], top[m][0]};
                    else top[m][1] = std::max(top[m][1], values[m]);
                }
            }
            last = sample;
        }
        fastest[int(kind)].keep_fastest({top[0][1], top[1][1], top[2][1], top[3][1], top[4][1]});
    }
    return fastest;
}

} // namespace kumite
