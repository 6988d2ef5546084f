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

// How much more the contact's distance to the course counts in a choice than the wrist's start (block_clips.h).
constexpr double k_contact_weight = 3.0;

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
    LimbChain unit; // an arm of unit length, upper and lower alike
    unit.upper_length = unit.lower_length = 0.5;
    for (std::size_t c = 0; c < database.clips.size(); ++c) {
        const DbClip& record = database.clips[c];
        const bool left = record.side == static_cast<std::uint32_t>(Side::left), right = record.side == static_cast<std::uint32_t>(Side::right);
        if (!semantics_is_block(database.string(record.semantics)) || !db_clip_is_strike(record) || !(left || right) || record.hit_frame <= 0 ||
            record.hit_frame >= static_cast<std::int32_t>(record.frame_count)) {
            continue;
        }
        const int limb = left ? int(Limb::arm_l) : int(Limb::arm_r);
        const std::array<int, 2> parents{int(left ? BodyPart::clavicle_l : BodyPart::clavicle_r), int(BodyPart::chest)};
        Clip clip;
        clip.index = static_cast<int>(c);
        clip.first_placed = static_cast<int>(m_placed.size());
        for (int f = 0; f < int(record.frame_count); ++f) {
            for (const int parent : parents) {
                const ArmFrame arm = arm_frame(clip.index, f, limb, parent);
                const ArmPoints at = place_arm(yaw_turn(-arm.yaw_rad), arm.parts[0], arm.chest, arm.extremity, arm.swivel, Eigen::Vector3d::Zero(), unit,
                                               Eigen::Vector3d::Zero());
                m_placed.push_back({at.wrist.cast<float>(), at.contact.cast<float>()});
                // The clip's own fastest arm move (wrist and elbow relative to the shoulder): what a block's motion
                // is measured against. The elbow from the contact: contact = wrist + fraction * (elbow - wrist).
                if (f > 0) {
                    const int k = parent == parents[0] ? 0 : 1;
                    const Placed& before = placed(clip, f - 1, k);
                    const Eigen::Vector3f elbow_before = before.wrist + (before.contact - before.wrist) / float(k_block_contact_fraction);
                    const double step = std::max((at.wrist.cast<float>() - before.wrist).norm(), (at.elbow.cast<float>() - elbow_before).norm());
                    clip.arm_speed_per_m[k] = std::max(clip.arm_speed_per_m[k], step / m_frame_time_s);
                }
            }
        }
        // The last sweep: from the frame (within a second before the hit) where the contact is farthest from where
        // it ends, to the hit. A meeting is from a third of the way in: the forearm has to be on its way.
        const int hit = record.hit_frame;
        int sweep_from = hit;
        double farthest = -1.0;
        for (int f = std::max(0, hit - static_cast<int>(std::lround(1.0 / m_frame_time_s))); f <= hit; ++f) {
            const double d = (placed(clip, f, 0).contact - placed(clip, hit, 0).contact).norm();
            if (d > farthest) farthest = d, sweep_from = f;
        }
        clip.meet_from = sweep_from + (hit - sweep_from + 2) / 3;
        m_clips.push_back(clip);
    }
}

BlockClips::ArmFrame BlockClips::arm_frame(int clip, double frame, int limb, int parent_part) const {
    const DbClip& record = m_db.clips[clip];
    // A frame from an unverified database's values may be NaN (motion_database.h): the first frame then, never a
    // cast of NaN to an index.
    const double clamped = std::isfinite(frame) ? std::clamp(frame, 0.0, double(record.frame_count - 1)) : 0.0;
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
    const bool left = query.limb == int(Limb::arm_l);
    const Side side = left ? Side::left : Side::right;
    const int parent = chain.parent_part == int(left ? BodyPart::clavicle_l : BodyPart::clavicle_r) ? 0 : 1;
    // The wanted kind when the database holds it for this side, else any.
    bool kind_held = false;
    for (const Clip& clip : m_clips) kind_held |= m_db.clips[clip.index].side == std::uint32_t(side) && m_db.clips[clip.index].strike_kind() == query.kind;
    // The course points and the wrist now on the unit arm, in the fighter's heading frame, and the leads each leaves.
    const Eigen::Quaterniond to_heading = yaw_turn(-query.heading_yaw_rad);
    const int course_count = std::clamp(query.course_count, 0, int(query.course.size()));
    std::array<Eigen::Vector3f, 4> targets;
    std::array<int, 4> max_leads{}, min_leads{};
    bool any_time = false;
    for (int k = 0; k < course_count; ++k) {
        targets[k] = (to_heading * (query.course[k].point - query.shoulder) / length).cast<float>();
        max_leads[k] = static_cast<int>(std::floor(query.course[k].time_s / m_frame_time_s));
        min_leads[k] = std::max(1, static_cast<int>(std::ceil(0.4 * query.course[k].time_s / m_frame_time_s)));
        any_time |= max_leads[k] >= 1;
    }
    if (!any_time) return false;
    const Eigen::Vector3f wrist = (to_heading * (query.wrist - query.shoulder) / length).cast<float>();
    BlockClipChoice best;
    best.score = std::numeric_limits<double>::infinity();
    const Clip* best_clip = nullptr;
    for (const Clip& clip : m_clips) {
        const DbClip& record = m_db.clips[clip.index];
        if (record.side != std::uint32_t(side) || (kind_held && record.strike_kind() != query.kind)) continue;
        for (int k = 0; k < course_count; ++k) {
            const int min_lead = min_leads[k], max_lead = max_leads[k];
            if (max_lead < 1) continue;
            for (int meet = std::max(clip.meet_from, min_lead); meet <= record.hit_frame; ++meet) {
                const double contact_error = (placed(clip, meet, parent).contact - targets[k]).norm();
                if (contact_error > query.max_contact_error) continue;
                const double d_target = k_contact_weight * contact_error;
                if (d_target >= best.score) continue;
                for (int lead = min_lead; lead <= std::min(max_lead, meet); ++lead) {
                    const int start = meet - lead;
                    const double score = (placed(clip, start, parent).wrist - wrist).norm() + d_target;
                    if (score >= best.score) continue;
                    best.clip = clip.index;
                    best.start_frame = start;
                    best.meet_frame = meet;
                    best.rate = lead * m_frame_time_s / query.course[k].time_s;
                    best.score = score;
                    best.course_point = k;
                    best.contact_error_m = contact_error * length;
                    best_clip = &clip;
                }
            }
        }
    }
    if (best_clip == nullptr) return false;
    best.clip_arm_from_shoulder_mps = best_clip->arm_speed_per_m[parent] * length;
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
    const ArmPoints at = place_arm(turn, arm.parts[0], arm.chest, arm.extremity, arm.swivel, shoulder, chain, Eigen::Vector3d::Zero());
    const Eigen::Vector3d extremity = out.part_frames[chain.parent_part].conjugate() * (at.wrist - shoulder) / chain.length();
    const double swivel = limb_swivel(shoulder, at.elbow, at.wrist, limb_swivel_reference(out, limb));
    const std::array<BodyPart, 3> parts = limb_parts(static_cast<Limb>(limb));
    for (int k = 0; k < 3; ++k) {
        Eigen::Quaterniond& shown = out.part_frames[int(parts[k])];
        shown = shown.slerp(weight, Eigen::Quaterniond(turn * arm.parts[k + 1])).normalized();
    }
    out.extremity[limb] = (1.0 - weight) * out.extremity[limb] + weight * extremity;
    out.swivel[limb] += weight * std::remainder(swivel - out.swivel[limb], 2.0 * k_pi);
}

} // namespace kumite
