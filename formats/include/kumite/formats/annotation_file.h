#pragma once
// Annotation files: the animator's editable description of which parts of which captures become database clips.
// JSON, documented in formats/README.md. These are the raw, mutable structs the authoring side edits; the bake
// turns them into immutable runtime data. Unknown keys are kept through a read/write round trip.

#include "kumite/core/body_map.h"
#include "kumite/core/result.h"
#include "kumite/core/strike_detection.h"
#include "kumite/core/strike_labels.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kumite {

// Version 2 added a strike's "kind" and "height" (strike_labels.h); version 1 files read as unlabelled.
inline constexpr int k_annotation_format_version = 2;

struct RawAnnotatedClip {
    std::string name;                 // unique within the file
    std::string source;               // capture path, relative to the mocap root when under it
    int first_frame = 0;              // trim range in the capture, inclusive
    int last_frame = 0;
    std::string semantics;            // punch, kick, reach, block, ...; not strikes: rest, step_forward, step_back, step_left, step_right, hit_reaction
    std::optional<BodyPart> segment;  // the hit segment (strikes)
    Side side = Side::none;
    std::optional<int> hit_frame;     // in capture frames, inside the trim range (strikes)
    bool mirror = false;              // also use the clip mirrored left <-> right
    StrikeKind kind = StrikeKind::none;       // strikes: straight, hook, ... (none: unlabelled)
    StrikeHeight height = StrikeHeight::none; // strikes: low, middle, high (none: unlabelled)
    std::string extra_json = "{}";    // keys this version does not know, kept as a JSON object

    bool is_strike() const; // not rest and not a step
};

struct RawAnnotations {
    int version = k_annotation_format_version;
    std::vector<RawAnnotatedClip> clips;
    // Frame rates of captures whose files give none (`Frame Time: 0`), by clip `source`: file key
    // "captures": {"<source>": {"fps": 100}}. Set by the animator in the window; the bake reads it.
    std::map<std::string, double> capture_fps;
    std::string extra_json = "{}"; // unknown top-level keys

    // Content checks that need no capture: names unique, ranges ordered, strikes with segment and hit frame
    // inside the range, a kind that belongs to the semantics (no hook kick), labels only on strikes. The error names the source, the clip and the field.
    Result<void> validate(std::string_view source_name = "annotations") const;
};

// Checks a clip against the capture it cuts from.
Result<void> raw_clip_validate_frames(const RawAnnotatedClip& clip, int capture_frame_count);

Result<RawAnnotations> annotations_parse(std::string_view text, std::string_view source_name);
Result<RawAnnotations> annotations_read_file(const std::filesystem::path& path);
std::string annotations_write_string(const RawAnnotations& annotations);
Result<void> annotations_write_file(const std::filesystem::path& path, const RawAnnotations& annotations); // atomic

// What a clip's `source` holds for a capture: `path` relative to the mocap root when it lies under it (symlinks
// resolved on both), else absolute; '/' separators.
std::string source_relative_to_root(const std::filesystem::path& path, const std::filesystem::path& root);

// A detected strike as a clip of `source`: named <capture stem>_<segment>_<hit frame> and mirrored (the captures
// hold one side of most strikes; the mirror gives the other). `kumite suggest --write-annotations` and the
// annotation window's Accept both make clips this way.
RawAnnotatedClip clip_from_suggestion(const StrikeSuggestion& strike, const std::string& source);

} // namespace kumite
