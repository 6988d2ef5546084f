// The real kumite-annotate window, offscreen, driven the way an animator drives it: open the kick capture,
// accept the three right-kick suggestions, save, bake, click the heatmap; drag the hit marker, pick a bone,
// quit with unsaved changes; and a window process killed after an edit whose autosave is recovered on reopen.
// Dialogs (file choosers, questions) are answered by a timer, as a user would click them.

#include "heatmap_panel.h"
#include "main_window.h"
#include "preview_panel.h"
#include "scene_builder.h"
#include "scene_view.h"
#include "support/test_paths.h"
#include "timeline_strip.h"
#include "window_test_support.h"

#include "kumite/formats/motion_database_file.h"

#include <catch2/catch.hpp>

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLineEdit>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QThread>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace kumite;
using namespace kumite::annotate;

namespace {

const std::string& k_kick_capture = test::k_window_kick_capture;
using test::click_accept_buttons;
using test::gui_application;
using test::have_captures;
using test::settle;
using test::temp_mocap_root;

bool wait_until(const std::function<bool()>& done, int timeout_ms = 10000) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeout_ms) return false;
        QApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(2);
    }
    return true;
}

// Answers the next modal dialog of type T with `answer`, from the event loop the dialog runs; `answer` returns
// false to be asked again at the next tick. Gives up after 10 s so that an unused answer never clicks a later
// test's dialog; a dialog of that type still open then is rejected, so the test fails instead of hanging.
template <class T>
void answer_next_dialog_when(std::function<bool(T*)> answer) {
    auto* timer = new QTimer(qApp);
    timer->setInterval(10);
    auto* age = new QElapsedTimer;
    age->start();
    QObject::connect(timer, &QTimer::destroyed, [age] { delete age; });
    QObject::connect(timer, &QTimer::timeout, [timer, answer, age] {
        auto* dialog = qobject_cast<T*>(QApplication::activeModalWidget());
        const bool expired = age->elapsed() > 10000;
        if (expired && dialog) {
            std::fprintf(stderr, "test: gave up answering a %s, rejecting it\n", dialog->metaObject()->className());
            QMetaObject::invokeMethod(dialog, "reject", Qt::QueuedConnection);
        }
        if (expired || (dialog && answer(dialog))) {
            timer->stop();
            timer->deleteLater();
        }
    });
    timer->start();
}

template <class T>
void answer_next_dialog(std::function<void(T*)> answer) {
    answer_next_dialog_when<T>([answer](T* dialog) {
        answer(dialog);
        return true;
    });
}

// The file dialog fills its name field from the suggested path once its folder model has loaded, which under load
// can come after a selection made too early: select until the dialog reports our file, then accept. Qt's own
// dialog ignores selectFile while its name field has the focus (as a typing user would want), which it gets
// depending on timing: the field gives up the focus first.
void choose_file(const QString& path) {
    answer_next_dialog_when<QFileDialog>([path](QFileDialog* dialog) {
        if (auto* name = dialog->findChild<QLineEdit*>("fileNameEdit")) name->clearFocus();
        dialog->selectFile(path);
        const QStringList selected = dialog->selectedFiles();
        if (selected.size() != 1 || QFileInfo(selected[0]).absoluteFilePath() != QFileInfo(path).absoluteFilePath()) {
            std::fprintf(stderr, "test: the file dialog selects %s, waiting for %s\n", qPrintable(selected.join(", ")), qPrintable(path));
            return false;
        }
        QMetaObject::invokeMethod(dialog, "accept"); // protected in QFileDialog, a slot all the same
        return true;
    });
}

void press_button(QMessageBox::StandardButton button) {
    answer_next_dialog<QMessageBox>([button](QMessageBox* box) { box->button(button)->click(); });
}

void send_mouse(QWidget* widget, QEvent::Type type, QPointF point, Qt::MouseButtons buttons) {
    QMouseEvent event(type, point, widget->mapToGlobal(point), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(widget, &event);
}

} // namespace

TEST_CASE("annotate window: three right kicks from suggestions, saved, baked, heatmap clicked", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window");
    MainWindow window(root);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / k_kick_capture).string())));
    settle();
    CHECK(click_accept_buttons(window, 10) == 3);
    AnnotationDocument& document = window.document();
    REQUIRE(document.clip_count() == 3);
    CHECK(window.isWindowModified());
    CHECK(window.windowTitle().contains("[*]"));

    const std::filesystem::path saved = root / "kicks.json";
    choose_file(QString::fromStdString(saved.string()));
    REQUIRE(window.save());
    CHECK_FALSE(window.isWindowModified());
    CHECK(document.file_path().toStdString() == saved.string());
    CHECK(test::read_text(saved) == annotations_write_string(document.annotations()));
    for (int index = 0; index < 3; ++index) CHECK(document.clip(index).source == k_kick_capture);

    const std::filesystem::path database = root / "kicks.kdb";
    choose_file(QString::fromStdString(database.string()));
    window.bake();
    REQUIRE(std::filesystem::exists(database));
    Result<MotionDatabase> opened = MotionDatabase::open(database, /*verify_hash=*/true);
    REQUIRE(opened);
    CHECK(opened->view().clips.size() == 6);
    CHECK(document.issues().empty());

    auto* heatmap = window.findChild<HeatmapView*>();
    REQUIRE(heatmap);
    settle();
    REQUIRE(heatmap->isVisible());
    const int clusters = int(opened->view().clusters.size());
    const double side = std::min(heatmap->width(), heatmap->height()) - 8;
    const QPointF origin((heatmap->width() - side) / 2.0, (heatmap->height() - side) / 2.0);
    document.select_clip(-1);
    int clicked_row = -1, clicked_column = -1;
    QObject::connect(heatmap, &HeatmapView::cell_clicked, [&](int row, int column) { clicked_row = row, clicked_column = column; });
    send_mouse(heatmap, QEvent::MouseButtonPress, origin + QPointF(2.5 * side / clusters, 0.5 * side / clusters), Qt::LeftButton);
    CHECK(clicked_row == 0);
    CHECK(clicked_column == 2);
    // The jump selected the clip of cluster 0's representative pose.
    const int selected = document.selected_clip();
    REQUIRE(selected >= 0);
    const PoseLocation location = pose_location(opened->view(), pose_heatmap_of_clusters(opened->view()).row_poses[0]);
    CHECK(document.clip(selected).name == location.clip_name);
}

TEST_CASE("annotate window: a hit-marker drag is one undo step, picking a bone sets the hit segment", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-drag");
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / k_kick_capture).string())));
    settle();
    REQUIRE(click_accept_buttons(window, 1) == 1);
    AnnotationDocument& document = window.document();
    document.select_clip(0);
    settle();
    const RawAnnotatedClip before = document.clip(0);
    const int frame_count = document.current_capture()->file.clip.frame_count();

    auto* strip = window.findChild<TimelineStrip*>();
    REQUIRE(strip);
    REQUIRE(strip->width() > 100);
    auto x_of = [&](int frame) { return 8.0 + (strip->width() - 16.0) * frame / (frame_count - 1); };
    const double y = strip->height() / 2.0;
    const int steps = document.undo_stack()->count();
    send_mouse(strip, QEvent::MouseButtonPress, QPointF(x_of(*before.hit_frame), y), Qt::LeftButton);
    for (int offset = 1; offset <= 5; ++offset) {
        send_mouse(strip, QEvent::MouseMove, QPointF(x_of(*before.hit_frame + offset), y), Qt::LeftButton);
    }
    send_mouse(strip, QEvent::MouseButtonRelease, QPointF(x_of(*before.hit_frame + 5), y), Qt::NoButton);
    CHECK(document.clip(0).hit_frame == *before.hit_frame + 5);
    CHECK(document.undo_stack()->count() == steps + 1);
    CHECK(document.undo_stack()->undoText() == "Move Hit Frame");
    document.undo_stack()->undo();
    CHECK(document.clip(0).hit_frame == before.hit_frame);

    auto* view = window.findChild<view::SceneView*>();
    REQUIRE(view);
    const int left_ankle = document.current_capture()->file.body_map.joint(BodyPart::foot_l);
    emit view->picked(left_ankle);
    CHECK(document.clip(0).segment == BodyPart::foot_l);
    CHECK(document.clip(0).side == Side::left);
    CHECK(document.undo_stack()->undoText() == "Set Hit Segment");
    document.undo_stack()->undo();
    CHECK(document.clip(0).segment == BodyPart::foot_r);
}

TEST_CASE("annotate window: quitting with unsaved changes asks, and Cancel keeps the window open", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-quit");
    MainWindow window(root);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / k_kick_capture).string())));
    settle();
    REQUIRE(click_accept_buttons(window, 1) == 1);
    press_button(QMessageBox::Cancel);
    CHECK_FALSE(window.close());
    CHECK(window.isVisible());
    press_button(QMessageBox::Discard);
    CHECK(window.close());
}

// Run by the next test in a child process: edits an annotation file in the window, waits for the autosave,
// then dies by SIGKILL (no clean-up of any kind).
TEST_CASE("annotate window child: edit then get killed", "[.annotate_window_child]") {
    const char* file = std::getenv("KUMITE_ANNOTATE_CHILD_FILE");
    const char* root = std::getenv("KUMITE_ANNOTATE_CHILD_ROOT");
    if (!file || !root) return;
    gui_application();
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(file));
    window.document().set_current_source(k_kick_capture);
    settle();
    REQUIRE(click_accept_buttons(window, 2) == 2);
    const std::filesystem::path sidecar = std::string(file) + ".autosave";
    REQUIRE(wait_until([&] { return test::read_text(sidecar) == window.document().text(); }));
    std::raise(SIGKILL);
}

TEST_CASE("annotate window: a killed window's edits are offered back and recovered on reopen", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-kill");
    const std::filesystem::path file = root / "kicks.json";
    {
        AnnotationDocument document(root);
        REQUIRE(document.open_capture(QString::fromStdString((root / k_kick_capture).string())));
        document.add_suggestion(document.current_capture()->suggestions.front(), k_kick_capture);
        REQUIRE(document.save_as(QString::fromStdString(file.string())));
    }
    const std::string saved_text = test::read_text(file);
    const test::CommandOutput child = test::run_command(
        "KUMITE_ANNOTATE_CHILD_FILE=" + file.string() + " KUMITE_ANNOTATE_CHILD_ROOT=" + root.string() + " " +
        (test::bin_dir() / "annotate_window_tests").string() + " \"annotate window child: edit then get killed\"");
    INFO(child.out << child.err);
    REQUIRE(child.status == 128 + SIGKILL);
    CHECK(test::read_text(file) == saved_text); // the file itself was never touched
    const std::string autosaved = test::read_text(file.string() + ".autosave");
    REQUIRE_FALSE(autosaved.empty());
    Result<RawAnnotations> recovered_clips = annotations_parse(autosaved, "autosave");
    REQUIRE(recovered_clips);
    CHECK(recovered_clips->clips.size() == 3);

    MainWindow window(root);
    window.show();
    press_button(QMessageBox::Yes);
    REQUIRE(window.open_path(QString::fromStdString(file.string())));
    CHECK(window.document().text() == autosaved);
    CHECK(window.document().is_dirty());
    CHECK(window.isWindowModified());
    REQUIRE(window.save()); // to the file it came from: no dialog
    CHECK(test::read_text(file) == autosaved);
    CHECK_FALSE(std::filesystem::exists(file.string() + ".autosave"));
}

TEST_CASE("annotate window: a folder opens every capture, the first on show, the selector switches", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-folder");
    const std::string punch = "bandai-namco-1/dataset-1_punch_normal_001.bvh";
    std::filesystem::copy_file(test::mocap_root() / punch, root / punch);
    std::ofstream(root / "bandai-namco-1/zz_broken.bvh") << "HIERARCHY\nROOT Hips\n";
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / "bandai-namco-1").string())));
    settle();
    AnnotationDocument& document = window.document();
    CHECK(document.captures().captures().size() == 2);
    REQUIRE(document.issues().size() == 1); // the broken one, with its name
    CHECK(document.issues()[0].file.endsWith("zz_broken.bvh"));
    REQUIRE(document.current_capture());
    CHECK(document.current_capture()->source == k_kick_capture);
    auto* selector = window.findChild<QComboBox*>("capture_selector");
    REQUIRE(selector);
    REQUIRE(selector->count() == 2);
    CHECK(selector->currentIndex() == 0);
    selector->setCurrentIndex(1);
    emit selector->activated(1);
    CHECK(document.current_capture()->source == punch);
}

TEST_CASE("annotate window: files dropped on the window open, and a bad one becomes an issue", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-drop");
    const std::filesystem::path bad = root / "bad.json";
    std::ofstream(bad) << "[1, 2";
    MainWindow window(root, /*interactive=*/false);
    window.show();
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(QString::fromStdString((root / k_kick_capture).string())),
                  QUrl::fromLocalFile(QString::fromStdString(bad.string()))});
    QDragEnterEvent enter(QPoint(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&window, &enter);
    CHECK(enter.isAccepted());
    QDropEvent drop(QPointF(50, 50), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&window, &drop);
    AnnotationDocument& document = window.document();
    REQUIRE(document.current_capture());
    CHECK(document.current_capture()->source == k_kick_capture);
    REQUIRE(document.issues().size() == 1);
    CHECK(document.issues()[0].file.endsWith("bad.json"));
}

TEST_CASE("annotate window: a bake that fails (missing capture) reports it and writes nothing", "[annotate_window]") {
    gui_application();
    const std::filesystem::path root = test::make_temp_dir("annotate-window-bake-fail");
    RawAnnotations annotations;
    RawAnnotatedClip clip;
    clip.name = "ghost";
    clip.source = "nowhere/missing.bvh";
    clip.first_frame = 0, clip.last_frame = 10, clip.semantics = "rest";
    annotations.clips.push_back(clip);
    REQUIRE(annotations_write_file(root / "ghost.json", annotations));
    MainWindow window(root);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / "ghost.json").string())));
    const size_t issues_before = window.document().issues().size();
    CHECK(issues_before == 1); // the missing capture, when the file opened
    const std::filesystem::path database = root / "ghost.kdb";
    choose_file(QString::fromStdString(database.string()));
    QString warning;
    answer_next_dialog<QMessageBox>([&warning](QMessageBox* box) {
        warning = box->text();
        box->button(QMessageBox::Ok)->click();
    });
    window.bake();
    CHECK(warning.contains("missing.bvh"));
    CHECK(window.document().issues().size() == issues_before + 1);
    CHECK_FALSE(std::filesystem::exists(database));
}

TEST_CASE("annotate window: the trajectory is computed once per strike, not once per frame", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    const LoadedCapture& capture = *document.current_capture();
    TrajectoryCache cache;
    const StrikeOnShow strike{BodyPart::foot_r, 30, 60, 87, false};
    const Result<ClipTrajectory>& first = cache.get(capture, strike);
    REQUIRE(first);
    const Eigen::Vector3d* points = first->points_world.data();
    const Eigen::Vector3d first_contact = first->contact_world;
    CHECK(cache.get(capture, strike)->points_world.data() == points); // the same storage: not recomputed
    StrikeOnShow moved = strike;
    moved.hit_frame = 61;
    const Result<ClipTrajectory>& second = cache.get(capture, moved);
    REQUIRE(second);
    CHECK(second->contact_world != first_contact);
    moved.hit_frame = 20; // before the in point
    CHECK_FALSE(cache.get(capture, moved));
}

TEST_CASE("annotate window: from an empty annotation file, accepted kicks save into that file", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-empty");
    const std::filesystem::path file = root / "empty.json";
    REQUIRE(annotations_write_file(file, RawAnnotations{}));
    MainWindow window(root);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString(file.string())));
    CHECK(window.document().clip_count() == 0);
    REQUIRE(window.open_path(QString::fromStdString((root / k_kick_capture).string())));
    settle();
    CHECK(click_accept_buttons(window, 10) == 3);
    CHECK(window.isWindowModified());
    REQUIRE(window.save()); // the file is known: no dialog
    CHECK_FALSE(window.isWindowModified());
    Result<RawAnnotations> saved = annotations_read_file(file);
    REQUIRE(saved);
    REQUIRE(saved->clips.size() == 3);
    for (const RawAnnotatedClip& clip : saved->clips) {
        CHECK(clip.semantics == "kick");
        CHECK(clip.side == Side::right);
        CHECK(clip.segment == BodyPart::foot_r);
        CHECK(clip.source == k_kick_capture);
    }
    CHECK(test::read_text(file) == annotations_write_string(*saved));
    // Both files are in the recent list (QSettings, a test location here), newest first.
    const QStringList recent = QSettings().value("recent_files").toStringList();
    REQUIRE(recent.size() >= 2);
    CHECK(recent[0] == QString::fromStdString((root / k_kick_capture).string()));
    CHECK(recent[1] == QString::fromStdString(file.string()));
}

TEST_CASE("annotate window: the scene holds a capsule per bone, the strike's dots, contact and twelve box edges", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    const LoadedCapture& capture = *document.current_capture();
    const Skeleton& skeleton = capture.file.clip.skeleton;
    TrajectoryCache cache;
    const StrikeOnShow strike{BodyPart::foot_r, 30, 60, 87, false};
    const Result<ClipTrajectory>& trajectory = cache.get(capture, strike);
    REQUIRE(trajectory);
    view::Scene scene;
    scene_build(scene, capture, 60, BodyPart::foot_r, &trajectory.value());
    CHECK(int(scene.capsules.size()) == skeleton.joint_count() - 1 + int(skeleton.end_sites.size()));
    REQUIRE(scene.spheres.size() == 1);
    int dots = 0, edges = 0, dot_points = 0;
    for (const view::Polyline& line : scene.polylines) {
        if (line.dots) ++dots, dot_points += int(line.points.size());
        else edges += line.points.size() == 2;
    }
    CHECK(dots == 2); // to the hit, after it
    CHECK(dot_points == 87 - 30 + 1);
    CHECK(edges == 12);
    // The skeleton stands on the grid: the lowest point of any bone is near y = 0.
    float lowest = 1e9f;
    for (const view::Capsule& capsule : scene.capsules) lowest = std::min({lowest, capsule.a.y(), capsule.b.y()});
    CHECK(std::abs(lowest) < 0.15f);
    // Picking: a capsule's id is the joint its segment starts at; the right foot's bone names foot_r, highlighted.
    const int ankle = capture.file.body_map.joint(BodyPart::foot_r);
    CHECK(scene_part_of_pick(capture, ankle) == BodyPart::foot_r);
    CHECK(scene_part_of_pick(capture, capture.file.body_map.joint(BodyPart::shin_r)) == BodyPart::shin_r);
    // The hit segment's bones share one colour, every other bone another.
    std::vector<view::Color> hit_colors, other_colors;
    for (const view::Capsule& capsule : scene.capsules) {
        (scene_part_of_pick(capture, capsule.id) == BodyPart::foot_r ? hit_colors : other_colors).push_back(capsule.color);
    }
    REQUIRE_FALSE(hit_colors.empty());
    REQUIRE_FALSE(other_colors.empty());
    for (const view::Color& color : hit_colors) CHECK(color == hit_colors.front());
    for (const view::Color& color : other_colors) CHECK(color == other_colors.front());
    CHECK(hit_colors.front() != other_colors.front());
}

TEST_CASE("annotate window: the preview plays the selected kick on every character, onto a target moved and dragged", "[annotate_window]") {
    gui_application();
    if (!have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = temp_mocap_root("annotate-window-preview");
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / k_kick_capture).string())));
    settle();
    REQUIRE(click_accept_buttons(window, 1) == 1); // one right kick from the suggestions
    AnnotationDocument& document = window.document();
    document.select_clip(0);
    PreviewPanel& preview = *window.preview();
    window.preview_dock()->raise();
    preview.rebuild_now();
    REQUIRE(preview.playback());
    CHECK(preview.character_names().size() == 5);
    for (const QString& name : preview.character_names()) {
        preview.set_character(name);
        REQUIRE(preview.playback());
        const StrikePlayback& played = *preview.playback();
        INFO(name.toStdString() << ": " << preview.status_text().toStdString());
        // At the natural hit the strike is the clip's own: on the target at the hit, not past it, no bad joint.
        CHECK((played.target - preview.target()).norm() < 1e-9);
        CHECK(played.contact_frame == played.hit_frame);
        CHECK(played.contact_error_m < 1e-3);
        CHECK(played.overshoot_m <= 0.03);
        CHECK(played.joint_limit_violations == 0);
        // Moved 10 cm down and 5 cm in: still met, still stopped there.
        preview.set_target(preview.target() + Eigen::Vector3d(0.0, -0.1, -0.05));
        CHECK(preview.playback()->contact_error_m < 0.01);
        CHECK(preview.playback()->overshoot_m <= 0.03);
        CHECK(preview.playback()->joint_limit_violations == 0);
        CHECK(preview.status_text().contains("joint-limit violations"));
        // Every shipped character has a body: the preview draws it skinned (its bones stay for QPainter).
        const view::Scene& drawn = preview.view()->scene();
        REQUIRE(drawn.bodies.size() == 1);
        CHECK(drawn.bodies[0].skin.size() == std::size_t(preview.playback()->motion.skeleton.joint_count()));
        CHECK(std::all_of(drawn.capsules.begin(), drawn.capsules.end(), [](const view::Capsule& c) { return c.of_body; }));
    }
    // Shift+drag in the view moves the target in the plane facing the camera, and the strike follows it.
    view::SceneView* view = preview.view();
    REQUIRE(view->width() > 50);
    const Eigen::Vector3d before = preview.target();
    const QPointF centre(view->width() / 2.0, view->height() / 2.0);
    auto send = [&](QEvent::Type type, QPointF point, Qt::MouseButtons buttons) {
        QMouseEvent event(type, point, view->mapToGlobal(point), Qt::LeftButton, buttons, Qt::ShiftModifier);
        QApplication::sendEvent(view, &event);
    };
    send(QEvent::MouseButtonPress, centre, Qt::LeftButton);
    send(QEvent::MouseMove, centre + QPointF(10, -5), Qt::LeftButton);
    send(QEvent::MouseMove, centre + QPointF(30, -25), Qt::LeftButton);
    send(QEvent::MouseButtonRelease, centre + QPointF(30, -25), Qt::NoButton);
    CHECK((preview.target() - before).norm() > 0.01);
    CHECK((preview.playback()->target - preview.target()).norm() < 1e-9);
    // The picture of it, as `kumite adapt --filmstrip` draws it.
    const std::filesystem::path strip = test::make_temp_dir("annotate-preview-strip") / "strip.png";
    QString error;
    CHECK(preview.save_filmstrip(QString::fromStdString(strip.string()), &error));
    CHECK(std::filesystem::file_size(strip) > 10000);
    // The README's picture of the dock: KUMITE_PREVIEW_SCREENSHOT=OUT.png build/bin/annotate_window_tests "*preview*"
    if (const char* keep = std::getenv("KUMITE_PREVIEW_SCREENSHOT")) {
        preview.pause();
        preview.seek(preview.playback()->contact_frame);
        window.write_screenshot(keep);
    }
    // A clip that is no strike shows why there is nothing to preview.
    document.select_clip(-1);
    preview.rebuild_now();
    CHECK_FALSE(preview.playback());
}
