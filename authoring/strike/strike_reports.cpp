// The reports of one strike's retrieval and adaptation (strike_reports.h).

#include "strike_reports.h"

#include "strike_stage.h"

#include <algorithm>

namespace kumite {

namespace {

const char* reach_name(Reach reach) { return reach == Reach::limb ? "limb" : reach == Reach::torso ? "torso" : "unreachable"; }

nlohmann::json vec3(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

nlohmann::json cost_json(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    auto at = [&](double q) { return values.empty() ? 0.0 : values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))]; };
    return {{"median", at(0.5)}, {"p99", at(0.99)}, {"max", values.empty() ? 0.0 : values.back()}};
}

} // namespace

nlohmann::json adapt_report_json(const StrikePlayback& playback, const RetrievalResult& retrieved, const MotionDatabaseView& db,
                                 const Skeleton& skeleton, const Eigen::Vector3d& target) {
    const DbClip& clip = db.clips[retrieved.clip];
    return {{"effector", skeleton.names[playback.effector_joint]},
            {"contact_frame", playback.contact_frame},
            {"effector_at_contact", vec3(playback.effector_at_contact)},
            {"target", vec3(target)},
            {"contact_error_m", playback.contact_error_m},
            {"hit_frame", playback.hit_frame},
            {"overshoot_m", playback.overshoot_m},
            {"effector_speed_at_contact_mps", playback.effector_speed_at_contact_mps},
            {"approach_direction", vec3(playback.approach_direction)},
            {"joint_limit_violations", playback.joint_limit_violations},
            {"reachable", playback.reach_at_contact != Reach::unreachable},
            {"reach", reach_name(playback.reach_at_contact)},
            {"bone_length_error_m", playback.bone_length_error_m},
            {"foot_drift_m", playback.foot_drift_m},
            {"support_foot_lifted", playback.support_foot_lift_m > 0.02},
            {"support_foot_lift_m", playback.support_foot_lift_m},
            {"support_feet", {{"left", playback.support_feet[0]}, {"right", playback.support_feet[1]}}},
            {"frame_cost_us", cost_json(playback.frame_cost_us)},
            {"frames", playback.motion.frame_count()},
            {"clip", db.string(clip.name)},
            {"kind", strike_kind_name(clip.strike_kind())},
            {"height", strike_height_name(clip.strike_height())},
            {"side", side_name(static_cast<Side>(clip.side))},
            {"start_frame", retrieved.start_frame},
            {"retrieval_contact_frame", retrieved.contact_frame},
            {"offset_to_fix_m", (retrieved.contact_point_world - target).norm()}};
}

nlohmann::json query_result_json(const Retriever& retriever, const RetrievalResult& result, double latency_us) {
    const MotionDatabaseView& db = retriever.database();
    const DbClip& clip = db.clips[result.clip];
    return {{"clip", db.string(clip.name)},
            {"clip_index", result.clip},
            {"semantics", db.string(clip.semantics)},
            {"side", side_name(static_cast<Side>(clip.side))},
            {"kind", strike_kind_name(clip.strike_kind())},
            {"height", strike_height_name(clip.strike_height())},
            {"segment", body_part_name(static_cast<BodyPart>(clip.segment))},
            {"start_frame", result.start_frame},
            {"contact_frame", result.contact_frame},
            {"time_to_contact_s", result.time_to_contact_s},
            {"d_pose", result.d_pose},
            {"d_target", result.d_target_m},
            {"score", result.score},
            {"latency_us", latency_us},
            {"contact_point", vec3(result.contact_point_world)},
            {"clip_to_world", {{"angle_rad", result.clip_to_world.angle_rad}, {"x", result.clip_to_world.x}, {"z", result.clip_to_world.z}}},
            {"counts",
             {{"clusters_visited", result.counts.clusters_visited},
              {"candidates_seen", result.counts.candidates_seen},
              {"inside_box", result.counts.inside_box},
              {"nodes_visited", result.counts.nodes_visited},
              {"pose_scored", result.counts.pose_scored},
              {"target_scored", result.counts.target_scored}}}};
}


} // namespace kumite
