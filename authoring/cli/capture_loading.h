#pragma once
// What every capture-reading subcommand shares: the --unit / --mocap-root / --body-map flags, locating a
// capture, reading it with its body map override, and printing JSON.

#include "arguments.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/character_catalog.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace kumite::cli {

class WarningGroups;

struct CaptureOptions {
    BvhReadOptions read;
    std::filesystem::path mocap_root;
    std::optional<std::filesystem::path> body_map_file;
    // Where the captures' warnings go when a command reads many (printed grouped at its end); null: each capture's
    // warnings straight to stderr.
    WarningGroups* warnings = nullptr;
};

// Reads the shared flags; a bad --unit is a usage error.
Result<CaptureOptions> capture_options_from(const Arguments& arguments);

// A --fps value: a finite rate in [0.001, 100000].
Result<double> frame_rate_from_text(const std::string& text);

// Refuses a capture without a frame rate for work that needs time (`what_needs_it`: "suggest"), saying how to
// give one.
Result<void> require_frame_rate(const BvhFile& file, const std::filesystem::path& path, std::string_view what_needs_it);

// `path` as given when it exists, else under the mocap root when relative.
std::filesystem::path resolve_capture_path(const std::filesystem::path& path, const std::filesystem::path& mocap_root);

// Reads the capture and applies --body-map, or the sidecar FILE.bodymap.json when there is one.
// The file's warnings (what it tolerated) go to options.warnings, else to stderr, one "warning: file:line: ..."
// line each.
Result<BvhFile> load_capture(const std::filesystem::path& path, const CaptureOptions& options);

// A capture that work over time can use: loaded (load_capture), with a frame rate (require_frame_rate, for
// `what_needs_it`) and its rest anatomy. Errors name the file.
struct TimedCapture {
    BvhFile file;
    RestAnatomy anatomy;
};
Result<TimedCapture> load_timed_capture(const std::filesystem::path& path, const CaptureOptions& options, std::string_view what_needs_it);

// $KUMITE_MOCAP_ROOT, else data/mocap (see locate_data_folder).
std::filesystem::path default_mocap_root();

nlohmann::json json_vec3(const Eigen::Vector3d& v);

// Prints exactly one JSON document and a newline on stdout; invalid UTF-8 in names is replaced, not thrown.
void print_json(const nlohmann::json& document);

} // namespace kumite::cli
