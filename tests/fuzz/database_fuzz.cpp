// libFuzzer target: any bytes handed to the database opener are either refused with a message or give a view
// whose every index, string reference and span the runtime could follow stays inside the mapping (ASan checks).

#include "kumite/formats/motion_database_file.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

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
    volatile std::size_t sink = 0;
    for (const kumite::DbClip& clip : db.clips) {
        sink = sink + db.string(clip.name).size() + db.string(clip.semantics).size() + db.actors[clip.actor].name.length;
        for (std::uint32_t frame = 0; frame < clip.frame_count; ++frame) {
            const kumite::DbPose& pose = db.poses[clip.first_pose + frame];
            sink = sink + pose.clip + db.mir_frames[clip.first_pose + frame].spine_count;
            sink = sink + static_cast<std::size_t>(db.feature(clip.first_pose + frame).back() != 0.0f);
        }
    }
    for (std::size_t c = 0; c < db.clusters.size(); ++c) {
        const kumite::DbCluster& cluster = db.clusters[c];
        sink = sink + static_cast<std::size_t>(db.centroid(static_cast<std::uint32_t>(c)).front() != 0.0f);
        for (std::uint32_t m = 0; m < cluster.member_count; ++m) sink = sink + db.poses[db.members[cluster.first_member + m]].frame;
    }
    kumite::MirFrame frame;
    if (!db.mir_frames.empty()) kumite::db_mir_frame_load(frame, db.mir_frames.back());
    return 0;
}
