// The annotation document without a window: undo commands, merging of drags, the dirty flag, saves that write
// exactly what `kumite bake` reads, and bad files reported instead of crashing.

#include "annotation_document.h"
#include "qt_application.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <QFile>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace kumite;
using namespace kumite::annotate;

namespace {

const std::string k_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

RawAnnotatedClip kick_clip(const std::string& name) {
    RawAnnotatedClip clip;
    clip.name = name;
    clip.source = k_kick_capture;
    clip.first_frame = 30;
    clip.last_frame = 87;
    clip.semantics = "kick";
    clip.segment = BodyPart::foot_r;
    clip.side = Side::right;
    clip.hit_frame = 60;
    clip.mirror = true;
    return clip;
}

} // namespace

TEST_CASE("annotation document: adding a clip is one undo step, undo and redo restore it exactly", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    CHECK_FALSE(document.is_dirty());
    document.add_clip(kick_clip("kick_a"));
    REQUIRE(document.clip_count() == 1);
    CHECK(document.is_dirty());
    CHECK(document.selected_clip() == 0);
    CHECK(document.undo_stack()->undoText() == "Add Clip");
    document.undo_stack()->undo();
    CHECK(document.clip_count() == 0);
    CHECK_FALSE(document.is_dirty());
    document.undo_stack()->redo();
    REQUIRE(document.clip_count() == 1);
    CHECK(clips_equal(document.clip(0), kick_clip("kick_a")));
}

TEST_CASE("annotation document: a clip added under a used name gets a unique one", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick"));
    document.add_clip(kick_clip("kick"));
    REQUIRE(document.clip_count() == 2);
    CHECK(document.clip(1).name == "kick_2");
    CHECK(document.annotations().validate());
}

TEST_CASE("annotation document: a drag of the hit frame merges into one step, separate drags stay apart", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick"));
    const int steps_before = document.undo_stack()->count();
    for (int frame = 61; frame <= 70; ++frame) {
        RawAnnotatedClip clip = document.clip(0);
        clip.hit_frame = frame;
        document.edit_clip(0, clip, ClipField::hit_frame, /*drag_session=*/7);
    }
    CHECK(document.undo_stack()->count() == steps_before + 1);
    CHECK(document.undo_stack()->undoText() == "Move Hit Frame");
    CHECK(document.clip(0).hit_frame == 70);

    RawAnnotatedClip later = document.clip(0);
    later.hit_frame = 72;
    document.edit_clip(0, later, ClipField::hit_frame, /*drag_session=*/8); // a new drag: a new step
    CHECK(document.undo_stack()->count() == steps_before + 2);

    document.undo_stack()->undo();
    CHECK(document.clip(0).hit_frame == 70);
    document.undo_stack()->undo();
    CHECK(document.clip(0).hit_frame == 60); // the whole first drag at once
}

TEST_CASE("annotation document: edits of different fields or without a session never merge", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick"));
    const int steps_before = document.undo_stack()->count();
    RawAnnotatedClip clip = document.clip(0);
    clip.first_frame = 31;
    document.edit_clip(0, clip, ClipField::first_frame, 3);
    clip.last_frame = 80;
    document.edit_clip(0, clip, ClipField::last_frame, 3);
    clip.mirror = false;
    document.edit_clip(0, clip, ClipField::mirror);
    clip.mirror = true;
    document.edit_clip(0, clip, ClipField::mirror);
    CHECK(document.undo_stack()->count() == steps_before + 4);
    CHECK(document.undo_stack()->undoText() == "Toggle Mirror");
}

TEST_CASE("annotation document: a drag that returns to its start leaves no undo step", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick"));
    const int steps_before = document.undo_stack()->count();
    for (int frame : {40, 45, 30}) {
        RawAnnotatedClip clip = document.clip(0);
        clip.first_frame = frame;
        document.edit_clip(0, clip, ClipField::first_frame, 11);
    }
    CHECK(document.clip(0).first_frame == 30);
    CHECK(document.undo_stack()->count() == steps_before);
}

TEST_CASE("annotation document: removing a clip and undoing puts it back in place", "[annotate]") {
    test::qt_application();
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("a"));
    document.add_clip(kick_clip("b"));
    document.add_clip(kick_clip("c"));
    document.remove_clip(1);
    REQUIRE(document.clip_count() == 2);
    CHECK(document.clip(1).name == "c");
    document.undo_stack()->undo();
    REQUIRE(document.clip_count() == 3);
    CHECK(document.clip(1).name == "b");
}

TEST_CASE("annotation document: save writes annotations_write_string's text atomically and reads back equal", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-save");
    const QString path = QString::fromStdString((folder / "kicks.json").string());
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick_a"));
    RawAnnotatedClip second = kick_clip("kick_b");
    second.first_frame = 168, second.hit_frame = 194, second.last_frame = 213, second.mirror = false;
    document.add_clip(second);
    REQUIRE(document.save_as(path));
    CHECK_FALSE(document.is_dirty());
    CHECK(document.file_path() == path);

    const std::string written = test::read_text(path.toStdString());
    CHECK(written == annotations_write_string(document.annotations()));
    Result<RawAnnotations> read = annotations_read_file(path.toStdString());
    REQUIRE(read);
    REQUIRE(read->clips.size() == 2);
    for (size_t index = 0; index < 2; ++index) CHECK(clips_equal(read->clips[index], document.annotations().clips[index]));
    CHECK(annotations_write_string(*read) == written);

    AnnotationDocument reopened(test::mocap_root());
    REQUIRE(reopened.open_annotations(path));
    CHECK(reopened.text() == written);
    CHECK_FALSE(reopened.is_dirty());
    CHECK(reopened.undo_stack()->count() == 0);
    // Only the written file is left in the folder: QSaveFile's temporary is gone.
    CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator{}) == 1);
}

TEST_CASE("annotation document: saving an invalid file is refused and leaves the old file alone", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-invalid");
    const QString path = QString::fromStdString((folder / "kicks.json").string());
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kick"));
    REQUIRE(document.save_as(path));
    const std::string before = test::read_text(path.toStdString());
    RawAnnotatedClip broken = document.clip(0);
    broken.segment.reset(); // a kick needs its hit segment
    document.edit_clip(0, broken, ClipField::segment);
    const Result<void> saved = document.save();
    REQUIRE_FALSE(saved);
    CHECK_THAT(saved.error().message, Catch::Contains("segment"));
    CHECK(document.is_dirty());
    CHECK(test::read_text(path.toStdString()) == before);
    CHECK_FALSE(document.clip_messages(0).empty());
}

TEST_CASE("annotation document: clip messages name a range past the capture's end", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    RawAnnotatedClip clip = kick_clip("kick");
    document.add_clip(clip);
    CHECK(document.clip_messages(0).empty());
    clip.last_frame = 100000;
    document.edit_clip(0, clip, ClipField::last_frame);
    REQUIRE(document.clip_messages(0).size() == 1);
    CHECK_THAT(document.clip_messages(0)[0], Catch::Contains("past the end"));
}

TEST_CASE("annotation document: a malformed annotation file is an error naming it, the document unchanged", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-bad");
    const std::filesystem::path bad = folder / "bad.json";
    std::ofstream(bad) << "{ \"format\": \"kumite-annotations\", \"clips\": [ {";
    AnnotationDocument document(test::mocap_root());
    document.add_clip(kick_clip("kept"));
    const Result<void> opened = document.open_annotations(QString::fromStdString(bad.string()));
    REQUIRE_FALSE(opened);
    CHECK_THAT(opened.error().message, Catch::Contains("bad.json"));
    CHECK(document.clip_count() == 1);
    CHECK(document.clip(0).name == "kept");
}

TEST_CASE("annotation document: a malformed capture is an issue with file and line", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-bad-bvh");
    const std::filesystem::path bad = folder / "broken.bvh";
    std::ofstream(bad) << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xposition Yposition\n}\n";
    AnnotationDocument document(test::mocap_root());
    const Result<void> opened = document.open_capture(QString::fromStdString(bad.string()));
    REQUIRE_FALSE(opened);
    const Issue issue = issue_from_message(opened.error().message);
    CHECK(issue.file.endsWith("broken.bvh"));
    CHECK(issue.line == 6); // the "}" where the third channel name should be
    CHECK_FALSE(issue.message.isEmpty());
    CHECK(document.current_capture() == nullptr);
}

TEST_CASE("annotation document: a capture read with a warning opens, the warning in the issues with its line", "[annotate]") {
    test::qt_application();
    // A real capture with its End Site renamed the way some exporters write it ("End ltoes").
    std::ifstream source(test::mocap_root() / "bandai-namco-1/dataset-1_kick_normal_001.bvh", std::ios::binary);
    if (!source) { WARN("captures absent: skipped"); return; }
    std::string text((std::istreambuf_iterator<char>(source)), std::istreambuf_iterator<char>());
    const std::size_t end_site = text.find("End Site");
    REQUIRE(end_site != std::string::npos);
    text.replace(end_site, 8, "End ltoes");
    const int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(end_site), '\n'));
    const std::filesystem::path file = test::make_temp_dir("annotate-warning") / "renamed_end.bvh";
    std::ofstream(file, std::ios::binary) << text;
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString(file.string())));
    REQUIRE(document.current_capture() != nullptr);
    REQUIRE(document.issues().size() == 1);
    CHECK(document.issues()[0].severity == IssueSeverity::warning);
    CHECK(document.issues()[0].file.endsWith("renamed_end.bvh"));
    CHECK(document.issues()[0].line == line);
    CHECK(document.issues()[0].message.contains("End ltoes"));
}

TEST_CASE("annotation document: an annotation file naming a missing capture opens with an issue", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-missing");
    RawAnnotations annotations;
    RawAnnotatedClip clip = kick_clip("ghost");
    clip.source = "nowhere/missing.bvh";
    annotations.clips.push_back(clip);
    REQUIRE(annotations_write_file(folder / "ghost.json", annotations));
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_annotations(QString::fromStdString((folder / "ghost.json").string())));
    CHECK(document.clip_count() == 1);
    REQUIRE(document.issues().size() == 1);
    CHECK(document.issues()[0].file.contains("missing.bvh"));
    CHECK_FALSE(document.clip_messages(0).empty());
}

TEST_CASE("issue: messages split into file, line and text", "[annotate]") {
    const Issue with_line = issue_from_message("data/a.bvh:12: expected a number", "fallback");
    CHECK(with_line.file == "data/a.bvh");
    CHECK(with_line.line == 12);
    CHECK(with_line.message == "expected a number");
    const Issue with_file = issue_from_message("shots.json: not valid JSON");
    CHECK(with_file.file == "shots.json");
    CHECK(with_file.line == 0);
    const Issue bare = issue_from_message("something odd", "x.bvh");
    CHECK(bare.file == "x.bvh");
    CHECK(bare.message == "something odd");
}

TEST_CASE("annotation document: a capture without a frame rate gets one from the animator, saved, with undo", "[annotate][corpus]") {
    test::qt_application();
    const std::string source = "hachaj-shorinryu/s1_mae_geri_right_sample0.bvh";
    if (!std::filesystem::exists(test::mocap_root() / source)) {
        WARN("no hachaj-shorinryu captures");
        return;
    }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / source).string())));
    const LoadedCapture* capture = document.current_capture();
    REQUIRE(capture != nullptr);
    CHECK(capture->source == source);
    CHECK_FALSE(capture->file.clip.has_frame_rate());
    CHECK(capture->suggestions.empty()); // no speeds without a rate
    // The Issues dock lists the reader's warning with its file and line.
    CHECK(std::any_of(document.issues().begin(), document.issues().end(),
                      [](const Issue& issue) { return issue.message.contains("Frame Time: 0") && issue.line > 0; }));

    document.set_capture_fps(source, 100.0);
    CHECK(document.undo_stack()->undoText() == "Set Frame Rate");
    CHECK(document.current_capture() == capture); // read again in place
    CHECK(capture->file.clip.frame_time_s == Approx(0.01));
    CHECK_FALSE(capture->suggestions.empty()); // the kick is found once the rate is known
    CHECK(document.capture_fps(source) == 100.0);
    CHECK(document.is_dirty());

    const std::filesystem::path file = test::make_temp_dir("annotate-fps") / "rates.json";
    REQUIRE(document.save_as(QString::fromStdString(file.string())));
    Result<RawAnnotations> saved = annotations_read_file(file);
    REQUIRE(saved.has_value());
    CHECK(saved->capture_fps.at(source) == 100.0);

    document.undo_stack()->undo();
    CHECK_FALSE(document.capture_fps(source).has_value());
    CHECK_FALSE(capture->file.clip.has_frame_rate());
    CHECK(capture->suggestions.empty());

    // Opening the saved file reads the capture at its rate.
    AnnotationDocument reopened(test::mocap_root());
    REQUIRE(reopened.open_annotations(QString::fromStdString(file.string())));
    REQUIRE(reopened.open_capture(QString::fromStdString((test::mocap_root() / source).string())));
    REQUIRE(reopened.current_capture() != nullptr);
    CHECK(reopened.current_capture()->file.clip.frame_time_s == Approx(0.01));
}
