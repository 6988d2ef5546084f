// kumite bake: annotations + captures -> one memory-mappable motion database (authoring/bake/bake.h).

#include "capture_loading.h"
#include "commands.h"
#include "progress_display.h"
#include "warning_groups.h"

#include "bake.h"
#include "exr_export.h"
#include "kumite/formats/motion_database_file.h"

#include <cstdio>
#include <iostream>
#include <thread>

namespace kumite::cli {

const CommandSpec& bake_spec() {
    static const CommandSpec spec{
        "bake",
        "ANNOTATIONS.json -o OUT.kdb [--mocap-root DIR] [--clusters K] [--exr DIR] [--jobs N] [--fps N] [--verbose]",
        "Bakes the annotated clips (and their mirrors) into one motion database: clips resampled to 30 fps and\n"
        "stored in the morphology-independent representation, per-pose features, foot contacts and hit-trajectory\n"
        "boxes, and k-means clusters of all poses under Kovar's distance. The same inputs give the same bytes.\n"
        "--exr DIR also writes the pose-distance matrix and one animation texture per clip as OpenEXR images.\n"
        "Warnings (captures repaired, clips that will not serve as annotated) come one line per kind, with how many;\n"
        "--verbose lists every one.",
        1, 1,
        {{"output", "OUT.kdb", "the database to write (also -o); written to a temporary, then renamed"},
         mocap_root_flag(),
         {"clusters", "K", "number of pose clusters (default 16)"},
         {"exr", "DIR", "also write pose_distance.exr and clip_NNN_NAME.exr animation textures into DIR"},
         {"jobs", "N", "threads to use (default: every core)"},
         {"fps", "N", "frame rate of captures whose files give none ('Frame Time: 0') and the annotation file's\n"
                      "\"captures\" does not list"},
         {"database-fps", "F", "database frame rate (default 30)"},
         verbose_flag()}};
    return spec;
}

int run_bake(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(bake_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> output = arguments.value("output");
    if (!output) return usage_error(bake_spec(), "missing -o OUT.kdb");
    const Result<long long> clusters = arguments.integer("clusters", 1, 100000, 16);
    if (!clusters) return usage_error(bake_spec(), clusters.error().message);
    const Result<long long> jobs = arguments.integer("jobs", 1, 256, std::max(1u, std::thread::hardware_concurrency()));
    if (!jobs) return usage_error(bake_spec(), jobs.error().message);
    const Result<long long> fps = arguments.integer("database-fps", 1, 1000, 30);
    if (!fps) return usage_error(bake_spec(), fps.error().message);
    std::optional<double> capture_fps;
    if (const std::optional<std::string> text = arguments.value("fps")) {
        Result<double> rate = frame_rate_from_text(*text);
        if (!rate) return usage_error(bake_spec(), rate.error().message);
        capture_fps = *rate;
    }

    const std::string annotations_path = arguments.positionals[0];
    Result<RawAnnotations> annotations = annotations_read_file(annotations_path);
    if (!annotations) return input_error(annotations.error().message);

    ProgressDisplay progress(std::cout);
    bake::BakeOptions options;
    const std::optional<std::string> root = arguments.value("mocap-root");
    options.mocap_root = root ? std::filesystem::path(*root) : default_mocap_root();
    options.clusters = static_cast<int>(*clusters);
    options.jobs = static_cast<int>(*jobs);
    options.frame_time_s = 1.0 / static_cast<double>(*fps);
    options.capture_fps = capture_fps;
    options.keep_motion = arguments.has("exr") || arguments.value("exr").has_value();
    options.progress = [&](const bake::BakeProgress& step) { progress.update(step.stage, step.done, step.total); };
    std::cout << "baking " << annotations->clips.size() << " annotated clips from " << annotations_path << " on " << options.jobs
              << " threads\n";
    Result<bake::BakeResult> baked = bake::bake_database(*annotations, annotations_path, options);
    progress.finish();
    if (!baked) return input_error(baked.error().message);
    WarningGroups warnings;
    for (const bake::BakeWarning& warning : baked->warnings) warnings.add(warning.where, warning.what);
    warnings.print(std::cerr, arguments.has("verbose"));

    const MotionDatabaseView view = baked->database.view();
    if (Result<void> written = motion_database_write(*output, view); !written) return input_error(written.error().message);
    std::error_code error;
    const auto bytes = std::filesystem::file_size(*output, error);
    char summary[256];
    std::snprintf(summary, sizeof summary, "wrote %s: %zu clips, %zu poses, %zu clusters, %zu actors, %.1f MB in %.2f s\n",
                  output->c_str(), view.clips.size(), view.poses.size(), view.clusters.size(), view.actors.size(),
                  static_cast<double>(bytes) / 1e6, baked->seconds);
    std::cout << summary;

    if (const std::optional<std::string> exr_folder = arguments.value("exr")) {
        Result<bake::ExrExportSummary> exported = bake::exr_export(*exr_folder, *baked, options.jobs, options.progress);
        progress.finish();
        if (!exported) return input_error(exported.error().message);
        std::snprintf(summary, sizeof summary, "wrote %zu EXR files to %s in %.2f s\n", exported->files.size(), exr_folder->c_str(),
                      exported->seconds);
        std::cout << summary;
    }
    return k_exit_ok;
}

} // namespace kumite::cli
