#include "heatmap_panel.h"

#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <cmath>

namespace kumite::annotate {
namespace {

constexpr int k_max_pose_rows = 400;

// A perceptual-ish dark-blue -> teal -> yellow ramp (viridis' end points and middle), t in 0..1.
QRgb ramp(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float stops[3][3] = {{68, 1, 84}, {33, 145, 140}, {253, 231, 37}};
    const int i = t < 0.5f ? 0 : 1;
    const float u = t < 0.5f ? t * 2.0f : (t - 0.5f) * 2.0f;
    auto mix = [&](int channel) { return int(stops[i][channel] + u * (stops[i + 1][channel] - stops[i][channel])); };
    return qRgb(mix(0), mix(1), mix(2));
}

QString location_text(const PoseLocation& location) {
    return QObject::tr("%1%2, frame %3").arg(QString::fromStdString(location.clip_name),
                                            location.mirrored ? QObject::tr(" (mirrored)") : QString())
        .arg(location.clip_frame);
}

} // namespace

HeatmapView::HeatmapView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(160, 160);
}

void HeatmapView::set_heatmap(const PoseHeatmap* heatmap, const QString& empty_text) {
    m_heatmap = heatmap;
    m_empty_text = empty_text;
    m_marked.reset();
    m_image = QImage();
    if (heatmap && heatmap->rows > 0 && heatmap->columns > 0) {
        m_image = QImage(heatmap->columns, heatmap->rows, QImage::Format_RGB32);
        const float scale = heatmap->max_distance > 0.0f ? 1.0f / std::sqrt(heatmap->max_distance) : 0.0f;
        for (int row = 0; row < heatmap->rows; ++row) {
            auto* line = reinterpret_cast<QRgb*>(m_image.scanLine(row));
            // sqrt: Kovar's distance is squared; the root spreads the near poses the animator looks for.
            for (int column = 0; column < heatmap->columns; ++column) line[column] = ramp(std::sqrt(heatmap->at(row, column)) * scale);
        }
    }
    update();
}

QRectF HeatmapView::matrix_rect() const {
    const double side = std::max(1, std::min(width(), height()) - 8);
    return QRectF((width() - side) / 2.0, (height() - side) / 2.0, side, side);
}

std::optional<std::pair<int, int>> HeatmapView::cell_at(QPointF point) const {
    if (m_image.isNull()) return std::nullopt;
    const QRectF area = matrix_rect();
    if (!area.contains(point)) return std::nullopt;
    const int column = std::clamp(int((point.x() - area.left()) / area.width() * m_heatmap->columns), 0, m_heatmap->columns - 1);
    const int row = std::clamp(int((point.y() - area.top()) / area.height() * m_heatmap->rows), 0, m_heatmap->rows - 1);
    return std::pair{row, column};
}

void HeatmapView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    if (m_image.isNull()) {
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, m_empty_text);
        return;
    }
    const QRectF area = matrix_rect();
    painter.drawImage(area, m_image);
    if (m_marked) {
        const double cell_width = area.width() / m_heatmap->columns, cell_height = area.height() / m_heatmap->rows;
        painter.setPen(QPen(Qt::white, 2));
        painter.drawRect(QRectF(area.left() + m_marked->second * cell_width, area.top() + m_marked->first * cell_height, cell_width,
                                cell_height)
                             .adjusted(-1, -1, 1, 1));
    }
}

void HeatmapView::mousePressEvent(QMouseEvent* event) {
    if (const auto cell = cell_at(event->position())) {
        m_marked = cell;
        update();
        emit cell_clicked(cell->first, cell->second);
    }
}

void HeatmapView::mouseMoveEvent(QMouseEvent* event) {
    const auto cell = cell_at(event->position());
    if (!cell) return;
    QToolTip::showText(event->globalPosition().toPoint(),
                       tr("%1\n%2\nd = %3").arg(QString::fromStdString(m_heatmap->row_labels[size_t(cell->first)]),
                                                QString::fromStdString(m_heatmap->column_labels[size_t(cell->second)]))
                           .arg(m_heatmap->at(cell->first, cell->second), 0, 'f', 3),
                       this);
}

HeatmapPanel::HeatmapPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_kind = new QComboBox(this);
    m_kind->addItems({tr("Cluster centroids"), tr("Poses (sampled)"), tr("Selected clip vs clusters")});
    m_title = new QLabel(tr("no database baked yet"), this);
    top->addWidget(m_kind);
    top->addWidget(m_title, 1);
    layout->addLayout(top);
    m_view = new HeatmapView(this);
    layout->addWidget(m_view, 1);
    m_cell = new QLabel(this);
    m_cell->setWordWrap(true);
    layout->addWidget(m_cell);
    auto* buttons = new QHBoxLayout;
    m_go_a = new QPushButton(tr("Go to A"), this);
    m_go_b = new QPushButton(tr("Go to B"), this);
    m_go_a->setEnabled(false);
    m_go_b->setEnabled(false);
    buttons->addWidget(m_go_a);
    buttons->addWidget(m_go_b);
    layout->addLayout(buttons);

    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] { rebuild(); });
    connect(m_view, &HeatmapView::cell_clicked, this, [this](int row, int column) {
        show_cell(row, column);
        if (m_pair) emit jump_requested(pose_location(m_database->view(), m_pair->first));
    });
    connect(m_go_a, &QPushButton::clicked, this, [this] {
        if (m_pair) emit jump_requested(pose_location(m_database->view(), m_pair->first));
    });
    connect(m_go_b, &QPushButton::clicked, this, [this] {
        if (m_pair) emit jump_requested(pose_location(m_database->view(), m_pair->second));
    });
}

void HeatmapPanel::set_database(std::shared_ptr<const MotionDatabaseContent> database, const QString& path) {
    m_database = std::move(database);
    m_title->setText(QFileInfo(path).fileName());
    rebuild();
}

void HeatmapPanel::set_selected_clip(const std::string& clip_name) {
    if (clip_name == m_selected_clip) return;
    m_selected_clip = clip_name;
    if (m_kind->currentIndex() == 2) rebuild();
}

void HeatmapPanel::rebuild() {
    m_pair.reset();
    m_cell->clear();
    m_go_a->setEnabled(false);
    m_go_b->setEnabled(false);
    m_view->set_heatmap(nullptr, tr("Bake the file (File > Bake...) to see its pose distances"));
    if (!m_database) return;
    switch (m_kind->currentIndex()) {
    case 0: m_heatmap = pose_heatmap_of_clusters(m_database->view()); break;
    case 1: m_heatmap = pose_heatmap_of_poses(m_database->view(), k_max_pose_rows); break;
    default: m_heatmap = pose_heatmap_of_clip(m_database->view(), m_selected_clip); break;
    }
    m_view->set_heatmap(&m_heatmap, tr("Select a clip of the baked file: its poses (rows) against the clusters (columns)"));
}

void HeatmapPanel::show_cell(int row, int column) {
    if (!m_database || row >= m_heatmap.rows || column >= m_heatmap.columns) return;
    m_pair = std::pair{m_heatmap.row_poses[size_t(row)], m_heatmap.column_poses[size_t(column)]};
    const MotionDatabaseView view = m_database->view();
    m_cell->setText(tr("%1 vs %2: d = %3\nA: %4\nB: %5")
                        .arg(QString::fromStdString(m_heatmap.row_labels[size_t(row)]),
                             QString::fromStdString(m_heatmap.column_labels[size_t(column)]))
                        .arg(m_heatmap.at(row, column), 0, 'f', 3)
                        .arg(location_text(pose_location(view, m_pair->first)), location_text(pose_location(view, m_pair->second))));
    m_go_a->setEnabled(true);
    m_go_b->setEnabled(true);
}

} // namespace kumite::annotate
