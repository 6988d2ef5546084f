// Opening a motion database: MotionDatabase::open (map + structure) on the reference database and on one ten
// times its size (the reference's clips repeated, written to a temporary folder and removed at the end), plus any
// other database given (scripts/make_large_database.sh bakes one from every Bandai capture). Per database, in the
// same run and on the same warm page cache:
//   - open: what the runtime pays (header, sections, actors, clips, clusters; no per-pose record read);
//   - baseline: open followed by verify_values (every value read and checked at open, as a parsing opener does);
//   - verify: MotionDatabase::verify on an open database (every value and the content hash: db-info --verify).
// Each timing maps the file anew and unmaps it (the database goes out of scope inside the timed work).
//
// usage: database_open_bench REF.kdb [MORE.kdb...] [--repeats N] [--scale K]
//        (bake the reference with `kumite bake data/annotations/reference.json -o ref.kdb`)
// Prints one JSON document.

#include "kumite/formats/motion_database_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <iostream>
#include <string>
#include <vector>

using namespace kumite;

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "database_open_bench: " << message << "\n";
    std::exit(1);
}

template <class Work>
nlohmann::json time_runs(int repeats, Work&& work) {
    work(); // warm: the first run maps pages the later ones find in the page cache
    std::vector<double> times;
    for (int i = 0; i < repeats; ++i) {
        const auto start = Clock::now();
        work();
        times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    const std::size_t p99 = std::min(times.size() - 1, static_cast<std::size_t>(0.99 * times.size()));
    return {{"n", repeats}, {"median", times[times.size() / 2]}, {"p99", times[p99]}, {"max", times.back()}};
}

// The database `scale` times over: every clip, pose, MIR frame and feature repeated, each copy's members added
// to the same clusters (so the counts grow and the cluster count does not, as in a bigger bake).
MotionDatabaseContent repeated(const MotionDatabaseView& db, int scale) {
    MotionDatabaseContent out;
    out.meta = db.meta;
    out.strings.assign(db.strings.begin(), db.strings.end());
    out.actors.assign(db.actors.begin(), db.actors.end());
    out.centroids.assign(db.centroids.begin(), db.centroids.end());
    const auto pose_count = static_cast<std::uint32_t>(db.poses.size());
    for (int copy = 0; copy < scale; ++copy) {
        const auto clip_offset = static_cast<std::uint32_t>(copy * db.clips.size());
        for (DbClip clip : db.clips) {
            clip.first_pose += copy * pose_count;
            out.clips.push_back(clip);
        }
        for (DbPose pose : db.poses) {
            pose.clip += clip_offset;
            out.poses.push_back(pose);
        }
        out.mir_frames.insert(out.mir_frames.end(), db.mir_frames.begin(), db.mir_frames.end());
        out.features.insert(out.features.end(), db.features.begin(), db.features.end());
    }
    for (const DbCluster& cluster : db.clusters) {
        DbCluster grown = cluster;
        grown.first_member = static_cast<std::uint32_t>(out.members.size());
        grown.member_count = cluster.member_count * scale;
        for (int copy = 0; copy < scale; ++copy) {
            for (std::uint32_t m = 0; m < cluster.member_count; ++m) out.members.push_back(db.members[cluster.first_member + m] + copy * pose_count);
        }
        out.clusters.push_back(grown);
    }
    return out;
}

nlohmann::json bench_database(const std::filesystem::path& path, const std::string& label, int repeats) {
    Result<MotionDatabase> probe = MotionDatabase::open(path, /*verify=*/true);
    if (!probe) fail(probe.error().message);
    const MotionDatabaseView& db = probe->view();
    auto open = [&] {
        Result<MotionDatabase> database = MotionDatabase::open(path);
        if (!database) fail(database.error().message);
    };
    auto open_and_values = [&] {
        Result<MotionDatabase> database = MotionDatabase::open(path);
        if (!database || !database->verify_values()) fail(path.string() + ": refused");
    };
    const int slow_repeats = std::max(3, repeats / 5); // the baseline and verify read every byte
    const nlohmann::json open_us = time_runs(repeats, open);
    const nlohmann::json baseline_us = time_runs(slow_repeats, open_and_values);
    const nlohmann::json verify_us = time_runs(slow_repeats, [&] {
        if (!probe->verify()) fail(path.string() + ": refused by verify");
    });
    return {{"database", label},
            {"file", path.string()},
            {"bytes", probe->image().byte_size()},
            {"clips", db.clips.size()},
            {"poses", db.poses.size()},
            {"clusters", db.clusters.size()},
            {"open_us", open_us},
            {"baseline", {{"name", "open + verify_values (every value checked at open)"}, {"us", baseline_us}}},
            {"speedup_vs_baseline", baseline_us["median"].get<double>() / open_us["median"].get<double>()},
            {"verify_us", verify_us}};
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    int repeats = 200;
    int scale = 10;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
        else if (argument == "--scale" && i + 1 < argc) scale = std::max(2, std::atoi(argv[++i]));
        else if (argument == "--help") {
            std::cout << "usage: database_open_bench REF.kdb [MORE.kdb...] [--repeats N] [--scale K]\n";
            return 0;
        } else files.emplace_back(argument);
    }
    if (files.empty()) fail("give the reference database (kumite bake data/annotations/reference.json -o ref.kdb)");

    Result<MotionDatabase> reference = MotionDatabase::open(files[0], /*verify=*/true);
    if (!reference) fail(reference.error().message);
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("kumite-open-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder, error);
    if (error) fail(folder.string() + ": " + error.message());
    const std::filesystem::path scaled = folder / ("reference_x" + std::to_string(scale) + ".kdb");
    if (Result<void> written = motion_database_write(scaled, repeated(reference->view(), scale).view()); !written) fail(written.error().message);

    nlohmann::json databases = nlohmann::json::array();
    databases.push_back(bench_database(files[0], "reference", repeats));
    databases.push_back(bench_database(scaled, "reference x" + std::to_string(scale), repeats));
    for (std::size_t f = 1; f < files.size(); ++f) databases.push_back(bench_database(files[f], files[f].filename().string(), repeats));
    std::filesystem::remove_all(folder, error);

    const double reference_open = databases[0]["open_us"]["median"].get<double>();
    const nlohmann::json report = {{"benchmark", "database_open"},
                                   {"repeats", repeats},
                                   {"databases", databases},
                                   {"open_median_ratio_scaled_to_reference", databases[1]["open_us"]["median"].get<double>() / reference_open}};
    std::cout << report.dump(2) << "\n";
    return 0;
}
