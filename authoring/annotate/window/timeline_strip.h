#pragma once
// The painted strip under the scrub slider: the capture's frames left to right, the suggestions' spans as faint
// bars, the clip's trim range with draggable in/out handles, the hit frame marker and the current frame. A drag
// of a handle reports every frame it passes with one session number, so the document merges it into one undo
// step; a click or drag elsewhere scrubs.

#include <QWidget>

#include <optional>
#include <utility>
#include <vector>

namespace kumite::annotate {

enum class TimelineHandle { in_point, out_point, hit_frame };

class TimelineStrip : public QWidget {
    Q_OBJECT
public:
    explicit TimelineStrip(QWidget* parent = nullptr);

    void set_frame_count(int frame_count);
    void set_current_frame(int frame);
    // The selected clip's range; none when no clip is selected. hit < 0: no hit frame.
    void set_trim(std::optional<std::pair<int, int>> range, int hit_frame);
    void set_spans(std::vector<std::pair<int, int>> suggestion_spans);

    QSize sizeHint() const override { return {600, 44}; }

signals:
    void scrubbed(int frame);
    void handle_dragged(kumite::annotate::TimelineHandle handle, int frame, int drag_session);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    double x_of(int frame) const;
    int frame_at(double x) const;
    std::optional<TimelineHandle> handle_at(double x) const;

    int m_frame_count = 0;
    int m_current = 0;
    std::optional<std::pair<int, int>> m_trim;
    int m_hit = -1;
    std::vector<std::pair<int, int>> m_spans;
    std::optional<TimelineHandle> m_dragging;
    bool m_scrubbing = false;
    int m_drag_session = 0;
};

} // namespace kumite::annotate
