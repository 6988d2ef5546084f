#include "kumite/formats/annotation_file.h"

#include "kumite/formats/atomic_file.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>

namespace kumite {
namespace {

using nlohmann::json;

const std::set<std::string> k_non_strikes = {"rest", "step_forward", "step_back", "step_left", "step_right", "hit_reaction"};
const std::set<std::string> k_clip_keys = {"name", "source", "first", "last", "semantics", "segment", "side", "hit_frame", "mirror", "kind", "height"};

std::string side_name(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "none"; }

Error clip_error(std::string_view source, size_t index, const std::string& clip_name, const std::string& what) {
    return make_error(ErrorCode::invalid, std::string(source) + ": clip " + std::to_string(index) +
                                              (clip_name.empty() ? "" : " (" + clip_name + ")") + ": " + what);
}

Result<RawAnnotatedClip> clip_from_json(const json& item, size_t index, std::string_view source) {
    RawAnnotatedClip clip;
    if (!item.is_object()) return clip_error(source, index, "", "expected an object");
    auto string_field = [&](const char* key, std::string& out, bool required) -> std::optional<Error> {
        if (!item.contains(key)) return required ? std::optional<Error>(clip_error(source, index, clip.name, std::string("missing \"") + key + "\"")) : std::nullopt;
        if (!item[key].is_string()) return clip_error(source, index, clip.name, std::string("\"") + key + "\" must be a string");
        out = item[key].get<std::string>();
        return std::nullopt;
    };
    auto int_field = [&](const char* key, int& out) -> std::optional<Error> {
        if (!item.contains(key)) return clip_error(source, index, clip.name, std::string("missing \"") + key + "\"");
        if (!item[key].is_number_integer()) return clip_error(source, index, clip.name, std::string("\"") + key + "\" must be an integer");
        const auto value = item[key].get<long long>();
        if (value < 0 || value > 100000000) return clip_error(source, index, clip.name, std::string("\"") + key + "\" is out of range");
        out = static_cast<int>(value);
        return std::nullopt;
    };
    if (auto error = string_field("name", clip.name, true)) return *error;
    if (auto error = string_field("source", clip.source, true)) return *error;
    if (auto error = string_field("semantics", clip.semantics, true)) return *error;
    if (auto error = int_field("first", clip.first_frame)) return *error;
    if (auto error = int_field("last", clip.last_frame)) return *error;
    if (item.contains("segment") && !item["segment"].is_null()) {
        std::string name;
        if (auto error = string_field("segment", name, true)) return *error;
        clip.segment = body_part_from_name(name);
        if (!clip.segment) return clip_error(source, index, clip.name, "unknown body part \"" + name + "\" in \"segment\"");
    }
    if (item.contains("side")) {
        std::string name;
        if (auto error = string_field("side", name, true)) return *error;
        if (name == "left") clip.side = Side::left;
        else if (name == "right") clip.side = Side::right;
        else if (name == "none") clip.side = Side::none;
        else return clip_error(source, index, clip.name, "\"side\" must be left, right or none, not \"" + name + "\"");
    }
    if (item.contains("hit_frame") && !item["hit_frame"].is_null()) {
        int hit = 0;
        if (auto error = int_field("hit_frame", hit)) return *error;
        clip.hit_frame = hit;
    }
    if (item.contains("mirror")) {
        if (!item["mirror"].is_boolean()) return clip_error(source, index, clip.name, "\"mirror\" must be true or false");
        clip.mirror = item["mirror"].get<bool>();
    }
    if (item.contains("kind") && !item["kind"].is_null()) {
        std::string name;
        if (auto error = string_field("kind", name, true)) return *error;
        const std::optional<StrikeKind> kind = strike_kind_from_name(name);
        if (!kind) return clip_error(source, index, clip.name, "unknown \"kind\" \"" + name + "\" (straight, hook, uppercut, front, roundhouse, side, other, none)");
        clip.kind = *kind;
    }
    if (item.contains("height") && !item["height"].is_null()) {
        std::string name;
        if (auto error = string_field("height", name, true)) return *error;
        const std::optional<StrikeHeight> height = strike_height_from_name(name);
        if (!height) return clip_error(source, index, clip.name, "unknown \"height\" \"" + name + "\" (low, middle, high, none)");
        clip.height = *height;
    }
    json extra = json::object();
    for (const auto& [key, value] : item.items()) {
        if (!k_clip_keys.count(key)) extra[key] = value;
    }
    clip.extra_json = extra.dump();
    return clip;
}

// "captures": {"<source>": {"fps": N, ...}}: takes the rates out (into `rates`) and leaves any other keys.
Result<void> capture_rates_from_json(json& captures, const std::string& source, std::map<std::string, double>& rates) {
    if (!captures.is_object()) return make_error(ErrorCode::invalid, source + ": \"captures\" must be an object of capture paths");
    for (auto& [capture, entry] : captures.items()) {
        const std::string where = source + ": captures: \"" + capture + "\": ";
        if (!entry.is_object()) return make_error(ErrorCode::invalid, where + "expected an object such as {\"fps\": 100}");
        if (!entry.contains("fps")) continue;
        if (!entry["fps"].is_number() || !(entry["fps"].get<double>() >= 0.001 && entry["fps"].get<double>() <= 100000.0)) {
            return make_error(ErrorCode::invalid, where + "\"fps\" must be a frame rate from 0.001 to 100000");
        }
        rates[capture] = entry["fps"].get<double>();
        entry.erase("fps");
    }
    for (auto it = captures.begin(); it != captures.end();) {
        it = it->empty() ? captures.erase(it) : std::next(it);
    }
    return {};
}

} // namespace

bool RawAnnotatedClip::is_strike() const { return !k_non_strikes.count(semantics); }

Result<void> RawAnnotations::validate(std::string_view source_name) const {
    std::set<std::string> names;
    for (size_t index = 0; index < clips.size(); ++index) {
        const RawAnnotatedClip& clip = clips[index];
        auto fail = [&](const std::string& what) { return clip_error(source_name, index, clip.name, what); };
        if (clip.name.empty()) return fail("\"name\" is empty");
        if (!names.insert(clip.name).second) return fail("\"name\" is used by an earlier clip too");
        if (clip.source.empty()) return fail("\"source\" is empty");
        if (clip.semantics.empty() || clip.semantics.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") != std::string::npos) {
            return fail("\"semantics\" must be a lower-case word such as punch, kick or rest");
        }
        if (clip.first_frame > clip.last_frame) return fail("\"first\" is after \"last\"");
        if (clip.is_strike()) {
            if (!clip.segment) return fail("a " + clip.semantics + " needs a \"segment\" (the hit body part)");
            if (!clip.hit_frame) return fail("a " + clip.semantics + " needs a \"hit_frame\"");
        }
        if (!clip.is_strike() && (clip.kind != StrikeKind::none || clip.height != StrikeHeight::none)) {
            return fail("a " + clip.semantics + " is not a strike: it has no \"kind\" or \"height\"");
        }
        if (!strike_kind_fits(clip.semantics, clip.kind)) {
            return fail(std::string("a ") + clip.semantics + " cannot be of kind \"" + strike_kind_name(clip.kind) + "\"");
        }
        if (clip.hit_frame && (*clip.hit_frame < clip.first_frame || *clip.hit_frame > clip.last_frame)) {
            return fail("\"hit_frame\" " + std::to_string(*clip.hit_frame) + " is outside the trim range " +
                        std::to_string(clip.first_frame) + "-" + std::to_string(clip.last_frame));
        }
    }
    return {};
}

Result<void> raw_clip_validate_frames(const RawAnnotatedClip& clip, int capture_frame_count) {
    if (clip.last_frame >= capture_frame_count) {
        return make_error(ErrorCode::invalid, "clip " + clip.name + ": \"last\" " + std::to_string(clip.last_frame) + " is past the end of " +
                                                  clip.source + " (" + std::to_string(capture_frame_count) + " frames)");
    }
    return {};
}

Result<RawAnnotations> annotations_parse(std::string_view text, std::string_view source_name) {
    const std::string source(source_name);
    const json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded()) return make_error(ErrorCode::parse, source + ": not valid JSON");
    if (!document.is_object()) return make_error(ErrorCode::invalid, source + ": expected a JSON object with \"clips\"");
    RawAnnotations annotations;
    if (document.contains("version")) {
        if (!document["version"].is_number_integer()) return make_error(ErrorCode::invalid, source + ": \"version\" must be an integer");
        annotations.version = document["version"].get<int>();
        if (annotations.version > k_annotation_format_version || annotations.version < 1) {
            return make_error(ErrorCode::unsupported, source + ": annotation format version " + std::to_string(annotations.version) +
                                                          " is not one this kumite reads (1 to " + std::to_string(k_annotation_format_version) + ")");
        }
    }
    if (!document.contains("clips") || !document["clips"].is_array()) {
        return make_error(ErrorCode::invalid, source + ": expected a \"clips\" array");
    }
    size_t index = 0;
    for (const json& item : document["clips"]) {
        Result<RawAnnotatedClip> clip = clip_from_json(item, index++, source);
        if (!clip) return clip.error();
        annotations.clips.push_back(std::move(*clip));
    }
    json extra = json::object();
    for (const auto& [key, value] : document.items()) {
        if (key != "version" && key != "clips" && key != "format") extra[key] = value;
    }
    if (extra.contains("captures")) {
        if (Result<void> read = capture_rates_from_json(extra["captures"], source, annotations.capture_fps); !read) return read.error();
    }
    annotations.extra_json = extra.dump();
    annotations.version = k_annotation_format_version; // read older versions, write the current one
    if (Result<void> valid = annotations.validate(source); !valid) return valid.error();
    return annotations;
}

Result<RawAnnotations> annotations_read_file(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return make_error(ErrorCode::io, path.string() + ": cannot open annotation file");
    std::ostringstream text;
    text << stream.rdbuf();
    return annotations_parse(text.str(), path.string());
}

std::string annotations_write_string(const RawAnnotations& annotations) {
    json document = json::parse(annotations.extra_json, nullptr, false);
    if (!document.is_object()) document = json::object();
    document["format"] = "kumite-annotations";
    document["version"] = k_annotation_format_version;
    for (const auto& [capture, fps] : annotations.capture_fps) document["captures"][capture]["fps"] = fps;
    if (document.contains("captures") && document["captures"].empty()) document.erase("captures");
    json clips = json::array();
    for (const RawAnnotatedClip& clip : annotations.clips) {
        json item = json::parse(clip.extra_json, nullptr, false);
        if (!item.is_object()) item = json::object();
        item["name"] = clip.name;
        item["source"] = clip.source;
        item["first"] = clip.first_frame;
        item["last"] = clip.last_frame;
        item["semantics"] = clip.semantics;
        if (clip.segment) item["segment"] = std::string(body_part_name(*clip.segment));
        item["side"] = side_name(clip.side);
        if (clip.hit_frame) item["hit_frame"] = *clip.hit_frame;
        item["mirror"] = clip.mirror;
        if (clip.kind != StrikeKind::none) item["kind"] = strike_kind_name(clip.kind);
        if (clip.height != StrikeHeight::none) item["height"] = strike_height_name(clip.height);
        clips.push_back(std::move(item));
    }
    document["clips"] = std::move(clips);
    return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

Result<void> annotations_write_file(const std::filesystem::path& path, const RawAnnotations& annotations) {
    return write_file_atomically(path, annotations_write_string(annotations));
}

std::string source_relative_to_root(const std::filesystem::path& path, const std::filesystem::path& root) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::weakly_canonical(path, error);
    if (error) return path.generic_string();
    const std::filesystem::path absolute_root = std::filesystem::weakly_canonical(root, error);
    if (error) return path.generic_string();
    const std::filesystem::path relative = absolute.lexically_relative(absolute_root);
    if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    return absolute.generic_string();
}

RawAnnotatedClip clip_from_suggestion(const StrikeSuggestion& strike, const std::string& source) {
    RawAnnotatedClip clip;
    clip.source = source;
    clip.name = std::filesystem::path(source).stem().string() + "_" + std::string(body_part_name(strike.segment)) + "_" +
                std::to_string(strike.hit_frame);
    clip.first_frame = strike.first_frame;
    clip.last_frame = strike.last_frame;
    clip.semantics = strike_semantics_name(strike.semantics);
    clip.segment = strike.segment;
    clip.side = strike.side;
    clip.hit_frame = strike.hit_frame;
    clip.mirror = true;
    clip.kind = strike.labels.kind;
    clip.height = strike.labels.height;
    return clip;
}

} // namespace kumite
