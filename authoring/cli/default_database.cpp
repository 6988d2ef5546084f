#include "default_database.h"

#include "bake.h"
#include "capture_loading.h"

#include "kumite/formats/annotation_file.h"
#include "kumite/formats/database_image.h"
#include "kumite/formats/motion_database_file.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace kumite::cli {
namespace {

std::filesystem::path cache_folder() {
    if (const char* folder = std::getenv("KUMITE_CACHE_DIR"); folder && *folder) return folder;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "kumite";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "kumite";
    return std::filesystem::temp_directory_path() / "kumite-cache";
}

// FNV-1a, 64 bits: enough to tell one input set from another, not a security measure.
struct Fingerprint {
    std::uint64_t value = 1469598103934665603ull;
    void add(std::string_view bytes) {
        for (const char c : bytes) value = (value ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
        return text;
    }
};

std::string missing_captures_message(const std::filesystem::path& mocap_root, const std::string& why) {
    return "no database given (DB.kdb or $KUMITE_DB), and the reference one cannot be baked: " + why +
           ". Get the captures with scripts/fetch_mocap.sh (it links ../shared/mocap or downloads the public Bandai-Namco "
           "dataset into " + mocap_root.string() + "), or set KUMITE_MOCAP_ROOT to where they are";
}

} // namespace

Result<std::filesystem::path> default_database_path() {
    if (const char* given = std::getenv("KUMITE_DB"); given && *given) {
        std::error_code error;
        if (!std::filesystem::exists(given, error)) return make_error(ErrorCode::io, std::string("$KUMITE_DB: ") + given + " does not exist");
        return std::filesystem::path(given);
    }
    const std::filesystem::path annotations_path = locate_data_folder("KUMITE_ANNOTATIONS", "data/annotations/reference.json");
    const std::filesystem::path mocap_root = default_mocap_root();
    std::ifstream stream(annotations_path, std::ios::binary);
    if (!stream) return make_error(ErrorCode::io, missing_captures_message(mocap_root, "cannot read " + annotations_path.string()));
    std::ostringstream text;
    text << stream.rdbuf();
    Result<RawAnnotations> annotations = annotations_parse(text.str(), annotations_path.string()); // read once, hashed below
    if (!annotations) return annotations.error();

    // What the bake depends on: the annotations, each capture's path, size and time, the database format.
    Fingerprint fingerprint;
    fingerprint.add(text.str());
    fingerprint.add(std::to_string(k_database_format_version));
    std::set<std::string> sources;
    for (const RawAnnotatedClip& clip : annotations->clips) sources.insert(clip.source);
    for (const std::string& source : sources) {
        const std::filesystem::path path = resolve_capture_path(source, mocap_root);
        std::error_code error;
        const auto size = std::filesystem::file_size(path, error);
        if (error) return make_error(ErrorCode::io, missing_captures_message(mocap_root, "the capture " + source + " is missing"));
        const auto time = std::filesystem::last_write_time(path, error).time_since_epoch().count();
        fingerprint.add(path.string() + "|" + std::to_string(size) + "|" + std::to_string(time) + "\n");
    }
    const std::filesystem::path cached = cache_folder() / ("reference-" + fingerprint.hex() + ".kdb");
    std::error_code error;
    if (std::filesystem::exists(cached, error) && MotionDatabase::open(cached).has_value()) return cached;

    std::filesystem::create_directories(cached.parent_path(), error);
    if (error) return make_error(ErrorCode::io, cached.parent_path().string() + ": cannot create the cache folder (" + error.message() + ")");
    bake::BakeOptions options;
    options.mocap_root = mocap_root;
    Result<bake::BakeResult> baked = bake::bake_database(*annotations, annotations_path.string(), options);
    if (!baked) return baked.error();
    if (Result<void> written = motion_database_write(cached, baked->database.view()); !written) return written.error();
    // Earlier bakes of other inputs are stale now.
    for (const auto& entry : std::filesystem::directory_iterator(cached.parent_path(), error)) {
        const std::string name = entry.path().filename().string();
        if (entry.path() != cached && name.starts_with("reference-") && name.ends_with(".kdb")) std::filesystem::remove(entry.path(), error);
    }
    char line[512];
    std::snprintf(line, sizeof line, "kumite: baked %s into %s (%zu clips, %.2f s): no cached database for these annotations and captures\n",
                  annotations_path.c_str(), cached.c_str(), baked->database.view().clips.size(), baked->seconds);
    std::cerr << line;
    return cached;
}

Result<std::filesystem::path> database_path_from(const Arguments& arguments) {
    if (!arguments.positionals.empty()) return std::filesystem::path(arguments.positionals[0]);
    return default_database_path();
}

} // namespace kumite::cli
