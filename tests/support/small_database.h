#pragma once
// A small motion database built in memory, for tests of the file, the verifier and the retriever on a database
// they can corrupt record by record: two clips of one actor (a 3-frame rest, a 4-frame right punch with its hit at
// frame 2), seven poses, one cluster. tests/fuzz/database_corpus/small.kdb is its written form.

#include "kumite/core/motion_database.h"

namespace kumite::test {

inline MotionDatabaseContent small_database() {
    MotionDatabaseContent db;
    db.meta.frame_time_s = 1.0f / 30.0f;
    db.meta.feature_stride = 3;
    DbActor actor;
    actor.name = db.add_string("bandai");
    actor.leg_length_m = 0.8f;
    actor.arm_length_m = 0.55f;
    actor.height_m = 1.6f;
    actor.ankle_height_m = 0.08f;
    db.actors.push_back(actor);
    for (int c = 0; c < 2; ++c) {
        DbClip clip;
        clip.name = db.add_string(c == 0 ? "guard" : "punch_r");
        clip.semantics = db.add_string(c == 0 ? "rest" : "punch");
        clip.source = db.add_string("bandai/x.bvh");
        clip.first_pose = static_cast<std::uint32_t>(db.poses.size());
        clip.frame_count = c == 0 ? 3 : 4;
        if (c == 1) {
            clip.flags = db_clip_strike;
            clip.segment = static_cast<std::int32_t>(BodyPart::hand_r);
            clip.side = static_cast<std::uint32_t>(Side::right);
            clip.hit_frame = 2;
        }
        for (std::uint32_t f = 0; f < clip.frame_count; ++f) {
            DbPose pose;
            pose.clip = static_cast<std::uint32_t>(db.clips.size());
            pose.frame = f;
            pose.hit_point[1] = 1.2f + 0.1f * f;
            db.poses.push_back(pose);
            DbMirFrame frame;
            frame.hip_centre[1] = 0.9f;
            frame.part_frames[0][3] = 1.0f;
            db.mir_frames.push_back(frame);
            for (int d = 0; d < k_feature_dimensions; ++d) db.features.push_back(0.01f * d + f);
        }
        db.clips.push_back(clip);
    }
    db.centroids.assign(k_feature_dimensions, 0.5f);
    db.clusters.push_back({0, 7, 1.0f, 0.0f});
    for (std::uint32_t p = 0; p < 7; ++p) db.members.push_back(p);
    return db;
}

} // namespace kumite::test
