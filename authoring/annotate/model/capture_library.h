#pragma once
// The captures an annotation session has opened, each read once: the BVH with its body map (sidecar override
// included, as every tool reads it), its rest anatomy when the body map allows one, and the strikes
// `kumite suggest` would propose. Clips name a capture by `source`: its path relative to the mocap root when it
// lies under it (what `kumite bake --mocap-root` resolves), else the path as given.

#include "kumite/core/rest_anatomy.h"
#include "kumite/core/strike_detection.h"
#include "kumite/formats/annotation_file.h"
#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kumite::annotate {

struct LoadedCapture {
    std::filesystem::path path; // the file read
    std::string source;         // as clips name it
    BvhFile file;               // metres
    std::optional<RestAnatomy> anatomy;   // none when the body map lacks parts trajectories need
    std::string anatomy_error;            // why there is no anatomy
    std::vector<StrikeSuggestion> suggestions; // strikes_detect, empty without anatomy
};

// $KUMITE_MOCAP_ROOT, else data/mocap in the working folder, else the repository's found from the executable
// (build-x/bin/kumite-annotate -> data/mocap), else "data/mocap".
std::filesystem::path default_mocap_root();

// source_relative_to_root and clip_from_suggestion (kumite/formats/annotation_file.h) make a capture's clips.

// The hit frame to propose for a clip of `capture` trimmed to first..last with this hit segment: the hit of a
// punch/kick suggestion of that segment inside the range, else the strongest extension peak of the segment
// (strikes_detect's "reach") inside it; none without anatomy or peak. The animator confirms it.
std::optional<int> hit_frame_suggest(const LoadedCapture& capture, BodyPart segment, int first_frame, int last_frame);

class CaptureLibrary {
public:
    explicit CaptureLibrary(std::filesystem::path mocap_root) : m_mocap_root(std::move(mocap_root)) {}

    const std::filesystem::path& mocap_root() const { return m_mocap_root; }
    // A clip's source as a path to read: as given when it exists or is absolute, else under the mocap root.
    std::filesystem::path resolve(const std::string& source) const;

    // Reads the capture once (cached by source). Errors name the file and, for BVH syntax, the line. `fps` is
    // the rate of a capture whose file gives none (the annotation file's "captures"); without one such a capture
    // loads with no rate (a warning, no suggestions).
    Result<const LoadedCapture*> load(const std::filesystem::path& path_or_source, std::optional<double> fps = std::nullopt);
    // Reads a loaded capture again at another rate (none: the file's own); the LoadedCapture stays at its address.
    Result<const LoadedCapture*> reload(const std::string& source, std::optional<double> fps);
    const LoadedCapture* find(const std::string& source) const;
    const std::vector<std::unique_ptr<LoadedCapture>>& captures() const { return m_captures; }
    void clear() { m_captures.clear(); }

private:
    Result<std::unique_ptr<LoadedCapture>> read(const std::filesystem::path& path, const std::string& source, std::optional<double> fps) const;

    std::filesystem::path m_mocap_root;
    std::vector<std::unique_ptr<LoadedCapture>> m_captures; // in opening order
};

} // namespace kumite::annotate
