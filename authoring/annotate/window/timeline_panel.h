#pragma once
// The timeline dock: the capture on show (any the session opened), play/pause, step, scrub slider, frame and time readout, the strip with the trim handles and
// the hit marker (timeline_strip.h), and the strikes `kumite suggest` proposes for the current capture, with their
// proposed kind and height. Selecting a proposal previews it in the viewport; its Accept button adds it to the file
// as a clip (kind and height included), one undo step.

#include "annotation_document.h"
#include "timeline_strip.h"

#include <QTimer>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QTreeWidget;

namespace kumite::annotate {

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    TimelinePanel(AnnotationDocument& document, QWidget* parent = nullptr);

    int current_frame() const { return m_frame; }
    void set_current_frame(int frame);
    // The proposal on show when no clip is selected: an index into the current capture's suggestions.
    std::optional<int> previewed_suggestion() const { return m_preview; }
    void toggle_playing();
    void step(int frames);

signals:
    void frame_changed(int frame);
    void preview_changed();

private:
    void on_capture_changed();
    void on_selection_changed();
    void on_handle_dragged(TimelineHandle handle, int frame, int drag_session);
    void rebuild_suggestions();
    void rebuild_captures();
    void update_readout();
    void advance_playback();
    std::pair<int, int> play_range() const;

    AnnotationDocument& m_document;
    int m_frame = 0;
    std::optional<int> m_preview;
    QTimer m_play_timer;
    QComboBox* m_capture = nullptr;
    QPushButton* m_play = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_readout = nullptr;
    TimelineStrip* m_strip = nullptr;
    QTreeWidget* m_suggestions = nullptr;
};

} // namespace kumite::annotate
