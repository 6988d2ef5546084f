#include "kumite/formats/annotation_file.h"
#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <set>

using namespace kumite;

namespace {
const char* const k_annotations = R"({
  "version": 1,
  "project_note": "kept",
  "clips": [
    {"name": "kick_r_060", "source": "bandai-namco-1/dataset-1_kick_normal_001.bvh", "first": 30, "last": 87,
     "semantics": "kick", "segment": "foot_r", "side": "right", "hit_frame": 60, "mirror": true, "reviewed_by": "ana"},
    {"name": "guard", "source": "bandai-namco-1/dataset-1_walk_normal_001.bvh", "first": 0, "last": 40, "semantics": "rest"}
  ]
})";

std::string error_of(const std::string& text) {
    Result<RawAnnotations> annotations = annotations_parse(text, "a.json");
    REQUIRE_FALSE(annotations.has_value());
    return annotations.error().message;
}
} // namespace

TEST_CASE("annotation_file: reads clips and keeps unknown keys through a round trip", "[formats]") {
    Result<RawAnnotations> annotations = annotations_parse(k_annotations, "a.json");
    REQUIRE(annotations.has_value());
    REQUIRE(annotations->clips.size() == 2);
    const RawAnnotatedClip& kick = annotations->clips[0];
    CHECK(kick.segment == BodyPart::foot_r);
    CHECK(kick.side == Side::right);
    CHECK(kick.hit_frame == 60);
    CHECK(kick.mirror);
    CHECK(kick.is_strike());
    CHECK_FALSE(annotations->clips[1].is_strike());

    const std::string written = annotations_write_string(*annotations);
    Result<RawAnnotations> again = annotations_parse(written, "b.json");
    REQUIRE(again.has_value());
    CHECK(annotations_write_string(*again) == written);
    const nlohmann::json document = nlohmann::json::parse(written);
    CHECK(document["project_note"] == "kept");
    CHECK(document["clips"][0]["reviewed_by"] == "ana");
    CHECK(document["version"] == k_annotation_format_version);
}

TEST_CASE("annotation_file: invalid content names the clip and the field", "[formats]") {
    auto with = [](const std::string& from, const std::string& to) {
        std::string text = k_annotations;
        text.replace(text.find(from), from.size(), to);
        return text;
    };
    CHECK_THAT(error_of(with("\"hit_frame\": 60", "\"hit_frame\": 99")),
               Catch::Contains("a.json: clip 0 (kick_r_060)") && Catch::Contains("outside the trim range"));
    CHECK_THAT(error_of(with("\"foot_r\"", "\"foot_x\"")), Catch::Contains("unknown body part \"foot_x\""));
    CHECK_THAT(error_of(with("\"segment\": \"foot_r\", ", "")), Catch::Contains("needs a \"segment\""));
    CHECK_THAT(error_of(with("\"first\": 30", "\"first\": 90")), Catch::Contains("\"first\" is after \"last\""));
    CHECK_THAT(error_of(with("\"name\": \"guard\"", "\"name\": \"kick_r_060\"")), Catch::Contains("clip 1") && Catch::Contains("earlier clip"));
    CHECK_THAT(error_of(with("\"first\": 30", "\"first\": -3")), Catch::Contains("\"first\" is out of range"));
    CHECK_THAT(error_of(with("\"side\": \"right\"", "\"side\": \"up\"")), Catch::Contains("\"side\" must be"));
    CHECK_THAT(error_of(with("\"version\": 1", "\"version\": 7")), Catch::Contains("version 7"));
    CHECK_THAT(error_of("{\"clips\": 3}"), Catch::Contains("\"clips\" array"));
    CHECK_THAT(error_of("not json"), Catch::Contains("not valid JSON"));
}

TEST_CASE("annotation_file: frames are checked against the capture", "[formats]") {
    Result<RawAnnotations> annotations = annotations_parse(k_annotations, "a.json");
    REQUIRE(annotations.has_value());
    CHECK(raw_clip_validate_frames(annotations->clips[0], 358).has_value());
    Result<void> short_capture = raw_clip_validate_frames(annotations->clips[0], 80);
    REQUIRE_FALSE(short_capture.has_value());
    CHECK_THAT(short_capture.error().message, Catch::Contains("kick_r_060") && Catch::Contains("past the end"));
}

TEST_CASE("annotation_file: files are written atomically and read back", "[formats]") {
    Result<RawAnnotations> annotations = annotations_parse(k_annotations, "a.json");
    REQUIRE(annotations.has_value());
    const std::filesystem::path path = kumite::test::make_temp_dir("annotations") / "clips.json";
    REQUIRE(annotations_write_file(path, *annotations).has_value());
    Result<RawAnnotations> read = annotations_read_file(path);
    REQUIRE(read.has_value());
    CHECK(read->clips.size() == 2);
    CHECK_FALSE(annotations_read_file(path.parent_path() / "missing.json").has_value());
}

TEST_CASE("annotation_file: the reference annotations fit their captures", "[formats][corpus]") {
    Result<RawAnnotations> annotations = annotations_read_file(kumite::test::source_dir() / "data/annotations/reference.json");
    REQUIRE(annotations.has_value());
    int strikes = 0;
    std::set<std::pair<std::string, Side>> kinds;
    std::set<std::string> motions;
    for (const RawAnnotatedClip& clip : annotations->clips) {
        motions.insert(clip.semantics);
        if (clip.is_strike()) {
            strikes += clip.mirror ? 2 : 1;
            kinds.insert({clip.semantics, clip.side});
            if (clip.mirror) kinds.insert({clip.semantics, clip.side == Side::left ? Side::right : Side::left});
        }
        const std::filesystem::path capture = kumite::test::mocap_root() / clip.source;
        if (!std::filesystem::exists(capture)) continue;
        Result<BvhFile> file = bvh_read_file(capture);
        REQUIRE(file.has_value());
        INFO(clip.name);
        CHECK(raw_clip_validate_frames(clip, file->clip.frame_count()).has_value());
    }
    CHECK(strikes >= 60);
    for (const char* semantics : {"punch", "kick"}) {
        CHECK(kinds.count({semantics, Side::left}) == 1);
        CHECK(kinds.count({semantics, Side::right}) == 1);
    }
    for (const char* motion : {"rest", "step_forward", "step_back", "step_left", "step_right"}) CHECK(motions.count(motion) == 1);
}

TEST_CASE("annotation_file: version 1 files read as unlabelled strikes, version 2 keeps kind and height", "[formats]") {
    Result<RawAnnotations> old = annotations_parse(k_annotations, "old.json");
    REQUIRE(old.has_value());
    CHECK(old->clips[0].kind == StrikeKind::none);
    CHECK(old->clips[0].height == StrikeHeight::none);
    old->clips[0].kind = StrikeKind::roundhouse;
    old->clips[0].height = StrikeHeight::high;
    const std::string written = annotations_write_string(*old);
    const nlohmann::json document = nlohmann::json::parse(written);
    CHECK(document["version"] == 2);
    CHECK(document["clips"][0]["kind"] == "roundhouse");
    CHECK(document["clips"][0]["height"] == "high");
    CHECK_FALSE(document["clips"][1].contains("kind")); // a rest has none
    Result<RawAnnotations> again = annotations_parse(written, "new.json");
    REQUIRE(again.has_value());
    CHECK(again->clips[0].kind == StrikeKind::roundhouse);
    CHECK(again->clips[0].height == StrikeHeight::high);
}

TEST_CASE("annotation_file: a kind of another semantics, an unknown label, or labels on a rest are refused", "[formats]") {
    auto with = [](const std::string& from, const std::string& to) {
        std::string text = k_annotations;
        text.replace(text.find(from), from.size(), to);
        return text;
    };
    CHECK_THAT(error_of(with("\"mirror\": true,", "\"mirror\": true, \"kind\": \"hook\",")),
               Catch::Contains("clip 0 (kick_r_060)") && Catch::Contains("a kick cannot be of kind \"hook\""));
    CHECK_THAT(error_of(with("\"mirror\": true,", "\"mirror\": true, \"kind\": \"haymaker\",")), Catch::Contains("unknown \"kind\" \"haymaker\""));
    CHECK_THAT(error_of(with("\"mirror\": true,", "\"mirror\": true, \"height\": \"knee\",")), Catch::Contains("unknown \"height\" \"knee\""));
    CHECK_THAT(error_of(with("\"mirror\": true,", "\"mirror\": true, \"height\": 3,")), Catch::Contains("\"height\" must be a string"));
    CHECK_THAT(error_of(with("\"semantics\": \"rest\"", "\"semantics\": \"rest\", \"height\": \"low\"")),
               Catch::Contains("clip 1 (guard)") && Catch::Contains("not a strike"));
    CHECK_THAT(error_of(with("\"version\": 1", "\"version\": 3")), Catch::Contains("version 3"));
}
