#include "pose_heatmap.h"

#include "kumite/core/pose_features.h"

#include <algorithm>
#include <limits>

namespace kumite::annotate {
namespace {

void fill_distances(PoseHeatmap& heatmap, const std::vector<std::span<const float>>& features) {
    heatmap.size = static_cast<int>(features.size());
    heatmap.distances.assign(features.size() * features.size(), 0.0f);
    for (int row = 0; row < heatmap.size; ++row) {
        for (int column = row + 1; column < heatmap.size; ++column) {
            const float distance = static_cast<float>(pose_feature_distance(features[size_t(row)], features[size_t(column)]));
            heatmap.distances[size_t(row * heatmap.size + column)] = distance;
            heatmap.distances[size_t(column * heatmap.size + row)] = distance;
            heatmap.max_distance = std::max(heatmap.max_distance, distance);
        }
    }
}

std::string pose_label(const MotionDatabaseView& database, std::uint32_t pose) {
    const DbPose& record = database.poses[pose];
    return std::string(database.string(database.clips[record.clip].name)) + " " + std::to_string(record.frame);
}

} // namespace

PoseHeatmap pose_heatmap_of_clusters(const MotionDatabaseView& database) {
    PoseHeatmap heatmap;
    std::vector<std::span<const float>> features;
    for (std::uint32_t cluster = 0; cluster < database.clusters.size(); ++cluster) {
        const DbCluster& record = database.clusters[cluster];
        features.push_back(database.centroid(cluster));
        std::uint32_t nearest = 0;
        double nearest_distance = std::numeric_limits<double>::infinity();
        for (std::uint32_t member = 0; member < record.member_count; ++member) {
            const std::uint32_t pose = database.members[record.first_member + member];
            const double distance = pose_feature_distance(database.centroid(cluster), database.feature(pose));
            if (distance < nearest_distance) nearest_distance = distance, nearest = pose;
        }
        heatmap.poses.push_back(nearest);
        heatmap.labels.push_back("cluster " + std::to_string(cluster) + " (" + std::to_string(record.member_count) + " poses)");
    }
    fill_distances(heatmap, features);
    return heatmap;
}

PoseHeatmap pose_heatmap_of_poses(const MotionDatabaseView& database, int max_rows) {
    PoseHeatmap heatmap;
    const std::size_t pose_count = database.poses.size();
    if (pose_count == 0 || max_rows <= 0) return heatmap;
    const std::size_t step = (pose_count + static_cast<std::size_t>(max_rows) - 1) / static_cast<std::size_t>(max_rows);
    std::vector<std::span<const float>> features;
    for (std::size_t pose = 0; pose < pose_count; pose += step) {
        features.push_back(database.feature(static_cast<std::uint32_t>(pose)));
        heatmap.poses.push_back(static_cast<std::uint32_t>(pose));
        heatmap.labels.push_back(pose_label(database, static_cast<std::uint32_t>(pose)));
    }
    fill_distances(heatmap, features);
    return heatmap;
}

PoseLocation pose_location(const MotionDatabaseView& database, std::uint32_t pose) {
    const DbPose& record = database.poses[pose];
    const DbClip& clip = database.clips[record.clip];
    PoseLocation location;
    location.clip_name = std::string(database.string(clip.name));
    location.mirrored = (clip.flags & db_clip_mirrored) != 0;
    const std::string mirror_suffix = "~mirror"; // bake_clip.cpp's mirrored_clip_name
    if (location.mirrored && location.clip_name.size() > mirror_suffix.size() &&
        location.clip_name.compare(location.clip_name.size() - mirror_suffix.size(), mirror_suffix.size(), mirror_suffix) == 0) {
        location.clip_name.resize(location.clip_name.size() - mirror_suffix.size());
    }
    location.clip_frame = static_cast<int>(record.frame);
    location.capture_time_s = static_cast<double>(record.frame) * static_cast<double>(database.meta.frame_time_s);
    location.source_first_frame = static_cast<int>(clip.source_first_frame);
    return location;
}

} // namespace kumite::annotate
