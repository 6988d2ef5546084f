// libFuzzer target: any bytes handed to the database opener are either refused with a message or give a view
// whose every span, clip, string, actor and cluster range the runtime could follow stays inside the mapping, and
// a retriever built over it (the runtime's reader of the per-pose values the opener does not check) stays inside
// too; when verify_values also accepts, every pose record's clip and every member can be followed (ASan checks).

#include "kumite/core/retrieval.h"
#include "kumite/formats/motion_database_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace {

// What the structure promises: clips tile the poses, clusters the members, strings and actors are in range.
std::size_t follow_structure(const kumite::MotionDatabaseView& db) {
    std::size_t sink = 0;
    for (const kumite::DbClip& clip : db.clips) {
        sink += db.string(clip.name).size() + db.string(clip.semantics).size() + db.string(clip.source).size() + db.actors[clip.actor].name.length;
        for (std::uint32_t frame = 0; frame < clip.frame_count; ++frame) {
            const std::uint32_t pose = clip.first_pose + frame;
            sink += db.poses[pose].flags + db.mir_frames[pose].spine_count;
            sink += static_cast<std::size_t>(db.feature(pose).back() != 0.0f);
        }
        if (clip.hit_frame >= 0) sink += db.poses[clip.first_pose + clip.hit_frame].flags;
    }
    for (std::size_t c = 0; c < db.clusters.size(); ++c) {
        const kumite::DbCluster& cluster = db.clusters[c];
        sink += static_cast<std::size_t>(db.centroid(static_cast<std::uint32_t>(c)).front() != 0.0f);
        for (std::uint32_t m = 0; m < cluster.member_count; ++m) sink += db.members[cluster.first_member + m];
    }
    kumite::MirFrame frame;
    if (!db.mir_frames.empty()) kumite::db_mir_frame_load(frame, db.mir_frames.back()); // chain counts clamped
    return sink;
}

// The retriever reads members, features and headings without a verify: a query for every semantics must stay in
// bounds and answer with a start inside its clip.
void query_every_semantics(const kumite::MotionDatabaseView& db) {
    const kumite::Retriever retriever(db);
    kumite::RetrievalWorkspace workspace = retriever.make_workspace();
    kumite::RetrievalQuery query;
    query.pose_feature = db.feature(0);
    query.target_world = Eigen::Vector3d(0.1, 1.2, 0.6);
    query.character = {0.9, 0.6};
    for (const kumite::DbClip& clip : db.clips) {
        query.semantics = retriever.semantics_id(db.string(clip.semantics));
        for (const kumite::RetrievalResult& result : {retriever.query(query, workspace), retriever.query_exhaustive(query)}) {
            if (!result.found) continue;
            if (result.clip < 0 || std::size_t(result.clip) >= db.clips.size()) std::abort();
            const kumite::DbClip& found = db.clips[static_cast<std::size_t>(result.clip)];
            // The contact: where the hit point has covered the retriever's share of its way to the hit, at or before it.
            if (result.start_frame < 0 || std::uint32_t(result.start_frame) >= found.frame_count || result.contact_frame < 0 ||
                result.contact_frame > found.hit_frame ||
                result.contact_frame != kumite::db_clip_contact_frame(db, found, retriever.settings().contact_extension, retriever.settings().contact_speed_share)) {
                std::abort();
            }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
    kumite::Result<kumite::DatabaseImage> image = kumite::DatabaseImage::view(bytes, "fuzz.kdb", /*verify_hash=*/false);
    if (!image) {
        if (image.error().message.empty()) std::abort();
        return 0;
    }
    kumite::Result<kumite::MotionDatabase> database = kumite::MotionDatabase::from_image(std::move(*image), "fuzz.kdb");
    if (!database) {
        if (database.error().message.empty()) std::abort();
        return 0;
    }
    const kumite::MotionDatabaseView& db = database->view();
    volatile std::size_t sink = follow_structure(db);
    if (db.clips.size() <= 64 && db.poses.size() <= 4096) query_every_semantics(db); // small inputs: fuzzing speed
    kumite::Result<void> verified = database->verify_values();
    if (!verified) {
        if (verified.error().message.empty()) std::abort();
        return 0;
    }
    for (const kumite::DbPose& pose : db.poses) sink = sink + db.clips[pose.clip].first_pose + pose.frame;
    for (std::uint32_t member : db.members) sink = sink + db.poses[member].frame;
    return 0;
}
