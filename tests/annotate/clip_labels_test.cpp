// A strike clip's kind and height in the document, without a window: each edit one undo step that undo and redo
// restore exactly, a change of semantics that drops a kind it no longer allows in the same step, the kinds each
// semantics offers, the list's text, saves that write "kind" and "height", and suggestions that carry them.

#include "annotation_document.h"
#include "clip_labels.h"
#include "qt_application.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace kumite;
using namespace kumite::annotate;

namespace {

const std::string k_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

RawAnnotatedClip strike_clip(const std::string& name, const std::string& semantics, BodyPart segment) {
    RawAnnotatedClip clip;
    clip.name = name;
    clip.source = k_kick_capture;
    clip.first_frame = 30;
    clip.last_frame = 87;
    clip.semantics = semantics;
    clip.segment = segment;
    clip.side = Side::right;
    clip.hit_frame = 60;
    return clip;
}

} // namespace

TEST_CASE("clip labels: kind and height edits are one undo step each, undo restores and redo reapplies", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(strike_clip("kick", "kick", BodyPart::foot_r));
    const std::filesystem::path saved = test::make_temp_dir("annotate-labels-undo") / "kick.json";
    REQUIRE(document.save_as(QString::fromStdString(saved.string())));
    const int steps_before = document.undo_stack()->count();
    RawAnnotatedClip clip = document.clip(0);
    clip.kind = StrikeKind::roundhouse;
    document.edit_clip(0, clip, ClipField::kind);
    CHECK(document.is_dirty());
    CHECK(document.undo_stack()->undoText() == "Set Strike Kind");
    clip.height = StrikeHeight::high;
    document.edit_clip(0, clip, ClipField::height);
    CHECK(document.undo_stack()->undoText() == "Set Strike Height");
    CHECK(document.undo_stack()->count() == steps_before + 2);
    CHECK(document.clip(0).kind == StrikeKind::roundhouse);
    CHECK(document.clip(0).height == StrikeHeight::high);

    document.undo_stack()->undo();
    CHECK(document.clip(0).kind == StrikeKind::roundhouse);
    CHECK(document.clip(0).height == StrikeHeight::none);
    document.undo_stack()->undo();
    CHECK(document.clip(0).kind == StrikeKind::none);
    CHECK_FALSE(document.is_dirty()); // back at the saved state
    document.undo_stack()->redo();
    CHECK(document.clip(0).kind == StrikeKind::roundhouse);
    CHECK(document.clip(0).height == StrikeHeight::none);
    document.undo_stack()->redo();
    CHECK(document.clip(0).height == StrikeHeight::high);
    CHECK(document.is_dirty());

    // The same value again is no edit: no step to undo.
    document.edit_clip(0, document.clip(0), ClipField::kind);
    CHECK(document.undo_stack()->count() == steps_before + 2);
}

TEST_CASE("clip labels: save writes kind and height into the JSON and reopening reads them", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-labels-save");
    const QString path = QString::fromStdString((folder / "labelled.json").string());
    AnnotationDocument document(test::mocap_root());
    document.add_clip(strike_clip("hook", "punch", BodyPart::hand_r));
    document.add_clip(strike_clip("unlabelled", "punch", BodyPart::hand_r));
    RawAnnotatedClip clip = document.clip(0);
    clip.kind = StrikeKind::hook;
    document.edit_clip(0, clip, ClipField::kind);
    clip.height = StrikeHeight::high;
    document.edit_clip(0, clip, ClipField::height);
    REQUIRE(document.save_as(path));
    CHECK_FALSE(document.is_dirty());

    const std::string written = test::read_text(path.toStdString());
    CHECK(written == annotations_write_string(document.annotations()));
    CHECK_THAT(written, Catch::Contains("\"kind\": \"hook\""));
    CHECK_THAT(written, Catch::Contains("\"height\": \"high\""));
    CHECK_THAT(written, Catch::Contains("\"version\": 2"));

    AnnotationDocument reopened(test::mocap_root());
    REQUIRE(reopened.open_annotations(path));
    REQUIRE(reopened.clip_count() == 2);
    CHECK(reopened.clip(0).kind == StrikeKind::hook);
    CHECK(reopened.clip(0).height == StrikeHeight::high);
    CHECK(reopened.clip(1).kind == StrikeKind::none);
    CHECK(reopened.clip(1).height == StrikeHeight::none);
    CHECK(clips_equal(reopened.clip(0), document.clip(0)));
    CHECK(reopened.text() == written);
}

TEST_CASE("clip labels: punch to kick drops a hook in the same undo step, the height stays", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    RawAnnotatedClip punch = strike_clip("punch", "punch", BodyPart::hand_r);
    punch.kind = StrikeKind::hook;
    punch.height = StrikeHeight::high;
    document.add_clip(punch);
    const int steps_before = document.undo_stack()->count();

    document.edit_clip(0, clip_with_semantics(document.clip(0), "kick"), ClipField::semantics);
    CHECK(document.undo_stack()->count() == steps_before + 1);
    CHECK(document.undo_stack()->undoText() == "Set Semantics");
    CHECK(document.clip(0).semantics == "kick");
    CHECK(document.clip(0).kind == StrikeKind::none);
    CHECK(document.clip(0).height == StrikeHeight::high);
    CHECK(document.annotations().validate());

    document.undo_stack()->undo();
    CHECK(document.clip(0).semantics == "punch");
    CHECK(document.clip(0).kind == StrikeKind::hook);
    document.undo_stack()->redo();
    CHECK(document.clip(0).kind == StrikeKind::none);
}

TEST_CASE("clip labels: a kind that still fits survives a change of semantics, a non-strike loses both labels", "[annotate]") {
    RawAnnotatedClip clip = strike_clip("strike", "punch", BodyPart::hand_r);
    clip.kind = StrikeKind::other;
    clip.height = StrikeHeight::middle;
    const RawAnnotatedClip kick = clip_with_semantics(clip, "kick");
    CHECK(kick.kind == StrikeKind::other);
    CHECK(kick.height == StrikeHeight::middle);
    const RawAnnotatedClip rest = clip_with_semantics(clip, "rest");
    CHECK(rest.kind == StrikeKind::none);
    CHECK(rest.height == StrikeHeight::none);
    RawAnnotations file;
    file.clips.push_back(rest);
    CHECK(file.validate());
    // A clip that becomes a strike gets a hit frame to be valid.
    RawAnnotatedClip idle = rest;
    idle.hit_frame.reset();
    CHECK(clip_with_semantics(idle, "kick").hit_frame == (idle.first_frame + idle.last_frame) / 2);
}

TEST_CASE("clip labels: each semantics offers none and only the kinds that fit it", "[annotate]") {
    using K = StrikeKind;
    CHECK(strike_kinds_offered("punch") == std::vector<K>{K::none, K::straight, K::hook, K::uppercut, K::other});
    CHECK(strike_kinds_offered("kick") == std::vector<K>{K::none, K::front, K::roundhouse, K::side, K::other});
    CHECK(strike_kinds_offered("reach") == std::vector<K>{K::none, K::other});
    CHECK(strike_kinds_offered("slash") == std::vector<K>{K::none, K::other});
    for (const char* semantics : {"punch", "kick", "reach"}) {
        for (K kind : strike_kinds_offered(semantics)) CHECK(strike_kind_fits(semantics, kind));
    }
}

TEST_CASE("clip labels: the list text reads semantics, side, kind and height", "[annotate]") {
    RawAnnotatedClip clip = strike_clip("punch", "punch", BodyPart::hand_r);
    CHECK(clip_labels_text(clip) == "punch right");
    clip.kind = StrikeKind::hook;
    clip.height = StrikeHeight::high;
    CHECK(clip_labels_text(clip) == "punch right hook high");
    clip.side = Side::none;
    clip.kind = StrikeKind::none;
    CHECK(clip_labels_text(clip) == "punch high");
    CHECK(strike_labels_text(StrikeKind::front, StrikeHeight::none) == "front");
}

TEST_CASE("clip labels: an accepted suggestion carries its proposed kind and height", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    const LoadedCapture* capture = document.current_capture();
    REQUIRE(capture);
    REQUIRE_FALSE(capture->suggestions.empty());
    for (const StrikeSuggestion& strike : capture->suggestions) {
        document.add_suggestion(strike, capture->source);
        const RawAnnotatedClip& clip = document.clip(document.clip_count() - 1);
        INFO(clip.name << ": " << clip_labels_text(clip).toStdString());
        CHECK(clip.kind == strike.labels.kind);
        CHECK(clip.height == strike.labels.height);
        CHECK(clip.kind != StrikeKind::none); // punches and kicks are always given a kind
        CHECK(clip.height != StrikeHeight::none);
        CHECK(document.clip_messages(document.clip_count() - 1).empty());
    }
}
