// What opening a motion database checks: everything the runtime follows without reading a per-pose record. META,
// the actors, every clip header (strings, actor, pose range, labels, box), the section sizes against the pose and
// cluster counts, every cluster's member range and radius, the centroids. Its time grows with the clips and
// clusters, not with the poses: the POSE, MIRF, FEAT and MEMB sections are not read (motion_database_values.cpp).

#include "motion_database_checker.h"

namespace kumite::database_checks {
namespace {

bool string_in_table(const MotionDatabaseView& db, DbString s) { return std::uint64_t(s.offset) + s.length <= db.strings.size(); }

Result<void> check_meta_and_actors(const MotionDatabaseView& db, const Checker& check) {
    const DbMeta& meta = db.meta;
    if (!(meta.frame_time_s > 0.0f && meta.frame_time_s <= 1.0f) || meta.feature_dimensions != k_feature_dimensions ||
        meta.feature_parts != k_feature_point_count || meta.feature_stride < 1 || meta.feature_stride > 1000) {
        return check.fail_at<DbMeta>(k_section_meta, 0, "frame time, feature layout or stride is not one this kumite reads");
    }
    for (std::size_t a = 0; a < db.actors.size(); ++a) {
        const DbActor& actor = db.actors[a];
        if (!string_in_table(db, actor.name)) return check.fail_at<DbActor>(k_section_actors, a, "name is outside the string table");
        const float sizes[] = {actor.leg_length_m, actor.arm_length_m, actor.height_m, actor.ankle_height_m};
        if (!all_finite(sizes) || actor.leg_length_m <= 0.0f || actor.arm_length_m <= 0.0f) {
            return check.fail_at<DbActor>(k_section_actors, a, "sizes must be finite and positive");
        }
    }
    return {};
}

// Clips tile the poses in order: clip c's poses are first_pose .. first_pose + frame_count - 1, so a pose index
// reached through a clip and a frame below its frame count is always inside POSE, MIRF and FEAT.
Result<void> check_clips(const MotionDatabaseView& db, const Checker& check) {
    std::uint64_t next_pose = 0;
    for (std::size_t c = 0; c < db.clips.size(); ++c) {
        const DbClip& clip = db.clips[c];
        auto fail = [&](const std::string& what) { return check.fail_at<DbClip>(k_section_clips, c, what); };
        if (!string_in_table(db, clip.name) || !string_in_table(db, clip.semantics) || !string_in_table(db, clip.source)) return fail("a name is outside the string table");
        if (clip.actor >= db.actors.size()) return fail("actor " + out_of_range(clip.actor, db.actors.size(), "actors"));
        if (clip.frame_count == 0 || clip.first_pose != next_pose || next_pose + clip.frame_count > db.poses.size()) {
            return fail("its poses must follow the previous clip's within the " + std::to_string(db.poses.size()) + " poses");
        }
        next_pose += clip.frame_count;
        if (clip.segment < -1 || clip.segment >= k_body_part_count) return fail("segment " + std::to_string(clip.segment) + " is not a body part");
        if (clip.side > 2) return fail("side " + std::to_string(clip.side) + " is not none, left or right");
        if (clip.hit_frame < -1 || clip.hit_frame >= static_cast<std::int64_t>(clip.frame_count)) {
            return fail("hit frame " + out_of_range(std::uint64_t(std::int64_t(clip.hit_frame)), clip.frame_count, "frames"));
        }
        if (db_clip_is_strike(clip) && (clip.hit_frame < 0 || clip.segment < 0)) return fail("a strike without hit frame or segment");
        if (!all_finite(clip.box_min) || !all_finite(clip.box_max)) return fail("its box is not finite");
        if (clip.kind >= k_strike_kind_count) return fail("kind " + std::to_string(clip.kind) + " is not a strike kind");
        if (clip.height >= k_strike_height_count) return fail("height " + std::to_string(clip.height) + " is not low, middle or high");
        if (clip.reserved != 0) return fail("its reserved bytes are not 0");
    }
    if (next_pose != db.poses.size()) {
        return check.fail_at<DbClip>(k_section_clips, db.clips.size() - (db.clips.empty() ? 0 : 1),
                                     "clips cover " + std::to_string(next_pose) + " of " + std::to_string(db.poses.size()) + " poses");
    }
    return {};
}

// The per-pose sections hold one record (or feature) per pose; MEMB one index per pose.
Result<void> check_section_sizes(const MotionDatabaseView& db, const Checker& check) {
    if (db.mir_frames.size() != db.poses.size()) {
        return check.fail_at<DbMirFrame>(k_section_mir_frames, 0, std::to_string(db.mir_frames.size()) + " frames for " +
                                                                      std::to_string(db.poses.size()) + " poses");
    }
    if (db.features.size() != db.poses.size() * k_feature_dimensions) {
        return check.fail_at<float>(k_section_features, 0, "holds " + std::to_string(db.features.size()) + " values, not " +
                                                               std::to_string(db.poses.size()) + " poses x " + std::to_string(k_feature_dimensions));
    }
    if (db.centroids.size() != db.clusters.size() * k_feature_dimensions) {
        return check.fail_at<float>(k_section_centroids, 0, "holds " + std::to_string(db.centroids.size()) + " values, not " +
                                                                std::to_string(db.clusters.size()) + " clusters x " + std::to_string(k_feature_dimensions));
    }
    if (db.members.size() != db.poses.size()) {
        return check.fail_at<std::uint32_t>(k_section_members, 0, std::to_string(db.members.size()) + " members for " +
                                                                      std::to_string(db.poses.size()) + " poses");
    }
    return {};
}

// Clusters tile the members in order, so a member index reached through a cluster is inside MEMB. Which pose each
// member names is a value (verify_values); the retriever bounds it where it reads it (core/retrieval.cpp).
Result<void> check_clusters(const MotionDatabaseView& db, const Checker& check) {
    std::uint64_t next_member = 0;
    for (std::size_t c = 0; c < db.clusters.size(); ++c) {
        const DbCluster& cluster = db.clusters[c];
        if (cluster.first_member != next_member || next_member + cluster.member_count > db.members.size() || !std::isfinite(cluster.radius)) {
            return check.fail_at<DbCluster>(k_section_clusters, c, "members must follow the previous cluster's within the " +
                                                                       std::to_string(db.members.size()) + " members");
        }
        next_member += cluster.member_count;
    }
    if (next_member != db.members.size()) {
        return check.fail_at<DbCluster>(k_section_clusters, 0, "clusters hold " + std::to_string(next_member) + " members for " +
                                                                   std::to_string(db.poses.size()) + " poses");
    }
    if (!all_finite(db.centroids)) {
        std::size_t i = 0;
        while (std::isfinite(db.centroids[i])) ++i;
        return check.fail_at<float>(k_section_centroids, i, "cluster " + std::to_string(i / k_feature_dimensions) + "'s centroid is not finite");
    }
    return {};
}

} // namespace

Result<void> check_structure(const MotionDatabaseView& db, const Checker& check) {
    if (Result<void> checked = check_meta_and_actors(db, check); !checked) return checked;
    if (Result<void> checked = check_clips(db, check); !checked) return checked;
    if (Result<void> checked = check_section_sizes(db, check); !checked) return checked;
    if (Result<void> checked = check_clusters(db, check); !checked) return checked;
    if (db.poses.empty() || db.clusters.empty()) return check.fail(0, "the database holds no poses or no clusters");
    return {};
}

} // namespace kumite::database_checks
