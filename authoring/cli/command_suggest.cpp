// kumite suggest: punches and kicks proposed from captures alone (see core/strike_detection.h for the rule).

#include "capture_loading.h"
#include "commands.h"
#include "warning_groups.h"
#include "kumite/core/strike_detection.h"
#include "kumite/formats/annotation_file.h"

#include <cstdio>
#include <iomanip>
#include <map>
#include <set>
#include <iostream>

namespace kumite::cli {

const CommandSpec& suggest_spec() {
    static const CommandSpec spec{
        "suggest",
        "FILE.bvh... [--segment PART] [--verbose] [--json]",
        "Proposes the strikes in captures: punches (hand extension peaks in front of the chest after a fast\n"
        "move, or a fist swung and stopped with the elbow bent: hooks, uppercuts), kicks (a straight leg raised, its foot reaching out), knee strikes (a folded leg whose knee rises)\n"
        "and elbow strikes (an elbow driven up with the fist folded by the head), each with its hit frame and span. With --segment\n"
        "PART, reports the extension peaks of that body part instead (semantics 'reach'). --write-annotations\n"
        "turns every suggestion into a clip (mirrored too), with paths relative to --mocap-root when under it.\n"
        "Each strike also gets a proposed kind (straight/hook/uppercut, front/roundhouse/side) and height\n"
        "(low/middle/high). --compare ANNOTATIONS.json proposes kind and height for every labelled strike of an\n"
        "annotation file and prints how often they agree with its labels, with the confusion tables. With captures\n"
        "and --compare, it scores the detection instead: per folder, recall and precision against the file's\n"
        "strikes of those captures (same semantics and side, hits within 0.25 s), kind agreement, confusion tables.\n"
        "The captures' warnings come at the end, one line per kind with how many; --verbose lists every one.\n"
        "--thresholds NAME=V,... tries other detection thresholds (scripts/suggest_lopo.py chooses them per held-out\n"
        "performer).",
        0, 100000,
        {{"segment", "PART", "a body part (hand_l, foot_r, head, ...): report its extension peaks"},
         {"write-annotations", "OUT.json", "write every suggestion as a clip of an annotation file ready for bake"},
         {"compare", "ANNOTATIONS.json", "compare with the file's labels (alone), or score the detection on the captures given"},
         {"thresholds", "NAME=V,...", "try other detection thresholds (core/strike_thresholds.h; scripts/suggest_lopo.py chooses them)"},
         unit_flag(), strict_flag(), fps_flag(), mocap_root_flag(), body_map_flag(), verbose_flag(), json_flag()}};
    return spec;
}

namespace {

nlohmann::json strikes_json(const std::vector<StrikeSuggestion>& strikes) {
    nlohmann::json list = nlohmann::json::array();
    for (const StrikeSuggestion& strike : strikes) {
        list.push_back({{"semantics", strike_semantics_name(strike.semantics)},
                        {"segment", std::string(body_part_name(strike.segment))},
                        {"side", strike.side == Side::left ? "left" : strike.side == Side::right ? "right" : "none"},
                        {"hit_frame", strike.hit_frame},
                        {"first", strike.first_frame},
                        {"last", strike.last_frame},
                        {"confidence", strike.confidence},
                        {"kind", strike_kind_name(strike.labels.kind)},
                        {"height", strike_height_name(strike.labels.height)},
                        {"hit_height_m", strike.labels.hit_height_m},
                        {"approach_m", {{"along", strike.labels.approach_along_m}, {"sideways", strike.labels.approach_sideways_m},
                                        {"up", strike.labels.approach_up_m}}},
                        {"hips_to_line_deg", strike.labels.hips_to_line_deg}});
    }
    return list;
}

} // namespace

int run_compare(const std::string& annotations_path, const CaptureOptions& options, bool as_json); // below
int run_detection_compare(const std::vector<std::string>& paths, const std::string& annotations_path, const CaptureOptions& options,
                          const StrikeThresholds& thresholds, bool as_json); // suggest_detection.cpp

namespace {

// Everything suggest does after its flags: the captures' strikes, or the comparisons (--compare).
int suggest_from(const Arguments& arguments, const CaptureOptions& options) {
    StrikeThresholds thresholds;
    if (const std::optional<std::string> text = arguments.value("thresholds")) {
        Result<StrikeThresholds> parsed = strike_thresholds_parse(*text);
        if (!parsed) return usage_error(suggest_spec(), "--thresholds: " + parsed.error().message);
        thresholds = *parsed;
    }
    if (const std::optional<std::string> compare = arguments.value("compare")) {
        if (!arguments.positionals.empty()) return run_detection_compare(arguments.positionals, *compare, options, thresholds, arguments.has("json"));
        return run_compare(*compare, options, arguments.has("json"));
    }
    if (arguments.positionals.empty()) return usage_error(suggest_spec(), "give captures to look at, or --compare ANNOTATIONS.json");
    std::optional<BodyPart> segment;
    if (const std::optional<std::string> name = arguments.value("segment")) {
        segment = body_part_from_name(*name);
        if (!segment) return usage_error(suggest_spec(), "unknown body part '" + *name + "' (e.g. hand_l, foot_r, head)");
    }

    nlohmann::json files = nlohmann::json::array();
    RawAnnotations annotations;
    for (const std::string& path : arguments.positionals) {
        Result<TimedCapture> capture = load_timed_capture(path, options, "suggest (strike speeds)");
        if (!capture) return input_error(capture.error().message);
        const BvhFile* file = &capture->file;
        const std::vector<StrikeSuggestion> strikes = strikes_detect(file->clip, capture->anatomy, segment, thresholds);
        files.push_back({{"file", path}, {"strikes", strikes_json(strikes)}});
        const std::string source = source_relative_to_root(resolve_capture_path(path, options.mocap_root), options.mocap_root);
        if (!file->frame_rate_in_file) annotations.capture_fps[source] = 1.0 / file->clip.frame_time_s; // the bake needs it too
        for (const StrikeSuggestion& strike : strikes) annotations.clips.push_back(clip_from_suggestion(strike, source));
    }
    if (const std::optional<std::string> output = arguments.value("write-annotations")) {
        if (Result<void> valid = annotations.validate(*output); !valid) return input_error(valid.error().message);
        if (Result<void> written = annotations_write_file(*output, annotations); !written) return input_error(written.error().message);
    }

    if (arguments.has("json")) {
        print_json(files.size() == 1 ? nlohmann::json{{"strikes", files[0]["strikes"]}} : nlohmann::json{{"files", files}});
        return k_exit_ok;
    }
    for (const auto& file : files) {
        std::cout << file["file"].get<std::string>() << ": " << file["strikes"].size() << " strikes\n";
        for (const auto& strike : file["strikes"]) {
            std::cout << "  " << std::left << std::setw(6) << strike["semantics"].get<std::string>() << std::setw(8)
                      << strike["segment"].get<std::string>() << " hit " << std::setw(5) << strike["hit_frame"].get<int>()
                      << " frames " << strike["first"].get<int>() << "-" << strike["last"].get<int>() << "  confidence "
                      << std::fixed << std::setprecision(2) << strike["confidence"].get<double>() << "  "
                      << strike["kind"].get<std::string>() << " " << strike["height"].get<std::string>() << "\n";
        }
    }
    return k_exit_ok;
}

} // namespace

int run_suggest(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(suggest_spec(), argc, argv, arguments)) return *status;
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(suggest_spec(), options.error().message);
    WarningGroups warnings; // a folder of captures with one quirk: one line, not one per file
    options->warnings = &warnings;
    const int status = suggest_from(arguments, *options);
    warnings.print(std::cerr, arguments.has("verbose"));
    return status;
}

namespace {

// Agreement of proposed and annotated labels, with a confusion table per label (annotated -> proposed -> count).
struct LabelTally {
    int compared = 0;
    int agreed = 0;
    std::map<std::string, std::map<std::string, int>> confusion;
    void add(const std::string& annotated, const std::string& proposed) {
        ++compared;
        agreed += annotated == proposed;
        ++confusion[annotated][proposed];
    }
    nlohmann::json to_json() const {
        return {{"compared", compared}, {"agreed", agreed}, {"agreement", compared ? double(agreed) / compared : 0.0}, {"confusion", confusion}};
    }
};

void print_tally(const char* what, const LabelTally& tally) {
    std::printf("%s: %d of %d agree (%.0f%%)\n", what, tally.agreed, tally.compared, tally.compared ? 100.0 * tally.agreed / tally.compared : 0.0);
    std::set<std::string> proposed_names;
    for (const auto& [annotated, row] : tally.confusion) {
        for (const auto& [proposed, count] : row) proposed_names.insert(proposed);
    }
    std::printf("  %-14s", "labelled \\ proposed");
    for (const std::string& name : proposed_names) std::printf(" %10s", name.c_str());
    std::printf("\n");
    for (const auto& [annotated, row] : tally.confusion) {
        std::printf("  %-22s", annotated.c_str());
        for (const std::string& name : proposed_names) std::printf(" %10d", row.count(name) ? row.at(name) : 0);
        std::printf("\n");
    }
}

} // namespace

int run_compare(const std::string& annotations_path, const CaptureOptions& options, bool as_json) {
    Result<RawAnnotations> annotations = annotations_read_file(annotations_path);
    if (!annotations) return input_error(annotations.error().message);
    struct Loaded {
        BvhFile file;
        RestAnatomy anatomy;
    };
    std::map<std::string, Loaded> captures;
    LabelTally kinds, heights;
    nlohmann::json clips = nlohmann::json::array();
    for (const RawAnnotatedClip& clip : annotations->clips) {
        if (!clip.is_strike() || !clip.segment || !clip.hit_frame) continue;
        auto found = captures.find(clip.source);
        if (found == captures.end()) {
            CaptureOptions clip_options = options;
            if (const auto rate = annotations->capture_fps.find(clip.source); rate != annotations->capture_fps.end() && !options.read.frame_rate_hz) {
                clip_options.read.frame_rate_hz = rate->second;
            }
            Result<BvhFile> file = load_capture(clip.source, clip_options);
            if (!file) return input_error(annotations_path + ": clip " + clip.name + ": " + file.error().message);
            if (Result<void> timed = require_frame_rate(*file, clip.source, "suggest (strike speeds)"); !timed) return input_error(timed.error().message);
            Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
            if (!anatomy) return input_error(clip.source + ": " + anatomy.error().message);
            found = captures.emplace(clip.source, Loaded{std::move(*file), std::move(*anatomy)}).first;
        }
        const Loaded& capture = found->second;
        if (Result<void> fits = raw_clip_validate_frames(clip, capture.file.clip.frame_count()); !fits) return input_error(fits.error().message);
        const StrikeLabels proposed =
            strike_labels_propose(capture.file.clip, capture.anatomy, clip.semantics, *clip.segment, clip.first_frame, *clip.hit_frame);
        if (clip.kind != StrikeKind::none) kinds.add(clip.semantics + " " + strike_kind_name(clip.kind), clip.semantics + " " + strike_kind_name(proposed.kind));
        if (clip.height != StrikeHeight::none) heights.add(strike_height_name(clip.height), strike_height_name(proposed.height));
        clips.push_back({{"name", clip.name},
                         {"semantics", clip.semantics},
                         {"kind", strike_kind_name(clip.kind)},
                         {"height", strike_height_name(clip.height)},
                         {"proposed_kind", strike_kind_name(proposed.kind)},
                         {"proposed_height", strike_height_name(proposed.height)},
                         {"hit_height_m", proposed.hit_height_m},
                         {"hip_height_m", proposed.hip_height_m},
                         {"shoulder_height_m", proposed.shoulder_height_m},
                         {"approach_m", {{"along", proposed.approach_along_m}, {"sideways", proposed.approach_sideways_m}, {"up", proposed.approach_up_m}}},
                         {"hips_to_line_deg", proposed.hips_to_line_deg}});
    }
    if (as_json) {
        print_json({{"clips", clips}, {"kind", kinds.to_json()}, {"height", heights.to_json()}});
        return k_exit_ok;
    }
    for (const auto& clip : clips) {
        const bool differs = clip["kind"] != clip["proposed_kind"] || clip["height"] != clip["proposed_height"];
        std::printf("%c %-48s %-6s labelled %-10s %-6s proposed %-10s %-6s (hit %.2f m; hip %.2f, shoulder %.2f)\n", differs ? '*' : ' ',
                    clip["name"].get<std::string>().c_str(), clip["semantics"].get<std::string>().c_str(), clip["kind"].get<std::string>().c_str(),
                    clip["height"].get<std::string>().c_str(), clip["proposed_kind"].get<std::string>().c_str(),
                    clip["proposed_height"].get<std::string>().c_str(), clip["hit_height_m"].get<double>(), clip["hip_height_m"].get<double>(),
                    clip["shoulder_height_m"].get<double>());
    }
    print_tally("kind", kinds);
    print_tally("height", heights);
    return k_exit_ok;
}

} // namespace kumite::cli
