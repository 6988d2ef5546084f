#pragma once
// The kumite-annotate main window: the viewport in the middle (SceneView: skeleton, hit trajectory, contact
// point, hit-path box; click a bone to set the hit segment), docks for the timeline, the clips, the issues and
// the heatmap and the preview on a character, and the File/Edit/View menus. The window owns one AnnotationDocument and its Autosaver; panels
// edit the document only through its undo commands.

#include "annotation_document.h"
#include "autosave.h"

#include <QMainWindow>

#include <memory>

class QAction;
class QMenu;

namespace kumite::view {
class SceneView;
}

namespace kumite::annotate {

class ClipPanel;
class HeatmapPanel;
class PreviewPanel;
class IssuesPanel;
class TimelinePanel;
class TrajectoryCache;
struct PoseLocation;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `interactive` false (screenshots, tests): never ask questions in dialogs.
    MainWindow(std::filesystem::path mocap_root, bool interactive = true, QWidget* parent = nullptr);
    ~MainWindow() override;

    AnnotationDocument& document() { return *m_document; }
    // Opens a capture (.bvh), a folder of captures or an annotation file (.json); problems go to the issues panel.
    // False when nothing could be opened.
    bool open_path(const QString& path);
    bool save();
    bool save_as();
    void bake();
    PreviewPanel* preview() const { return m_preview; }
    QDockWidget* preview_dock() const { return m_preview_dock; }
    // Renders the whole window into a PNG.
    bool write_screenshot(const QString& path);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void build_actions();
    void build_docks();
    void ask_capture_fps(); // Edit > Capture Frame Rate...
    void update_title();
    void refresh_scene(bool frame_camera = false);
    void on_picked(int joint);
    void jump_to(const PoseLocation& location);
    bool open_annotations(const QString& path);
    bool open_capture(const QString& path);
    bool open_folder(const QString& path);
    void offer_recovery(const QString& opened_path, bool is_capture);
    bool maybe_save(); // true: go on (saved, discarded or clean); false: the user cancelled
    void new_document();
    void open_dialog();
    void open_folder_dialog();
    void remember_recent(const QString& path);
    void rebuild_recent_menu();

    std::unique_ptr<AnnotationDocument> m_document;
    std::unique_ptr<Autosaver> m_autosaver;
    std::unique_ptr<TrajectoryCache> m_trajectories;
    bool m_interactive = true;
    view::SceneView* m_view = nullptr;
    TimelinePanel* m_timeline = nullptr;
    ClipPanel* m_clips = nullptr;
    IssuesPanel* m_issues = nullptr;
    HeatmapPanel* m_heatmap = nullptr;
    QDockWidget* m_heatmap_dock = nullptr;
    PreviewPanel* m_preview = nullptr;
    QDockWidget* m_preview_dock = nullptr;
    QDockWidget* m_issues_dock = nullptr;
    QMenu* m_recent_menu = nullptr;
    QString m_last_trajectory_message;
    QString m_last_autosave_error;
};

} // namespace kumite::annotate
