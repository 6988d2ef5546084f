#include "bake.h"

#include "bake_clip.h"
#include "parallel_for.h"

#include "kumite/core/pose_clusters.h"

#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace kumite::bake {
namespace {

struct ClipJob {
    int annotation = 0;
    bool mirrored = false;
};

// Appends the baked clips in job order, with their strings, pose ranges and clip indices.
void assemble_clips(MotionDatabaseContent& db, std::vector<BakedClip>& baked, const std::vector<ClipJob>& jobs,
                    const RawAnnotations& annotations) {
    for (size_t index = 0; index < baked.size(); ++index) {
        BakedClip& clip = baked[index];
        DbClip record = clip.record;
        record.name = db.add_string(clip.name);
        record.semantics = db.add_string(clip.semantics);
        record.source = db.add_string(annotations.clips[jobs[index].annotation].source);
        record.first_pose = static_cast<std::uint32_t>(db.poses.size());
        for (DbPose& pose : clip.poses) pose.clip = static_cast<std::uint32_t>(db.clips.size());
        db.clips.push_back(record);
        db.poses.insert(db.poses.end(), clip.poses.begin(), clip.poses.end());
        db.mir_frames.insert(db.mir_frames.end(), clip.mir_frames.begin(), clip.mir_frames.end());
        db.features.insert(db.features.end(), clip.features.begin(), clip.features.end());
    }
}

void assemble_clusters(MotionDatabaseContent& db, const PoseClusters& clusters) {
    db.centroids = clusters.centroids;
    for (int c = 0; c < clusters.k; ++c) {
        DbCluster cluster;
        cluster.first_member = static_cast<std::uint32_t>(db.members.size());
        double radius = 0.0;
        for (size_t pose = 0; pose < clusters.assignment.size(); ++pose) {
            if (clusters.assignment[pose] != c) continue;
            db.members.push_back(static_cast<std::uint32_t>(pose));
            radius = std::max(radius, clusters.distance[pose]);
        }
        cluster.member_count = static_cast<std::uint32_t>(db.members.size() - cluster.first_member);
        cluster.radius = static_cast<float>(radius);
        db.clusters.push_back(cluster);
    }
}

// Leg strikes start only where the support foot is planted (retrieval.h): one whose support foot never is,
// from its first frame to its hit, bakes but can never be chosen.
void warn_unservable_strikes(const MotionDatabaseView& db, std::string_view annotations_name, std::vector<BakeWarning>& warnings) {
    for (const DbClip& clip : db.clips) {
        if (db_clip_support_foot(clip) && db_clip_support_down_until(db, clip) < 0) {
            warnings.push_back({std::string(annotations_name) + ": clip " + std::string(db.string(clip.name)),
                                "the support foot is never planted before the hit; retrieval will never start this strike"});
        }
    }
}

} // namespace

Result<BakeResult> bake_database(const RawAnnotations& annotations, std::string_view annotations_name, const BakeOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    if (Result<void> valid = annotations.validate(annotations_name); !valid) return valid.error();
    if (annotations.clips.empty()) return make_error(ErrorCode::invalid, std::string(annotations_name) + ": no clips to bake");
    if (!(options.frame_time_s > 0.0 && options.frame_time_s <= 1.0)) return make_error(ErrorCode::invalid, "frame time must be in (0, 1] s");
    const int jobs = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
    std::mutex progress_mutex;
    auto report = [&](const char* stage, int done, int total) {
        if (options.progress) options.progress(BakeProgress{stage, done, total});
    };

    Result<std::vector<BakeSource>> read = bake_read_sources(annotations, annotations_name, options, jobs,
                                                             [&](int done, int total) { report("reading captures", done, total); });
    if (!read) return read.error();
    std::vector<BakeSource>& sources = *read;
    BakeResult result;
    for (const BakeSource& source : sources) result.warnings.insert(result.warnings.end(), source.notes.begin(), source.notes.end());
    const std::vector<BakeActor> actors = bake_find_actors(sources);

    std::vector<ClipJob> clip_jobs;
    std::vector<int> source_of_annotation;
    for (int index = 0; index < static_cast<int>(annotations.clips.size()); ++index) {
        const RawAnnotatedClip& clip = annotations.clips[index];
        int source = 0;
        while (sources[source].name != clip.source) ++source;
        source_of_annotation.push_back(source);
        if (Result<void> fits = raw_clip_validate_frames(clip, sources[source].file.clip.frame_count()); !fits) {
            return make_error(ErrorCode::invalid, std::string(annotations_name) + ": " + fits.error().message);
        }
        clip_jobs.push_back({index, false});
        if (clip.mirror) clip_jobs.push_back({index, true});
    }

    const int feature_stride = std::max(1, static_cast<int>(std::lround(options.feature_window_s / options.frame_time_s)));
    std::vector<BakedClip> baked(clip_jobs.size());
    int clips_done = 0;
    parallel_for(static_cast<int>(clip_jobs.size()), jobs, [&](int index) {
        const ClipJob& job = clip_jobs[index];
        baked[index] = bake_clip(annotations.clips[job.annotation], job.mirrored, sources[source_of_annotation[job.annotation]],
                                 options.frame_time_s, feature_stride);
        std::lock_guard lock(progress_mutex);
        report("encoding clips", ++clips_done, static_cast<int>(clip_jobs.size()));
    });

    MotionDatabaseContent& db = result.database;
    for (const BakeActor& actor : actors) {
        DbActor record = bake_actor_record(sources[actor.first_source]);
        record.name = db.add_string(actor.name);
        db.actors.push_back(record);
    }
    assemble_clips(db, baked, clip_jobs, annotations);
    warn_unservable_strikes(db.view(), annotations_name, result.warnings);

    const PoseClusters clusters = pose_clusters_compute(db.features, options.clusters, options.seed, options.max_kmeans_iterations, jobs,
                                                        [&](int iteration) { report("clustering poses", iteration, options.max_kmeans_iterations); });
    report("clustering poses", clusters.iterations, clusters.iterations); // converged: the bar ends full
    assemble_clusters(db, clusters);
    db.meta.frame_time_s = static_cast<float>(options.frame_time_s);
    db.meta.feature_stride = static_cast<std::uint32_t>(feature_stride);
    db.meta.cluster_seed = options.seed;
    db.meta.kmeans_iterations = static_cast<std::uint32_t>(clusters.iterations);
    db.meta.cluster_inertia = static_cast<float>(clusters.inertia);

    if (options.keep_motion) {
        for (BakedClip& clip : baked) result.motions.push_back({clip.name, std::move(clip.motion)});
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

} // namespace kumite::bake
