#pragma once
// Pose-distance heatmaps of a baked database: Kovar's distance (pose_feature_distance, squared leg lengths)
// between the clusters' centroids, between poses sampled evenly over the database, or from each pose of one clip
// to every centroid. Each row and column stands for one database pose so a click on a cell can jump to the pose
// pair: for a cluster, its member nearest the centroid.

#include "kumite/core/motion_database.h"

#include <cstdint>
#include <string>
#include <vector>

namespace kumite::annotate {

struct PoseHeatmap {
    int rows = 0;
    int columns = 0;
    std::vector<float> distances;            // [row * columns + column]
    std::vector<std::uint32_t> row_poses;    // [row] the database pose the row stands for
    std::vector<std::uint32_t> column_poses; // [column]
    std::vector<std::string> row_labels;     // "cluster 3 (40 poses)" or "clip_name 12"
    std::vector<std::string> column_labels;
    float max_distance = 0.0f;

    float at(int row, int column) const { return distances[static_cast<size_t>(row * columns + column)]; }
};

// Square and symmetric, zero diagonal.
PoseHeatmap pose_heatmap_of_clusters(const MotionDatabaseView& database);
// At most `max_rows` poses, every ceil(poses / max_rows)-th; square and symmetric.
PoseHeatmap pose_heatmap_of_poses(const MotionDatabaseView& database, int max_rows);
// Rows: the poses of the baked clip `clip_name` (the annotated one, not its mirror); columns: the clusters.
// Empty when the database has no such clip.
PoseHeatmap pose_heatmap_of_clip(const MotionDatabaseView& database, const std::string& clip_name);

// Where a database pose comes from: its annotated clip (mirrors name their original) and the capture frame.
struct PoseLocation {
    std::string clip_name;  // as in the annotation file
    bool mirrored = false;
    int clip_frame = 0;     // in the baked clip (database frame time)
    double capture_time_s = 0.0; // after the clip's first capture frame
    int source_first_frame = 0;
};
PoseLocation pose_location(const MotionDatabaseView& database, std::uint32_t pose);

} // namespace kumite::annotate
