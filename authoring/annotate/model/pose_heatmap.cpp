#include "pose_heatmap.h"

#include "kumite/core/pose_features.h"

#include <algorithm>
#include <limits>

namespace kumite::annotate {
namespace {

struct Axis {
    std::vector<std::span<const float>> features;
    std::vector<std::uint32_t> poses;
    std::vector<std::string> labels;
};

std::string pose_label(const MotionDatabaseView& database, std::uint32_t pose) {
    const DbPose& record = database.poses[pose];
    return std::string(database.string(database.clips[record.clip].name)) + " " + std::to_string(record.frame);
}

// Every centroid, each standing for its member nearest to it.
Axis cluster_axis(const MotionDatabaseView& database) {
    Axis axis;
    for (std::uint32_t cluster = 0; cluster < database.clusters.size(); ++cluster) {
        const DbCluster& record = database.clusters[cluster];
        axis.features.push_back(database.centroid(cluster));
        std::uint32_t nearest = 0;
        double nearest_distance = std::numeric_limits<double>::infinity();
        for (std::uint32_t member = 0; member < record.member_count; ++member) {
            const std::uint32_t pose = database.members[record.first_member + member];
            const double distance = pose_feature_distance(database.centroid(cluster), database.feature(pose));
            if (distance < nearest_distance) nearest_distance = distance, nearest = pose;
        }
        axis.poses.push_back(nearest);
        axis.labels.push_back("cluster " + std::to_string(cluster) + " (" + std::to_string(record.member_count) + " poses)");
    }
    return axis;
}

void add_pose(Axis& axis, const MotionDatabaseView& database, std::uint32_t pose) {
    axis.features.push_back(database.feature(pose));
    axis.poses.push_back(pose);
    axis.labels.push_back(pose_label(database, pose));
}

PoseHeatmap heatmap_between(Axis rows, Axis columns, bool symmetric) {
    PoseHeatmap heatmap;
    heatmap.rows = static_cast<int>(rows.poses.size());
    heatmap.columns = static_cast<int>(columns.poses.size());
    heatmap.distances.assign(size_t(heatmap.rows) * size_t(heatmap.columns), 0.0f);
    for (int row = 0; row < heatmap.rows; ++row) {
        for (int column = symmetric ? row + 1 : 0; column < heatmap.columns; ++column) {
            const float distance = static_cast<float>(pose_feature_distance(rows.features[size_t(row)], columns.features[size_t(column)]));
            heatmap.distances[size_t(row * heatmap.columns + column)] = distance;
            if (symmetric) heatmap.distances[size_t(column * heatmap.columns + row)] = distance;
            heatmap.max_distance = std::max(heatmap.max_distance, distance);
        }
    }
    heatmap.row_poses = std::move(rows.poses);
    heatmap.row_labels = std::move(rows.labels);
    heatmap.column_poses = std::move(columns.poses);
    heatmap.column_labels = std::move(columns.labels);
    return heatmap;
}

} // namespace

PoseHeatmap pose_heatmap_of_clusters(const MotionDatabaseView& database) {
    Axis clusters = cluster_axis(database);
    return heatmap_between(clusters, clusters, true);
}

PoseHeatmap pose_heatmap_of_poses(const MotionDatabaseView& database, int max_rows) {
    Axis poses;
    const std::size_t pose_count = database.poses.size();
    if (pose_count == 0 || max_rows <= 0) return {};
    const std::size_t step = (pose_count + static_cast<std::size_t>(max_rows) - 1) / static_cast<std::size_t>(max_rows);
    for (std::size_t pose = 0; pose < pose_count; pose += step) add_pose(poses, database, static_cast<std::uint32_t>(pose));
    return heatmap_between(poses, poses, true);
}

PoseHeatmap pose_heatmap_of_clip(const MotionDatabaseView& database, const std::string& clip_name) {
    for (const DbClip& clip : database.clips) {
        if (database.string(clip.name) != clip_name || (clip.flags & db_clip_mirrored) != 0) continue;
        Axis poses;
        for (std::uint32_t frame = 0; frame < clip.frame_count; ++frame) add_pose(poses, database, clip.first_pose + frame);
        return heatmap_between(std::move(poses), cluster_axis(database), false);
    }
    return {};
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
