#include "timeline_strip.h"

#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace kumite::annotate {
namespace {
constexpr double k_margin_px = 8.0;
constexpr double k_grab_px = 6.0;
int g_next_drag_session = 1; // shared by every strip: a session number is never reused
} // namespace

TimelineStrip::TimelineStrip(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(40);
    setMouseTracking(true);
}

void TimelineStrip::set_frame_count(int frame_count) {
    m_frame_count = std::max(0, frame_count);
    update();
}

void TimelineStrip::set_current_frame(int frame) {
    m_current = frame;
    update();
}

void TimelineStrip::set_trim(std::optional<std::pair<int, int>> range, int hit_frame) {
    m_trim = range;
    m_hit = hit_frame;
    update();
}

void TimelineStrip::set_spans(std::vector<std::pair<int, int>> suggestion_spans) {
    m_spans = std::move(suggestion_spans);
    update();
}

double TimelineStrip::x_of(int frame) const {
    const double usable = std::max(1.0, width() - 2.0 * k_margin_px);
    return k_margin_px + usable * frame / std::max(1, m_frame_count - 1);
}

int TimelineStrip::frame_at(double x) const {
    const double usable = std::max(1.0, width() - 2.0 * k_margin_px);
    const int frame = static_cast<int>(std::lround((x - k_margin_px) / usable * std::max(1, m_frame_count - 1)));
    return std::clamp(frame, 0, std::max(0, m_frame_count - 1));
}

std::optional<TimelineHandle> TimelineStrip::handle_at(double x) const {
    if (!m_trim) return std::nullopt;
    // The hit marker sits inside the range: it wins when handles overlap, the out point over the in point.
    if (m_hit >= 0 && std::abs(x - x_of(m_hit)) <= k_grab_px) return TimelineHandle::hit_frame;
    if (std::abs(x - x_of(m_trim->second)) <= k_grab_px) return TimelineHandle::out_point;
    if (std::abs(x - x_of(m_trim->first)) <= k_grab_px) return TimelineHandle::in_point;
    return std::nullopt;
}

void TimelineStrip::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF track(k_margin_px, 6, std::max(1.0, width() - 2 * k_margin_px), height() - 12);
    painter.fillRect(rect(), palette().window());
    painter.fillRect(track, QColor(45, 48, 54));
    if (m_frame_count <= 0) return;

    for (const auto& [first, last] : m_spans) {
        painter.fillRect(QRectF(x_of(first), track.top() + 2, std::max(2.0, x_of(last) - x_of(first)), 6), QColor(90, 200, 100, 140));
    }
    if (m_trim) {
        const QRectF range(x_of(m_trim->first), track.top(), std::max(2.0, x_of(m_trim->second) - x_of(m_trim->first)), track.height());
        painter.fillRect(range, QColor(70, 120, 200, 150));
        painter.setPen(QPen(QColor(120, 190, 255), 3));
        painter.drawLine(QPointF(range.left(), 2), QPointF(range.left(), height() - 2));
        painter.drawLine(QPointF(range.right(), 2), QPointF(range.right(), height() - 2));
        if (m_hit >= 0) {
            const double x = x_of(m_hit);
            QPolygonF marker;
            marker << QPointF(x - 6, 0) << QPointF(x + 6, 0) << QPointF(x, 9);
            painter.setPen(Qt::NoPen);
            painter.setBrush(QColor(255, 70, 60));
            painter.drawPolygon(marker);
            painter.setPen(QPen(QColor(255, 70, 60), 2));
            painter.drawLine(QPointF(x, 8), QPointF(x, height()));
        }
    }
    painter.setPen(QPen(QColor(255, 255, 255), 1.5));
    painter.drawLine(QPointF(x_of(m_current), 0), QPointF(x_of(m_current), height()));
}

void TimelineStrip::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || m_frame_count <= 0) return;
    const double x = event->position().x();
    m_dragging = handle_at(x);
    if (m_dragging) {
        m_drag_session = g_next_drag_session++;
        return;
    }
    m_scrubbing = true;
    emit scrubbed(frame_at(x));
}

void TimelineStrip::mouseMoveEvent(QMouseEvent* event) {
    const double x = event->position().x();
    if (m_dragging) {
        emit handle_dragged(*m_dragging, frame_at(x), m_drag_session);
    } else if (m_scrubbing) {
        emit scrubbed(frame_at(x));
    } else {
        setCursor(handle_at(x) ? Qt::SizeHorCursor : Qt::ArrowCursor);
    }
}

void TimelineStrip::mouseReleaseEvent(QMouseEvent*) {
    m_dragging.reset();
    m_scrubbing = false;
}

} // namespace kumite::annotate
