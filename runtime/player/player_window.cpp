#include "player_window.h"

#include "player_hud.h"
#include "player_scene.h"

#include <QApplication>
#include <QCloseEvent>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QPainter>
#include <QTimer>
#include <QVBoxLayout>

#include <cstdio>
#include <deque>

namespace kumite::view {
namespace {

struct KeyCommand {
    int key;
    const char* label;
    const char* command;
};
const KeyCommand k_keys[] = {{Qt::Key_1, "1", "punch"},      {Qt::Key_2, "2", "punch left"}, {Qt::Key_3, "3", "punch right"},
                             {Qt::Key_4, "4", "kick"},       {Qt::Key_5, "5", "kick left"},  {Qt::Key_6, "6", "kick right"},
                             {Qt::Key_7, "7", "knee"},       {Qt::Key_8, "8", "elbow"}};

// What the strike keys add to their order: J cycles the punch kind, K the kick kind, H the height (index 0: any).
const char* const k_punch_kinds[] = {"", "straight", "hook", "uppercut"};
const char* const k_kick_kinds[] = {"", "front", "roundhouse", "side"};
const char* const k_heights[] = {"", "low", "middle", "high"};

const char* k_help =
    "1/2/3 punch any/left/right   4/5/6 kick any/left/right   7 knee   8 elbow   J punch kind   K kick kind   H height   C next character\n"
    "A aim latched / predicted   D defence on / off   B bones over the body   "
    "V orbit / head-coupled   S mono / side-by-side   F frame   Space pause   Esc quit   mouse: orbit, pan, zoom";

class PlayerWindow : public QWidget {
public:
    // `stepped_outside`: the bout is stepped by someone else (the headset's frame loop), who calls outside_step()
    // after each step and outside_frame() once a frame; the window only shows and takes keys.
    PlayerWindow(Bout& bout, const ViewerSettings& settings, const PlayerRunOptions& options, const std::function<void()>& after_step,
                 bool stepped_outside = false)
        : m_bout(bout), m_options(options), m_after_step(after_step), m_bodies(settings.bodies), m_skeleton_overlay(settings.skeleton_overlay) {
        setWindowTitle(stepped_outside ? "kumite play --xr (supervisor)" : "kumite play");
        resize(settings.width, settings.height);
        auto* layout = new QVBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_view = new SceneView(this);
        layout->addWidget(m_view);
        m_view->set_head_coupling(settings.coupling);
        m_view->set_projection(settings.camera);
        m_view->set_stereo(settings.stereo);
        constexpr float radians_per_degree = 3.14159265f / 180.0f;
        m_view->orbit_camera().target = settings.orbit_target; // by default from the side: fighter and user both in view
        m_view->orbit_camera().distance_m = settings.orbit_distance_m;
        m_view->orbit_camera().yaw_rad = settings.orbit_yaw_deg * radians_per_degree;
        m_view->orbit_camera().pitch_rad = settings.orbit_pitch_deg * radians_per_degree;
        m_view->set_overlay([this](QPainter& painter, const QRect& rect) { draw_hud(painter, rect); });
        m_view->setFocusPolicy(Qt::NoFocus);
        setFocusPolicy(Qt::StrongFocus);
        if (stepped_outside) return;
        connect(&m_timer, &QTimer::timeout, this, [this] { tick(); });
        m_timer.setTimerType(Qt::PreciseTimer);
        m_timer.start(4);
    }

    bool screenshot_failed = false;
    PlayerRunOutcome outcome;

    // Stepped outside: the step's events into the log; the current frame shown (drawn when Qt next paints).
    void outside_step() {
        for (const BoutEvent& event : m_bout.events()) describe(event);
    }
    void outside_frame() {
        if (!m_clock.isValid()) m_clock.start(), m_fps_clock.start();
        refresh_scene();
        count_frame();
        m_view->update();
    }
    bool paused() const { return m_paused; }
    bool closed() const { return m_closed; }
    std::string renderer() const { return m_view->renderer_description().toStdString(); }
    // The window as it is now, as PNG (false when it cannot be written).
    bool save(const std::string& path) {
        refresh_scene();
        return m_view->grab_image().save(QString::fromStdString(path), "PNG");
    }

protected:
    void closeEvent(QCloseEvent* event) override {
        m_closed = true;
        QWidget::closeEvent(event);
    }

    void keyPressEvent(QKeyEvent* event) override {
        for (const KeyCommand& key : k_keys) {
            if (event->key() == key.key) return send(with_labels(key.command));
        }
        switch (event->key()) {
        case Qt::Key_J: m_punch_kind = (m_punch_kind + 1) % 4; return;
        case Qt::Key_K: m_kick_kind = (m_kick_kind + 1) % 4; return;
        case Qt::Key_H: m_height = (m_height + 1) % 4; return;
        case Qt::Key_C: {
            const Fighter& fighter = m_bout.fighter(0);
            send("character " + m_bout.character_name((fighter.character() + 1) % m_bout.character_count()));
            return;
        }
        case Qt::Key_A:
            send(std::string("aim ") + (m_bout.fighter(0).aim() == FighterAim::latched ? "predicted" : "latched"));
            return;
        case Qt::Key_D: send(std::string("defence ") + (m_bout.fighter(0).defence_enabled() ? "off" : "on")); return;
        case Qt::Key_V:
            m_view->set_projection(m_view->projection() == Projection::orbit ? Projection::head_coupled : Projection::orbit);
            return;
        case Qt::Key_S:
            m_view->set_stereo(m_view->stereo() == StereoMode::mono ? StereoMode::side_by_side : StereoMode::mono);
            return;
        case Qt::Key_F: m_view->frame_scene(); return;
        case Qt::Key_B: m_skeleton_overlay = !m_skeleton_overlay; return;
        case Qt::Key_Space: m_paused = !m_paused; return;
        case Qt::Key_Escape:
        case Qt::Key_Q: close(); return;
        default: QWidget::keyPressEvent(event);
        }
    }

private:
    // A strike key's order with the kind and height chosen with J, K and H.
    std::string with_labels(std::string line) const {
        const char* kind = line.starts_with("kick") ? k_kick_kinds[m_kick_kind] : line.starts_with("punch") ? k_punch_kinds[m_punch_kind] : "";
        if (*kind) line += std::string(" ") + kind;
        if (*k_heights[m_height]) line += std::string(" ") + k_heights[m_height];
        return line;
    }
    static const char* or_any(const char* label) { return *label ? label : "any"; }

    void send(const std::string& line) {
        if (Result<void> sent = m_bout.command(line); !sent) note("error: " + sent.error().message);
        else note("> " + line);
    }
    void note(const std::string& text) {
        m_log.push_back(QString::fromStdString(text));
        while (m_log.size() > 6) m_log.pop_front();
    }

    void tick() {
        // Bout time runs on the wall clock, minus the time spent paused; every frame due is stepped (a slow
        // paint is caught up), only a stall of more than a second (a debugger, a suspended process) is skipped
        // rather than replayed, and its frames are counted as missed.
        if (!m_clock.isValid()) { // bout time starts with the first tick, once the window is up
            m_clock.start();
            m_fps_clock.start();
        }
        const double wall_s = m_clock.nsecsElapsed() * 1e-9;
        if (m_paused) {
            m_paused_s += wall_s - m_last_wall_s;
        }
        m_last_wall_s = wall_s;
        const double bout_s = wall_s - m_paused_s;
        const double frame_s = 1.0 / m_bout.rate_hz();
        if (bout_s - m_next_s > 1.0) {
            const long long skipped = static_cast<long long>((bout_s - m_next_s) * m_bout.rate_hz());
            m_bout.count_missed_frames(skipped);
            m_next_s += double(skipped) / m_bout.rate_hz();
        }
        bool stepped = false;
        const bool limited = m_options.stop_after_duration;
        while (!m_paused && m_next_s <= bout_s && !(limited && m_next_s >= m_options.duration_s - 1e-9)) {
            m_bout.step(m_next_s);
            if (m_after_step) m_after_step();
            for (const BoutEvent& event : m_bout.events()) describe(event);
            m_next_s += frame_s;
            stepped = true;
            if (m_bout.quit_requested()) break;
        }
        if (m_bout.quit_requested() || (limited && m_next_s >= m_options.duration_s - 1e-9)) {
            m_timer.stop();
            finish();
            return;
        }
        if (!stepped) return;
        refresh_scene();
        count_frame();
        m_view->update();
    }

    void count_frame() {
        ++m_frames_drawn;
        const double fps_elapsed = m_fps_clock.nsecsElapsed() * 1e-9;
        if (fps_elapsed >= 0.5) {
            m_fps = m_frames_drawn / fps_elapsed;
            m_frames_drawn = 0;
            m_fps_clock.restart();
        }
    }

    // The scene of the bout's current frame; seen from the user's own eyes (head-coupled), the eye follows the
    // head and the head (with a target latched on it) is left out, or it would cover the whole view.
    void refresh_scene() {
        const bool from_the_eyes = m_view->projection() == Projection::head_coupled;
        if (const Eigen::Vector3d* head = m_bout.head(); head && from_the_eyes) {
            HeadCoupling coupling = m_view->head_coupling();
            coupling.eye_world = head->cast<float>();
            m_view->set_head_coupling(coupling);
        }
        Scene& scene = m_view->scene();
        player_scene_build(m_bout, scene);
        scene.skeleton_overlay = m_skeleton_overlay;
        if (!m_bodies) { // capsules only
            scene.bodies.clear();
            for (Capsule& capsule : scene.capsules) capsule.of_body = false;
        }
        if (from_the_eyes) {
            const Eigen::Vector3f eye = m_view->head_coupling().eye_world;
            std::erase_if(m_view->scene().spheres, [&](const Sphere& s) { return (s.center - eye).norm() < s.radius_m + 0.1f; });
        }
    }

    void finish() {
        outcome.renderer = m_view->renderer_description().toStdString();
        outcome.body_mesh_uploads = m_view->body_mesh_uploads();
        if (!m_options.screenshot_path.empty()) {
            refresh_scene();
            const QImage image = m_view->grab_image();
            if (!image.save(QString::fromStdString(m_options.screenshot_path), "PNG")) {
                std::fprintf(stderr, "kumite play: cannot write the screenshot %s\n", m_options.screenshot_path.c_str());
                screenshot_failed = true;
            }
        }
        close();
    }

    void describe(const BoutEvent& bout_event) {
        const FighterEvent& e = bout_event.event;
        char text[224];
        switch (e.type) {
        case FighterEvent::Type::strike: {
            const DbClip& clip = m_bout.database().clips[e.clip];
            std::snprintf(text, sizeof text, "%.1f s  fighter %d: %s %s %s: %s (%s, %s), contact error %.1f cm", e.t_s, bout_event.fighter,
                          std::string(m_bout.database().string(clip.semantics)).c_str(), strike_kind_name(clip.strike_kind()),
                          strike_height_name(clip.strike_height()), e.hit ? "HIT" : "miss", target_part_name(e.target_part), fighter_aim_name(e.aim),
                          e.contact_error_m * 100.0);
            break;
        }
        case FighterEvent::Type::ignored_order: std::snprintf(text, sizeof text, "%.1f s  order ignored: %s", e.t_s, e.why); break;
        case FighterEvent::Type::order_queued: std::snprintf(text, sizeof text, "%.1f s  order waits", e.t_s); break;
        case FighterEvent::Type::order_expired: std::snprintf(text, sizeof text, "%.1f s  order expired: %s", e.t_s, e.why); break;
        case FighterEvent::Type::user_strike_end:
            std::snprintf(text, sizeof text, "%.1f s  user's %s at the %s: %s", e.t_s, e.user_strike.hand == 0 ? "left" : "right",
                          e.user_strike.at_head ? "head" : "chest", user_strike_outcome_name(e.user_strike.outcome));
            break;
        case FighterEvent::Type::tracker_lost: std::snprintf(text, sizeof text, "%.1f s  tracker lost", e.t_s); break;
        case FighterEvent::Type::tracker_back: std::snprintf(text, sizeof text, "%.1f s  tracker back", e.t_s); break;
        default: return;
        }
        note(text);
    }

    void draw_hud(QPainter& painter, const QRect& rect) {
        QString lines = bout_status_text(m_bout, m_fps);
        lines += QString("orders: punch %1, kick %2, height %3 (J, K, H)\n")
                     .arg(or_any(k_punch_kinds[m_punch_kind]))
                     .arg(or_any(k_kick_kinds[m_kick_kind]))
                     .arg(or_any(k_heights[m_height]));
        lines += QString("%1 camera%2  |  %3%4")
                     .arg(m_view->projection() == Projection::orbit ? "orbit" : "head-coupled")
                     .arg(m_view->stereo() == StereoMode::mono ? "" : ", stereo side by side")
                     .arg(m_view->renderer_description())
                     .arg(m_paused ? "  |  PAUSED" : "");
        painter.save();
        QFont font = painter.font();
        font.setPointSizeF(10.0);
        painter.setFont(font);
        const QRect top(rect.left() + 10, rect.top() + 8, rect.width() - 20, 170);
        painter.setPen(QColor(0, 0, 0, 160));
        painter.drawText(top.translated(1, 1), Qt::AlignLeft | Qt::AlignTop, lines);
        painter.setPen(QColor(235, 238, 245));
        painter.drawText(top, Qt::AlignLeft | Qt::AlignTop, lines);
        QString log;
        for (const QString& line : m_log) log += line + "\n";
        const QRect right(rect.right() - 420, rect.top() + 8, 410, 120);
        painter.setPen(QColor(255, 220, 140));
        painter.drawText(right, Qt::AlignRight | Qt::AlignTop, log);
        const QRect bottom(rect.left() + 10, rect.bottom() - 60, rect.width() - 20, 56);
        painter.setPen(QColor(180, 190, 210));
        painter.drawText(bottom, Qt::AlignLeft | Qt::AlignBottom, k_help);
        painter.restore();
    }

    Bout& m_bout;
    PlayerRunOptions m_options;
    std::function<void()> m_after_step;
    SceneView* m_view = nullptr;
    QTimer m_timer;
    QElapsedTimer m_clock, m_fps_clock;
    double m_next_s = 0.0, m_paused_s = 0.0, m_last_wall_s = 0.0, m_fps = 0.0;
    int m_frames_drawn = 0;
    bool m_paused = false, m_closed = false;
    bool m_bodies = true, m_skeleton_overlay = false;
    int m_punch_kind = 0, m_kick_kind = 0, m_height = 0; // indices into k_punch_kinds, k_kick_kinds, k_heights
    std::deque<QString> m_log;
};

} // namespace

struct SupervisorWindow::Window : PlayerWindow {
    using PlayerWindow::PlayerWindow;
};

SupervisorWindow::SupervisorWindow(Bout& bout, const ViewerSettings& settings) {
    static const std::function<void()> nothing;
    m_window = std::make_unique<Window>(bout, settings, PlayerRunOptions{}, nothing, true);
    if (settings.fullscreen) m_window->showFullScreen();
    else m_window->show();
}
SupervisorWindow::~SupervisorWindow() = default;
void SupervisorWindow::after_step() { m_window->outside_step(); }
void SupervisorWindow::show_frame() {
    m_window->outside_frame();
    QApplication::processEvents();
}
bool SupervisorWindow::paused() const { return m_window->paused(); }
bool SupervisorWindow::closed() const { return m_window->closed(); }
bool SupervisorWindow::save(const std::string& path) { return m_window->save(path); }
std::string SupervisorWindow::renderer() const { return m_window->renderer(); }

int run_player_window(Bout& bout, const ViewerSettings& settings, const PlayerRunOptions& options, const std::function<void()>& after_step,
                      PlayerRunOutcome* outcome) {
    static int argc = 1;
    static char name[] = "kumite";
    static char* argv[] = {name, nullptr};
    QApplication application(argc, argv);
    PlayerWindow window(bout, settings, options, after_step);
    if (settings.fullscreen) window.showFullScreen();
    else window.show();
    application.exec();
    if (outcome) *outcome = window.outcome;
    return window.screenshot_failed ? 1 : 0;
}

} // namespace kumite::view
