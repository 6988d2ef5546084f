#pragma once
// OpenEXR export of a baked database, for engines and for looking at it:
// - `pose_distance.exr`: one FLOAT channel Y, width = height = poses, pixel (i, j) = Kovar's distance between
//   poses i and j (leg lengths squared); attribute `kumite:clips` lists "name first_pose frames" per clip.
// - `clip_NNN_NAME.exr` per clip: an animation texture on the actor's skeleton, one row per frame, RGBA FLOAT;
//   pixel 0 is the root translation (x, y, z in metres, 0), pixel 1 + j the local rotation of joint j as a
//   quaternion (x, y, z, w). Attributes: `kumite:joints` (names), `kumite:parents` (parent names, "" for the
//   root), `kumite:frame_time_s`.
// Files are written to a temporary name and renamed, so a reader never sees half a file.

#include "bake.h"

namespace kumite::bake {

struct ExrExportSummary {
    std::vector<std::filesystem::path> files;
    double seconds = 0.0;
};

Result<ExrExportSummary> exr_export(const std::filesystem::path& folder, const BakeResult& baked, int jobs,
                                    const std::function<void(const BakeProgress&)>& progress = {});

} // namespace kumite::bake
