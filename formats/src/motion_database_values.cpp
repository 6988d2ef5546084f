// What verifying a motion database checks beyond its structure: every per-pose value. Each pose names the clip
// and frame the clip table gives it, every float of POSE, MIRF and FEAT is finite, MIR chains fit their arrays,
// and the members name every pose exactly once. O(poses): run by `kumite db-info --verify` and the runtime
// commands' --verify, not at open. The runtime never follows these values as indices without a bound
// (core/retrieval.cpp derives a pose's clip and frame from the clip table and skips a member outside the poses).

#include "motion_database_checker.h"

#include <cstddef>
#include <vector>

namespace kumite::database_checks {
namespace {

Result<void> check_poses(const MotionDatabaseView& db, const Checker& check) {
    for (std::size_t c = 0; c < db.clips.size(); ++c) {
        const DbClip& clip = db.clips[c];
        for (std::uint32_t f = 0; f < clip.frame_count; ++f) {
            const std::size_t p = std::size_t(clip.first_pose) + f;
            const DbPose& pose = db.poses[p];
            if (pose.clip != c || pose.frame != f) return check.fail_at<DbPose>(k_section_poses, p, "clip and frame do not match the clip table");
            if (!all_finite(pose.heading) || !all_finite(pose.hit_point) || !all_finite(pose.start_box_min) || !all_finite(pose.start_box_max)) {
                return check.fail_at<DbPose>(k_section_poses, p, "a value is not finite");
            }
        }
    }
    return {};
}

Result<void> check_mir_frames(const MotionDatabaseView& db, const Checker& check) {
    // A record's floats in three runs: the hip centre; part frames, chain frames and fractions; extremities and
    // swivels (the part mask and the chain counts lie between them).
    static_assert(offsetof(DbMirFrame, neck_fractions) + sizeof(DbMirFrame::neck_fractions) == offsetof(DbMirFrame, spine_count));
    constexpr std::size_t rotations_begin = offsetof(DbMirFrame, part_frames) / sizeof(float);
    constexpr std::size_t rotations_end = offsetof(DbMirFrame, spine_count) / sizeof(float);
    for (std::size_t p = 0; p < db.mir_frames.size(); ++p) {
        const DbMirFrame& frame = db.mir_frames[p];
        if (frame.spine_count > k_max_chain_joints || frame.neck_count > k_max_chain_joints) {
            return check.fail_at<DbMirFrame>(k_section_mir_frames, p, "a trunk chain is longer than " + std::to_string(k_max_chain_joints));
        }
        const std::span<const float> rotations(reinterpret_cast<const float*>(&frame) + rotations_begin, rotations_end - rotations_begin);
        if (!all_finite(frame.hip_centre) || !all_finite(rotations) ||
            !all_finite(std::span<const float>(&frame.extremity[0][0], sizeof(frame.extremity) / sizeof(float))) || !all_finite(frame.swivel)) {
            return check.fail_at<DbMirFrame>(k_section_mir_frames, p, "a value is not finite");
        }
    }
    return {};
}

Result<void> check_features(const MotionDatabaseView& db, const Checker& check) {
    constexpr std::size_t block = 4096; // finite blocks at vector speed; a block with a bad value is searched
    for (std::size_t begin = 0; begin < db.features.size(); begin += block) {
        const std::span<const float> values = db.features.subspan(begin, std::min(block, db.features.size() - begin));
        if (all_finite(values)) continue;
        std::size_t i = 0;
        while (std::isfinite(values[i])) ++i;
        return check.fail_at<float>(k_section_features, begin + i, "not a finite number");
    }
    return {};
}

Result<void> check_members(const MotionDatabaseView& db, const Checker& check) {
    std::vector<bool> seen(db.poses.size(), false);
    for (std::size_t m = 0; m < db.members.size(); ++m) {
        const std::uint32_t pose = db.members[m];
        if (pose >= db.poses.size()) return check.fail_at<std::uint32_t>(k_section_members, m, "pose " + out_of_range(pose, db.poses.size(), "poses"));
        if (seen[pose]) return check.fail_at<std::uint32_t>(k_section_members, m, "pose " + std::to_string(pose) + " is a member twice");
        seen[pose] = true;
    }
    return {}; // as many members as poses (open), none twice: every pose once
}

} // namespace

Result<void> check_values(const MotionDatabaseView& db, const Checker& check) {
    if (Result<void> checked = check_poses(db, check); !checked) return checked;
    if (Result<void> checked = check_mir_frames(db, check); !checked) return checked;
    if (Result<void> checked = check_features(db, check); !checked) return checked;
    return check_members(db, check);
}

} // namespace kumite::database_checks
