#pragma once
// The heatmap dock: the pose-distance matrix of the last baked database (pose_heatmap.h) — the clusters'
// centroids, poses sampled over the database, or the selected clip's poses against the centroids — drawn dark
// (near) to bright (far). A click on a cell shows the
// pose pair and jumps to the first pose's clip and frame; "Go to B" jumps to the second.

#include "pose_heatmap.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QPushButton;

namespace kumite::annotate {

class HeatmapView : public QWidget {
    Q_OBJECT
public:
    explicit HeatmapView(QWidget* parent = nullptr);
    // Not owned; null or empty shows `empty_text` instead.
    void set_heatmap(const PoseHeatmap* heatmap, const QString& empty_text = {});
    QSize sizeHint() const override { return {320, 320}; }

signals:
    void cell_clicked(int row, int column);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    QRectF matrix_rect() const;
    std::optional<std::pair<int, int>> cell_at(QPointF point) const;

    const PoseHeatmap* m_heatmap = nullptr;
    QImage m_image;
    QString m_empty_text;
    std::optional<std::pair<int, int>> m_marked;
};

class HeatmapPanel : public QWidget {
    Q_OBJECT
public:
    explicit HeatmapPanel(QWidget* parent = nullptr);
    void set_database(std::shared_ptr<const MotionDatabaseContent> database, const QString& path);
    // The clip the "Selected clip vs clusters" view shows (its name in the annotation file).
    void set_selected_clip(const std::string& clip_name);

signals:
    void jump_requested(const kumite::annotate::PoseLocation& location);

private:
    void rebuild();
    void show_cell(int row, int column);

    std::shared_ptr<const MotionDatabaseContent> m_database;
    PoseHeatmap m_heatmap;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> m_pair;
    std::string m_selected_clip;
    QComboBox* m_kind = nullptr;
    QLabel* m_title = nullptr;
    QLabel* m_cell = nullptr;
    HeatmapView* m_view = nullptr;
    QPushButton* m_go_a = nullptr;
    QPushButton* m_go_b = nullptr;
};

} // namespace kumite::annotate
