#pragma once
// The bake: an annotation file and its captures become one motion database (ARCHITECTURE.md steps 1-4). Every
// annotated clip (and its mirror when asked) is trimmed, resampled to the database's frame time, encoded in the
// morphology-independent representation, given per-pose features, foot contacts, heading frames and, for
// strikes, the hit trajectory's boxes; then all poses are clustered. Shared by `kumite bake` and the annotation
// window. Same annotations and options, same bytes: threads only split independent work.

#include "kumite/core/motion_database.h"
#include "kumite/formats/annotation_file.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace kumite::bake {

struct BakeProgress {
    std::string stage; // "reading captures", "encoding clips", "clustering poses"
    int done = 0;
    int total = 0;
};

struct BakeOptions {
    std::filesystem::path mocap_root = ".";   // annotation sources are relative to it (absolute ones are kept)
    int clusters = 16;
    int jobs = 0;                             // 0: every core
    double frame_time_s = 1.0 / 30.0;         // the database's
    // The rate of captures whose files give none and the annotation file's "captures" does not list (--fps).
    std::optional<double> capture_fps;
    double feature_window_s = 0.1;            // between the samples of a pose feature's window
    std::uint64_t seed = 0x6b756d697465ull;
    int max_kmeans_iterations = 50;
    bool keep_motion = false;                 // keep each clip's resampled motion (for animation textures)
    std::function<void(const BakeProgress&)> progress; // called one call at a time, from any bake thread
};

// A clip's motion as baked, on its actor's skeleton (kept on request).
struct BakedMotion {
    std::string clip_name;
    Clip clip;
};

// Something the bake says about its input: a capture it repaired, a clip that baked but will not serve as annotated.
struct BakeWarning {
    std::string where; // the capture's path, or "ANNOTATIONS: clip NAME"
    std::string what;
    std::string text() const { return where + ": " + what; }
};

struct BakeResult {
    MotionDatabaseContent database;
    std::vector<BakedMotion> motions; // [clip] when keep_motion
    double seconds = 0.0;
    // In the order of the captures, then of the clips: captures whose pinned root was moved to follow the feet, and
    // what baked but will not serve as annotated (a leg strike whose support foot is never planted before its hit:
    // retrieval never starts it from a standing fighter).
    std::vector<BakeWarning> warnings;
};

// Errors name the annotation file, the clip and what is wrong (a missing capture, a frame past its end, a
// skeleton that cannot be mirrored, ...).
Result<BakeResult> bake_database(const RawAnnotations& annotations, std::string_view annotations_name, const BakeOptions& options);

} // namespace kumite::bake
