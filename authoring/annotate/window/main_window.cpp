#include "main_window.h"

#include "clip_panel.h"
#include "heatmap_panel.h"
#include "preview_panel.h"
#include "issues_panel.h"
#include "scene_builder.h"
#include "scene_view.h"

#include "kumite/core/contact_point.h"
#include "timeline_panel.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QInputDialog>
#include <QKeySequence>
#include <QMenuBar>
#include <QStatusBar>
#include <QUndoView>

#include <cmath>

namespace kumite::annotate {

MainWindow::MainWindow(std::filesystem::path mocap_root, bool interactive, QWidget* parent)
    : QMainWindow(parent), m_document(std::make_unique<AnnotationDocument>(std::move(mocap_root))),
      m_autosaver(std::make_unique<Autosaver>(*m_document)), m_trajectories(std::make_unique<TrajectoryCache>()),
      m_interactive(interactive) {
    setAcceptDrops(true);
    m_view = new view::SceneView(this);
    setCentralWidget(m_view);
    build_docks();
    build_actions();
    statusBar()->showMessage(tr("Viewport: %1 — open a capture or an annotation file (File > Open, or drop it here)")
                                 .arg(m_view->renderer_description()));

    AnnotationDocument& document = *m_document;
    connect(&document, &AnnotationDocument::dirty_changed, this, &MainWindow::update_title);
    connect(&document, &AnnotationDocument::file_path_changed, this, &MainWindow::update_title);
    connect(&document, &AnnotationDocument::current_capture_changed, this, [this] { refresh_scene(true); });
    connect(&document, &AnnotationDocument::selection_changed, this, [this](int index) {
        m_heatmap->set_selected_clip(index >= 0 ? m_document->clip(index).name : std::string());
        refresh_scene();
    });
    connect(&document, &AnnotationDocument::clip_changed, this, [this] { refresh_scene(); });
    connect(&document, &AnnotationDocument::issues_changed, this, [this] {
        if (!m_document->issues().empty()) m_issues_dock->raise();
    });
    connect(m_timeline, &TimelinePanel::frame_changed, this, [this] { refresh_scene(); });
    connect(m_timeline, &TimelinePanel::preview_changed, this, [this] { refresh_scene(); });
    connect(m_view, &view::SceneView::picked, this, &MainWindow::on_picked);
    connect(m_heatmap, &HeatmapPanel::jump_requested, this, &MainWindow::jump_to);
    connect(m_autosaver.get(), &Autosaver::written, this,
            [this](const QString& path) { statusBar()->showMessage(tr("Autosaved to %1").arg(path), 3000); });
    // Reported once per message: the timer retries after every edit.
    connect(m_autosaver.get(), &Autosaver::failed, this, [this](const QString& message) {
        if (message == m_last_autosave_error) return;
        m_last_autosave_error = message;
        m_document->report(issue_from_message(message.toStdString(), {}, IssueSeverity::warning));
    });
    update_title();
    resize(1400, 900);
}

MainWindow::~MainWindow() = default;

void MainWindow::build_docks() {
    auto add_dock = [this](const QString& title, QWidget* widget, Qt::DockWidgetArea area) {
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(title);
        dock->setWidget(widget);
        addDockWidget(area, dock);
        return dock;
    };
    m_timeline = new TimelinePanel(*m_document, this);
    m_clips = new ClipPanel(*m_document, this);
    m_issues = new IssuesPanel(*m_document, this);
    m_heatmap = new HeatmapPanel(this);
    QDockWidget* timeline_dock = add_dock(tr("Timeline"), m_timeline, Qt::BottomDockWidgetArea);
    QDockWidget* clips_dock = add_dock(tr("Clips"), m_clips, Qt::RightDockWidgetArea);
    m_issues_dock = add_dock(tr("Issues"), m_issues, Qt::BottomDockWidgetArea);
    m_heatmap_dock = add_dock(tr("Heatmap"), m_heatmap, Qt::RightDockWidgetArea);
    m_preview = new PreviewPanel(*m_document, this);
    m_preview_dock = add_dock(tr("Preview"), m_preview, Qt::RightDockWidgetArea);
    auto* history = new QUndoView(m_document->undo_stack(), this);
    history->setEmptyLabel(tr("<opened>"));
    QDockWidget* history_dock = add_dock(tr("History"), history, Qt::BottomDockWidgetArea);
    tabifyDockWidget(timeline_dock, m_issues_dock);
    tabifyDockWidget(m_issues_dock, history_dock);
    tabifyDockWidget(clips_dock, m_heatmap_dock);
    tabifyDockWidget(m_heatmap_dock, m_preview_dock);
    timeline_dock->raise();
    clips_dock->raise();
    resizeDocks({timeline_dock}, {300}, Qt::Vertical);
    resizeDocks({clips_dock}, {380}, Qt::Horizontal);
}

void MainWindow::build_actions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, &MainWindow::new_document);
    file->addAction(tr("&Open..."), QKeySequence::Open, this, &MainWindow::open_dialog);
    file->addAction(tr("Open &Folder..."), this, &MainWindow::open_folder_dialog);
    m_recent_menu = file->addMenu(tr("Open &Recent"));
    rebuild_recent_menu();
    file->addSeparator();
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save &As..."), QKeySequence::SaveAs, this, &MainWindow::save_as);
    file->addSeparator();
    file->addAction(tr("&Bake..."), QKeySequence(tr("Ctrl+B")), this, &MainWindow::bake);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document->undo_stack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document->undo_stack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(tr("&Add Clip at Current Frame"), QKeySequence(tr("Ctrl+K")), this,
                    [this] { m_clips->add_clip_at(m_timeline->current_frame()); });
    edit->addAction(tr("&Remove Clip"), QKeySequence::Delete, this, [this] { m_document->remove_clip(m_document->selected_clip()); });
    edit->addSeparator();
    edit->addAction(tr("Capture &Frame Rate..."), this, &MainWindow::ask_capture_fps);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("&Frame Character"), QKeySequence(tr("F")), this, [this] { m_view->frame_scene(); });
    view->addAction(tr("&Play / Pause"), QKeySequence(tr("Space")), this, [this] { m_timeline->toggle_playing(); });
    view->addAction(tr("Step &Back"), QKeySequence(tr("Left")), this, [this] { m_timeline->step(-1); });
    view->addAction(tr("Step &Forward"), QKeySequence(tr("Right")), this, [this] { m_timeline->step(1); });
    view->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
}

void MainWindow::ask_capture_fps() {
    const LoadedCapture* capture = m_document->current_capture();
    if (!capture) {
        statusBar()->showMessage(tr("Open a capture first"), 5000);
        return;
    }
    const std::optional<double> given = m_document->capture_fps(capture->source);
    const bool in_file = capture->file.frame_rate_in_file;
    const double shown = given ? *given : capture->file.clip.has_frame_rate() ? 1.0 / capture->file.clip.frame_time_s : 100.0;
    const QString why = in_file ? tr("%1 says %2 fps. A rate given here replaces it (saved in the annotation file).")
                                      .arg(QString::fromStdString(capture->source))
                                      .arg(1.0 / capture->file.clip.frame_time_s, 0, 'g', 6)
                                : tr("%1 does not say its frame rate ('Frame Time: 0'). The rate given here is saved in the "
                                     "annotation file, and suggestions, playback and the bake use it.")
                                      .arg(QString::fromStdString(capture->source));
    bool accepted = false;
    const double fps = QInputDialog::getDouble(this, tr("Capture Frame Rate"), why + "\n\n" + tr("Frames per second:"), shown, 1.0, 1000.0,
                                               3, &accepted);
    if (!accepted) return;
    m_document->set_capture_fps(capture->source, fps);
    statusBar()->showMessage(tr("%1 read at %2 fps").arg(QString::fromStdString(capture->source)).arg(fps, 0, 'g', 6), 5000);
}

void MainWindow::update_title() {
    setWindowTitle(m_document->display_name() + QStringLiteral("[*] — kumite-annotate"));
    setWindowModified(m_document->is_dirty());
}

void MainWindow::refresh_scene(bool frame_camera) {
    const LoadedCapture* capture = m_document->current_capture();
    if (!capture) {
        m_view->scene().clear();
        m_view->update();
        return;
    }
    std::optional<StrikeOnShow> strike;
    std::optional<BodyPart> highlight;
    if (const int selected = m_document->selected_clip(); selected >= 0) {
        const RawAnnotatedClip& clip = m_document->clip(selected);
        highlight = clip.segment;
        if (clip.segment && clip.hit_frame) strike = StrikeOnShow{*clip.segment, clip.first_frame, *clip.hit_frame, clip.last_frame, false, semantics_is_block(clip.semantics)};
    } else if (const std::optional<int> preview = m_timeline->previewed_suggestion();
               preview && *preview < int(capture->suggestions.size())) {
        const StrikeSuggestion& proposal = capture->suggestions[size_t(*preview)];
        highlight = proposal.segment;
        strike = StrikeOnShow{proposal.segment, proposal.first_frame, proposal.hit_frame, proposal.last_frame, true,
                              proposal.semantics == StrikeSemantics::block};
    }
    const Result<ClipTrajectory>* trajectory = strike ? &m_trajectories->get(*capture, *strike) : nullptr;
    const bool drawable = trajectory && trajectory->has_value();
    scene_build(m_view->scene(), *capture, m_timeline->current_frame(), highlight, drawable ? &trajectory->value() : nullptr,
                strike && strike->proposal);
    const QString message =
        trajectory && !drawable ? tr("No trajectory: %1").arg(QString::fromStdString(trajectory->error().message)) : QString();
    if (message != m_last_trajectory_message && !message.isEmpty()) statusBar()->showMessage(message, 5000);
    m_last_trajectory_message = message;
    if (frame_camera) m_view->frame_scene();
    m_view->update();
}

void MainWindow::on_picked(int joint) {
    const LoadedCapture* capture = m_document->current_capture();
    if (!capture || joint < 0) return;
    const std::optional<BodyPart> part = scene_part_of_pick(*capture, joint);
    const int selected = m_document->selected_clip();
    if (!part) {
        statusBar()->showMessage(tr("That bone belongs to no body part of the body map"), 4000);
        return;
    }
    const QString part_name = QString::fromLatin1(body_part_name(*part).data(), qsizetype(body_part_name(*part).size()));
    if (selected < 0) {
        statusBar()->showMessage(tr("%1 — select or add a clip to make it the hit segment").arg(part_name), 4000);
        return;
    }
    RawAnnotatedClip clip = m_document->clip(selected);
    clip.segment = *part;
    if (part_name.endsWith(QStringLiteral("_l"))) clip.side = Side::left;
    if (part_name.endsWith(QStringLiteral("_r"))) clip.side = Side::right;
    m_document->edit_clip(selected, clip, ClipField::segment);
    statusBar()->showMessage(tr("Hit segment: %1").arg(part_name), 3000);
}

void MainWindow::jump_to(const PoseLocation& location) {
    const int index = m_document->find_clip(location.clip_name);
    if (index < 0) {
        statusBar()->showMessage(tr("Clip %1 is not in this file any more").arg(QString::fromStdString(location.clip_name)), 5000);
        return;
    }
    m_document->select_clip(index);
    if (const LoadedCapture* capture = m_document->capture_of(index)) {
        const double frame_time = capture->file.clip.frame_time_s;
        const int offset = capture->file.clip.has_frame_rate() ? int(std::lround(location.capture_time_s / frame_time)) : 0;
        m_timeline->set_current_frame(location.source_first_frame + offset);
    }
    statusBar()->showMessage(tr("Pose of %1, frame %2%3")
                                 .arg(QString::fromStdString(location.clip_name))
                                 .arg(m_timeline->current_frame())
                                 .arg(location.mirrored ? tr(" (the database holds it mirrored)") : QString()),
                             5000);
}

} // namespace kumite::annotate
