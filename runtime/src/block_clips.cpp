#include "kumite/runtime/block_clips.h"

#include "kumite/core/contact_point.h"
#include "kumite/core/two_bone_ik.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kumite {
namespace {

Eigen::Quaterniond load(const float (&q)[4]) { return Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized(); }

constexpr double k_pi = 3.14159265358979323846;

Eigen::Quaterniond yaw_turn(double yaw_rad) { return Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY())); }

// Where a wrist and elbow go for an arm whose extremity is `extremity` (parent frame, arm lengths), with `swivel`
// about the shoulder->wrist line from the chest's down direction, all turned by `turn`.
BlockClips::ArmPoints place_arm(const Eigen::Quaterniond& turn, const Eigen::Quaterniond& parent, const Eigen::Quaterniond& chest,
                                const Eigen::Vector3d& extremity, double swivel, const Eigen::Vector3d& shoulder, const LimbChain& chain,
                                const Eigen::Vector3d& wrist_offset) {
    const Eigen::Vector3d target = shoulder + turn * (parent * extremity * chain.length()) + wrist_offset;
    const TwoBoneSolution solved =
        two_bone_ik(shoulder, target, chain.upper_length, chain.lower_length, swivel, turn * -(chest * Eigen::Vector3d::UnitY()));
    return {solved.extremity, solved.middle, solved.extremity + k_block_contact_fraction * (solved.middle - solved.extremity)};
}

} // namespace

BlockClips::BlockClips(const MotionDatabaseView& database) : m_db(database) {
    if (database.meta.frame_time_s > 0.0f) m_frame_time_s = database.meta.frame_time_s;
    for (std::size_t c = 0; c < database.clips.size(); ++c) {
        const DbClip& clip = database.clips[c];
        const bool arm_side = clip.side == static_cast<std::uint32_t>(Side::left) || clip.side == static_cast<std::uint32_t>(Side::right);
        if (semantics_is_block(database.string(clip.semantics)) && db_clip_is_strike(clip) && arm_side && clip.hit_frame > 0 &&
            clip.hit_frame < static_cast<std::int32_t>(clip.frame_count)) {
            m_clips.push_back(static_cast<int>(c));
        }
    }
}

BlockClips::ArmFrame BlockClips::arm_frame(int clip, double frame, int limb, int parent_part) const {
    const DbClip& record = m_db.clips[clip];
    const double clamped = std::clamp(frame, 0.0, double(record.frame_count - 1));
    const int f0 = static_cast<int>(std::floor(clamped)), f1 = std::min(f0 + 1, int(record.frame_count) - 1);
    const double t = clamped - f0;
    const DbMirFrame& a = m_db.mir_frames[record.first_pose + f0];
    const DbMirFrame& b = m_db.mir_frames[record.first_pose + f1];
    const std::array<BodyPart, 3> parts = limb_parts(static_cast<Limb>(limb));
    const std::array<int, 4> indices{parent_part, int(parts[0]), int(parts[1]), int(parts[2])};
    ArmFrame out;
    for (int k = 0; k < 4; ++k) out.parts[k] = load(a.part_frames[indices[k]]).slerp(t, load(b.part_frames[indices[k]]));
    out.chest = load(a.part_frames[int(BodyPart::chest)]).slerp(t, load(b.part_frames[int(BodyPart::chest)]));
    const Eigen::Vector3d ea(a.extremity[limb][0], a.extremity[limb][1], a.extremity[limb][2]);
    const Eigen::Vector3d eb(b.extremity[limb][0], b.extremity[limb][1], b.extremity[limb][2]);
    out.extremity = (1.0 - t) * ea + t * eb;
    out.swivel = a.swivel[limb] + t * std::remainder(double(b.swivel[limb]) - a.swivel[limb], 2.0 * k_pi);
    const double yaw_a = m_db.poses[record.first_pose + f0].heading[2], yaw_b = m_db.poses[record.first_pose + f1].heading[2];
    out.yaw_rad = yaw_a + t * std::remainder(yaw_b - yaw_a, 2.0 * k_pi);
    return out;
}

BlockClips::ArmPoints BlockClips::arm_points(const RestAnatomy& anatomy, int limb, int clip, double frame, const Eigen::Vector3d& shoulder,
                                             double heading_yaw_rad, const Eigen::Vector3d& wrist_offset) const {
    const LimbChain& chain = anatomy.limbs[limb];
    const ArmFrame arm = arm_frame(clip, frame, limb, chain.parent_part);
    return place_arm(yaw_turn(heading_yaw_rad - arm.yaw_rad), arm.parts[0], arm.chest, arm.extremity, arm.swivel, shoulder, chain, wrist_offset);
}

bool BlockClips::choose(const BlockClipQuery& query, const RestAnatomy& anatomy, BlockClipChoice& choice) const {
    if (m_clips.empty()) return false;
    const LimbChain& chain = anatomy.limbs[query.limb];
    const double length = chain.length();
    const Side side = query.limb == int(Limb::arm_l) ? Side::left : Side::right;
    // The wanted kind when the database holds it for this side, else any.
    bool kind_held = false;
    for (const int c : m_clips) kind_held |= m_db.clips[c].side == std::uint32_t(side) && m_db.clips[c].strike_kind() == query.kind;
    const int max_lead = static_cast<int>(std::floor(query.time_s / m_frame_time_s));
    const int min_lead = std::max(1, static_cast<int>(std::ceil(0.4 * query.time_s / m_frame_time_s)));
    if (max_lead < 1) return false;
    BlockClipChoice best;
    best.score = std::numeric_limits<double>::infinity();
    for (const int c : m_clips) {
        const DbClip& clip = m_db.clips[c];
        if (clip.side != std::uint32_t(side) || (kind_held && clip.strike_kind() != query.kind)) continue;
        const ArmPoints at_hit = arm_points(anatomy, query.limb, c, clip.hit_frame, query.shoulder, query.heading_yaw_rad, Eigen::Vector3d::Zero());
        const double d_target = (at_hit.contact - query.contact_target).norm() / length;
        if (d_target >= best.score) continue;
        for (int lead = min_lead; lead <= std::min(max_lead, clip.hit_frame); ++lead) {
            const int start = clip.hit_frame - lead;
            const ArmPoints at_start = arm_points(anatomy, query.limb, c, start, query.shoulder, query.heading_yaw_rad, Eigen::Vector3d::Zero());
            const double score = (at_start.wrist - query.wrist).norm() / length + d_target;
            if (score >= best.score) continue;
            best.clip = c;
            best.start_frame = start;
            best.hit_frame = clip.hit_frame;
            best.rate = lead * m_frame_time_s / query.time_s;
            best.score = score;
            best.contact_error_m = d_target * length;
        }
    }
    if (best.clip < 0) return false;
    // The captured clip's own fastest arm move (wrist and elbow relative to the shoulder, its own trunk's frames),
    // on this arm: what a block's motion is measured against.
    const DbClip& record = m_db.clips[best.clip];
    ArmPoints before{};
    for (int f = 0; f < int(record.frame_count); ++f) {
        const ArmFrame arm = arm_frame(best.clip, f, query.limb, chain.parent_part);
        const ArmPoints now = place_arm(Eigen::Quaterniond::Identity(), arm.parts[0], arm.chest, arm.extremity, arm.swivel, Eigen::Vector3d::Zero(),
                                        chain, Eigen::Vector3d::Zero());
        if (f > 0) {
            const double step = std::max((now.wrist - before.wrist).norm(), (now.elbow - before.elbow).norm());
            best.clip_arm_speed_mps = std::max(best.clip_arm_speed_mps, step / m_frame_time_s);
        }
        before = now;
    }
    choice = best;
    return true;
}

void BlockClips::apply(MirFrame& out, const RestAnatomy& anatomy, int limb, int clip, double frame, double weight, const Eigen::Vector3d& shoulder,
                       double heading_yaw_rad) const {
    const LimbChain& chain = anatomy.limbs[limb];
    const ArmFrame arm = arm_frame(clip, frame, limb, chain.parent_part);
    const Eigen::Quaterniond turn = yaw_turn(heading_yaw_rad - arm.yaw_rad);
    // The clip's arm turned onto the fighter's heading, in the shown frame's terms: the extremity in its parent part,
    // the swivel from its chest's down direction (measured on the placed elbow), the parts' world frames.
    const ArmPoints placed = place_arm(turn, arm.parts[0], arm.chest, arm.extremity, arm.swivel, shoulder, chain, Eigen::Vector3d::Zero());
    const Eigen::Vector3d extremity = out.part_frames[chain.parent_part].conjugate() * (placed.wrist - shoulder) / chain.length();
    const double swivel = limb_swivel(shoulder, placed.elbow, placed.wrist, limb_swivel_reference(out, limb));
    const std::array<BodyPart, 3> parts = limb_parts(static_cast<Limb>(limb));
    for (int k = 0; k < 3; ++k) {
        Eigen::Quaterniond& shown = out.part_frames[int(parts[k])];
        shown = shown.slerp(weight, Eigen::Quaterniond(turn * arm.parts[k + 1])).normalized();
    }
    out.extremity[limb] = (1.0 - weight) * out.extremity[limb] + weight * extremity;
    out.swivel[limb] += weight * std::remainder(swivel - out.swivel[limb], 2.0 * k_pi);
}

} // namespace kumite
