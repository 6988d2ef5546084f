#pragma once
// Inside the bake: one annotated clip (or its mirror) turned into database records.

#include "bake_sources.h"

namespace kumite::bake {

struct BakedClip {
    std::string name;
    std::string semantics;
    DbClip record;                  // strings and first_pose are filled when the database is assembled
    std::vector<DbPose> poses;      // clip index filled at assembly
    std::vector<DbMirFrame> mir_frames;
    std::vector<float> features;    // [frame * k_feature_dimensions]
    Clip motion;                    // resampled (and mirrored) motion on the actor's skeleton
};

// `feature_stride`: frames between the samples of a feature's window.
BakedClip bake_clip(const RawAnnotatedClip& annotation, bool mirrored, const BakeSource& source, double frame_time_s, int feature_stride);

// The name of the mirrored twin: "kick_r_060" -> "kick_r_060~mirror".
std::string mirrored_clip_name(const std::string& name);

} // namespace kumite::bake
