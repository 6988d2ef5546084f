#pragma once
// The "Preview" dock: the selected strike clip on a shipped character, adapted to a target the animator moves,
// with the same code as `kumite adapt`: the clip is baked on its own (bake_database, as `kumite bake`), played from
// its first frame onto the character and driven onto the target at its hit frame (strike_playback_run), and drawn
// as the filmstrip draws its frames (strike_frame_scene). Below the view: contact error, overshoot, speed at
// contact, joint-limit violations. Move the target with the X/Y/Z boxes or Shift+drag it in the view; the
// strike replays at once. "Natural hit" puts the target where the clip's own hit lands on the character.

#include "annotation_document.h"

#include "kumite/runtime/strike_playback.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;

namespace kumite::view {
class SceneView;
}

namespace kumite::annotate {

class PreviewPanel : public QWidget {
    Q_OBJECT
public:
    explicit PreviewPanel(AnnotationDocument& document, QWidget* parent = nullptr);
    ~PreviewPanel() override;

    // What is shown (null when there is nothing to preview: no strike selected, or the bake failed).
    const StrikePlayback* playback() const { return m_playback.get(); }
    QString status_text() const;
    view::SceneView* view() const { return m_view; }
    Eigen::Vector3d target() const;
    QStringList character_names() const;

    void set_character(const QString& name);
    void set_target(const Eigen::Vector3d& target_world); // replays
    void put_target_at_natural_hit();
    // Bakes and plays the selected clip now instead of after the short delay edits wait for.
    void rebuild_now();
    bool save_filmstrip(const QString& path, QString* error = nullptr) const;
    // Shows frame `frame` of the playback (it goes on playing from there unless paused).
    void seek(int frame);
    void pause();

signals:
    void replayed(); // a new playback is shown

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Character;
    struct Baked;
    void schedule_rebuild();
    void rebuild();
    bool load_character();
    void replay();
    void show_frame();
    void show_message(const QString& text);
    void update_target_boxes();

    AnnotationDocument& m_document;
    std::unique_ptr<Character> m_character;
    std::unique_ptr<Baked> m_baked;
    std::unique_ptr<StrikePlayback> m_playback;
    Eigen::Vector3d m_target = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_natural_hit = Eigen::Vector3d::Zero();
    int m_frame = 0;
    bool m_dragging = false;
    bool m_framed = false;
    bool m_target_at_natural_hit = true;
    QComboBox* m_characters = nullptr;
    QDoubleSpinBox* m_xyz[3] = {nullptr, nullptr, nullptr};
    QPushButton* m_natural = nullptr;
    QPushButton* m_play = nullptr;
    QPushButton* m_filmstrip = nullptr;
    QLabel* m_figures = nullptr;
    view::SceneView* m_view = nullptr;
    QTimer* m_rebuild_timer = nullptr;
    QTimer* m_play_timer = nullptr;
};

} // namespace kumite::annotate
