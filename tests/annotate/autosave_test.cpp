// Autosave: a sidecar written while there are unsaved changes, removed on save, and offered for recovery when
// the file (or, for a never-saved session, its capture) is opened again after the process died.

#include "annotation_document.h"
#include "autosave.h"
#include "qt_application.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <QFile>

#include <fstream>
#include <sstream>

using namespace kumite;
using namespace kumite::annotate;

namespace {

const std::string k_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

RawAnnotatedClip kick_clip(const std::string& name, const std::string& source) {
    RawAnnotatedClip clip;
    clip.name = name;
    clip.source = source;
    clip.first_frame = 168;
    clip.last_frame = 213;
    clip.semantics = "kick";
    clip.segment = BodyPart::foot_r;
    clip.side = Side::right;
    clip.hit_frame = 194;
    return clip;
}

std::string read_text(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return file.readAll().toStdString();
}

} // namespace

TEST_CASE("autosave: an edit writes <file>.autosave after the delay, a save removes it", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-autosave");
    const QString path = QString::fromStdString((folder / "shots.json").string());
    AnnotationDocument document(test::mocap_root());
    Autosaver autosaver(document, 50);
    document.add_clip(kick_clip("first", k_kick_capture));
    REQUIRE(document.save_as(path));
    const QString sidecar = autosave_sidecar_for_file(path);
    CHECK(autosaver.sidecar_path() == sidecar);
    CHECK_FALSE(QFile::exists(sidecar));

    RawAnnotatedClip moved = document.clip(0);
    moved.hit_frame = 200;
    document.edit_clip(0, moved, ClipField::hit_frame);
    REQUIRE(test::process_events_until([&] { return QFile::exists(sidecar); }));
    CHECK(read_text(sidecar) == document.text());
    CHECK(autosave_pending_for(path, false) == sidecar);

    REQUIRE(document.save());
    CHECK_FALSE(QFile::exists(sidecar));
    CHECK(autosave_pending_for(path, false).isEmpty());
}

TEST_CASE("autosave: a long drag is autosaved while it goes on, not only when it stops", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-autosave-drag");
    const QString path = QString::fromStdString((folder / "shots.json").string());
    AnnotationDocument document(test::mocap_root());
    Autosaver autosaver(document, 100);
    document.add_clip(kick_clip("first", k_kick_capture));
    REQUIRE(document.save_as(path));
    const QString sidecar = autosave_sidecar_for_file(path);
    bool written_during_drag = false;
    for (int step = 0; step < 40 && !written_during_drag; ++step) { // an edit every ~15 ms for up to 600 ms
        RawAnnotatedClip clip = document.clip(0);
        clip.first_frame = 168 - 1 - step % 20;
        document.edit_clip(0, clip, ClipField::first_frame, 99);
        test::process_events_until([] { return false; }, 15);
        written_during_drag = QFile::exists(sidecar);
    }
    CHECK(written_during_drag);
}

TEST_CASE("autosave: undoing back to the saved state removes the sidecar", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-autosave-undo");
    const QString path = QString::fromStdString((folder / "shots.json").string());
    AnnotationDocument document(test::mocap_root());
    Autosaver autosaver(document, 0);
    document.add_clip(kick_clip("first", k_kick_capture));
    REQUIRE(document.save_as(path));
    document.remove_clip(0);
    const QString sidecar = autosave_sidecar_for_file(path);
    REQUIRE(test::process_events_until([&] { return QFile::exists(sidecar); }));
    document.undo_stack()->undo();
    CHECK_FALSE(document.is_dirty());
    CHECK_FALSE(QFile::exists(sidecar));
}

TEST_CASE("autosave: edits of a process that died are recovered when the file is opened again", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-recover");
    const QString path = QString::fromStdString((folder / "shots.json").string());
    std::string edited_text;
    {
        AnnotationDocument document(test::mocap_root());
        Autosaver autosaver(document, 0);
        document.add_clip(kick_clip("first", k_kick_capture));
        REQUIRE(document.save_as(path));
        document.add_clip(kick_clip("second", k_kick_capture));
        RawAnnotatedClip trimmed = document.clip(1);
        trimmed.first_frame = 170;
        document.edit_clip(1, trimmed, ClipField::first_frame, 5);
        REQUIRE(test::process_events_until([&] { return read_text(autosave_sidecar_for_file(path)) == document.text(); }));
        edited_text = document.text();
        // The process dies here: no save, no clean-up. Destroying the objects must not remove the sidecar either.
    }
    const QString sidecar = autosave_pending_for(path, false);
    REQUIRE(sidecar == autosave_sidecar_for_file(path));

    AnnotationDocument reopened(test::mocap_root());
    Autosaver autosaver(reopened, 0);
    REQUIRE(reopened.open_annotations(path));
    CHECK(reopened.clip_count() == 1);
    REQUIRE(reopened.recover_autosave(sidecar));
    CHECK(reopened.text() == edited_text);
    CHECK(reopened.is_dirty()); // recovered edits are unsaved edits
    CHECK(reopened.undo_stack()->undoText() == "Recover Autosaved Edits");
    reopened.undo_stack()->undo();
    CHECK(reopened.clip_count() == 1);
    reopened.undo_stack()->redo();
    REQUIRE(reopened.save());
    CHECK(read_text(path) == edited_text);
    CHECK_FALSE(QFile::exists(sidecar));
}

TEST_CASE("autosave: a never-saved session autosaves beside its first capture", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path capture = test::copy_capture_to_temp(k_kick_capture, "annotate-untitled");
    const QString capture_path = QString::fromStdString(capture.string());
    std::string edited_text;
    {
        AnnotationDocument document(test::mocap_root());
        Autosaver autosaver(document, 0);
        REQUIRE(document.open_capture(capture_path));
        const LoadedCapture* loaded = document.current_capture();
        REQUIRE(loaded);
        REQUIRE_FALSE(loaded->suggestions.empty());
        document.add_suggestion(loaded->suggestions.front(), loaded->source);
        CHECK(autosaver.sidecar_path() == autosave_sidecar_for_capture(capture_path));
        REQUIRE(test::process_events_until([&] { return QFile::exists(autosaver.sidecar_path()); }));
        edited_text = document.text();
    }
    const QString sidecar = autosave_pending_for(capture_path, true);
    REQUIRE_FALSE(sidecar.isEmpty());
    AnnotationDocument reopened(test::mocap_root());
    REQUIRE(reopened.open_capture(capture_path));
    REQUIRE(reopened.recover_autosave(sidecar));
    CHECK(reopened.text() == edited_text);
    CHECK(reopened.is_dirty());
}

TEST_CASE("autosave: a corrupt sidecar is refused with its name, the document unchanged", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-corrupt");
    const std::filesystem::path sidecar = folder / "shots.json.autosave";
    std::ofstream(sidecar) << "{ not json";
    AnnotationDocument document(test::mocap_root());
    const Result<void> recovered = document.recover_autosave(QString::fromStdString(sidecar.string()));
    REQUIRE_FALSE(recovered);
    CHECK_THAT(recovered.error().message, Catch::Contains("shots.json.autosave"));
    CHECK(document.clip_count() == 0);
    CHECK_FALSE(document.is_dirty());
}
