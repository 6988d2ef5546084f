#pragma once
// The pose-distance heatmap of a baked database: Kovar's distance (pose_feature_distance, squared leg lengths)
// between the clusters' centroids, or between poses sampled evenly over the database. Each row stands for one
// pose so a click on a cell can jump to the pose pair: for a cluster, its member nearest the centroid.

#include "kumite/core/motion_database.h"

#include <cstdint>
#include <string>
#include <vector>

namespace kumite::annotate {

struct PoseHeatmap {
    int size = 0;
    std::vector<float> distances;      // [row * size + column], symmetric, zero diagonal
    std::vector<std::uint32_t> poses;  // [row] the database pose the row stands for
    std::vector<std::string> labels;   // [row] "cluster 3" or "clip_name 12"
    float max_distance = 0.0f;

    float at(int row, int column) const { return distances[static_cast<size_t>(row * size + column)]; }
};

PoseHeatmap pose_heatmap_of_clusters(const MotionDatabaseView& database);
// At most `max_rows` poses, every ceil(poses / max_rows)-th.
PoseHeatmap pose_heatmap_of_poses(const MotionDatabaseView& database, int max_rows);

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
