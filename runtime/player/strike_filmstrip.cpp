#include "strike_filmstrip.h"

#include "player_scene.h"
#include "scene_geometry.h"
#include "scene_painter.h"

#include "kumite/formats/atomic_file.h"

#include <QBuffer>
#include <QGuiApplication>
#include <QPainter>

#include <memory>

#include <algorithm>
#include <cmath>

namespace kumite::view {
namespace {

const Color k_body_color{0.86f, 0.55f, 0.25f};
const Color k_target_color{1.0f, 0.2f, 0.15f};
const Color k_path_to_contact{1.0f, 0.85f, 0.2f};
const Color k_path_after_contact{0.35f, 0.7f, 1.0f};

void add_character(Scene& scene, const StrikePlayback& playback, int frame) {
    const auto positions = playback.positions(frame);
    add_skeleton_capsules(scene, playback.motion.skeleton, positions, 0.035f * float(std::max(0.5, positions[0].y()) / 0.95), k_body_color);
}

void add_path(Scene& scene, const StrikePlayback& playback, int from, int to, const Color& color) {
    Polyline line;
    line.color = color;
    line.width_px = 1.5f;
    for (int frame = std::max(from, 0); frame <= to && frame < int(playback.effector_path.size()); ++frame) {
        line.points.push_back(playback.effector_path[frame].cast<float>());
    }
    if (line.points.size() > 1) scene.polylines.push_back(std::move(line));
}

// Moves the camera back or forth until the box's corners fill 90% of the view (the box centred).
ViewProjection camera_fitting(OrbitCamera& camera, const Eigen::AlignedBox3f& box, float aspect) {
    camera.frame(box);
    for (int iteration = 0; iteration < 4; ++iteration) {
        const ViewProjection vp = camera.view_projection(aspect);
        float extent = 0.0f;
        for (int corner = 0; corner < 8; ++corner) {
            Eigen::Vector2f ndc;
            float depth;
            if (!project_point(vp, box.corner(Eigen::AlignedBox3f::CornerType(corner)), ndc, depth)) return vp;
            extent = std::max(extent, ndc.cwiseAbs().maxCoeff());
        }
        camera.distance_m *= std::clamp(extent / 0.9f, 0.5f, 2.0f);
    }
    return camera.view_projection(aspect);
}

} // namespace

void strike_frame_scene(const StrikePlayback& playback, int frame, int first_path_frame, Scene& scene) {
    scene.clear();
    scene.floor_half_size_m = 2.0f;
    if (frame < 0 || frame >= playback.motion.frame_count()) return;
    add_character(scene, playback, frame);
    Sphere target;
    target.center = playback.target.cast<float>();
    target.radius_m = 0.05f; // wider than a hand or foot capsule, so the contact still shows it
    target.color = k_target_color;
    target.opacity = 0.85f;
    scene.spheres.push_back(target);
    Sphere effector;
    effector.center = playback.effector_path[frame].cast<float>();
    effector.radius_m = 0.022f;
    effector.color = {1.0f, 1.0f, 1.0f};
    scene.spheres.push_back(effector);
    add_path(scene, playback, first_path_frame, std::min(frame, playback.contact_frame), k_path_to_contact);
    if (frame > playback.contact_frame) add_path(scene, playback, playback.contact_frame, frame, k_path_after_contact);
}

std::vector<int> filmstrip_frames(const StrikePlayback& playback, const FilmstripOptions& options) {
    std::vector<int> frames;
    const int last = playback.motion.frame_count() - 1;
    if (last < 0) return frames;
    const int step = std::max(1, options.frame_step);
    for (int offset = -options.frames_before; offset <= options.frames_after; offset += step) {
        frames.push_back(std::clamp(playback.contact_frame + offset, 0, last));
    }
    frames.push_back(std::clamp(playback.contact_frame, 0, last));
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

QImage strike_filmstrip_render(const StrikePlayback& playback, const QString& title, const FilmstripOptions& options) {
    const std::vector<int> frames = filmstrip_frames(playback, options);
    const int label_w = 56, title_h = 30, columns = std::max<int>(1, int(frames.size()));
    QImage image(label_w + columns * options.cell_width_px, title_h + 2 * options.cell_height_px, QImage::Format_RGB32);
    image.fill(QColor(18, 20, 26));
    if (frames.empty()) return image;

    // One camera per row for every cell, framing the character over the shown frames and the target.
    Eigen::AlignedBox3f box;
    for (int frame : frames) {
        for (const Eigen::Vector3d& p : playback.positions(frame)) box.extend(p.cast<float>());
    }
    box.extend(playback.target.cast<float>());
    const float aspect = float(options.cell_width_px) / float(options.cell_height_px);
    struct Row {
        const char* name;
        float yaw_rad;
    };
    const Row rows[2] = {{"side", 1.5707963f}, {"front", 0.3f}};

    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QColor(230, 230, 235));
    QFont font = painter.font();
    font.setPixelSize(14);
    painter.setFont(font);
    painter.drawText(QRect(8, 0, image.width() - 16, title_h), Qt::AlignVCenter | Qt::AlignLeft, title);
    const int first_shown = std::max(0, frames.front() - 2 * options.frame_step);
    Scene scene;
    for (int r = 0; r < 2; ++r) {
        OrbitCamera camera;
        camera.fov_y_deg = 20.0f;
        camera.yaw_rad = rows[r].yaw_rad;
        camera.pitch_rad = 0.08f;
        const ViewProjection vp = camera_fitting(camera, box, aspect);
        const int top = title_h + r * options.cell_height_px;
        painter.setPen(QColor(200, 200, 210));
        painter.drawText(QRect(0, top, label_w, options.cell_height_px), Qt::AlignCenter, rows[r].name);
        for (int c = 0; c < columns; ++c) {
            const int frame = frames[c];
            const QRect cell(label_w + c * options.cell_width_px, top, options.cell_width_px - 2, options.cell_height_px - 2);
            strike_frame_scene(playback, frame, first_shown, scene);
            paint_scene(painter, scene, vp, cell);
            const bool contact = frame == playback.contact_frame;
            painter.setPen(contact ? QColor(255, 80, 70) : QColor(220, 220, 228));
            const QString label = QString("frame %1%2").arg(frame).arg(contact ? "  contact" : "");
            painter.drawText(cell.adjusted(6, 4, -4, 0), Qt::AlignTop | Qt::AlignLeft, label);
            if (frame > playback.contact_frame && frame < int(playback.past_target_m.size())) {
                painter.setPen(QColor(170, 200, 240));
                painter.drawText(cell.adjusted(6, 0, -4, -4), Qt::AlignBottom | Qt::AlignLeft,
                                 QString("past %1 cm").arg(100.0 * playback.past_target_m[frame], 0, 'f', 1));
            }
            if (contact) {
                painter.setPen(QPen(QColor(255, 80, 70), 3));
                painter.setBrush(Qt::NoBrush);
                painter.drawRect(cell.adjusted(1, 1, -1, -1));
            }
        }
    }
    return image;
}

Result<void> strike_filmstrip_save(const StrikePlayback& playback, const QString& title, const std::string& png_path,
                                   const FilmstripOptions& options) {
    std::unique_ptr<QGuiApplication> application;
    if (!QGuiApplication::instance()) { // fonts need an application; the offscreen platform needs no display
        static int argc = 1;
        static char name[] = "kumite";
        static char* argv[] = {name, nullptr};
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
        application = std::make_unique<QGuiApplication>(argc, argv);
    }
    const QImage image = strike_filmstrip_render(playback, title, options);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) return make_error(ErrorCode::io, png_path + ": could not encode the filmstrip as PNG");
    return write_file_atomically(png_path, std::string_view(bytes.constData(), std::size_t(bytes.size())));
}

} // namespace kumite::view
