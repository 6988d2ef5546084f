#include "preview_panel.h"

#include "bake.h"
#include "player_scene.h"
#include "scene_geometry.h"
#include "scene_view.h"
#include "strike_filmstrip.h"

#include "kumite/core/retrieval.h"
#include "kumite/formats/character_body.h"
#include "kumite/formats/character_catalog.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

namespace kumite::annotate {

struct PreviewPanel::Character {
    std::string name;
    BvhFile file;
    std::shared_ptr<const SkinnedMesh> body; // drawn skinned where OpenGL is; null without a body
    RestAnatomy anatomy;
    std::unique_ptr<CharacterRig> rig;
};

// The selected clip baked alone, and what it was baked from (to bake again only when that changes).
struct PreviewPanel::Baked {
    RawAnnotatedClip clip;
    std::optional<double> fps; // the capture's rate given in the annotation file, if any
    MotionDatabaseContent database;
};

namespace {

constexpr int k_lead_frames = 6;

} // namespace

PreviewPanel::PreviewPanel(AnnotationDocument& document, QWidget* parent) : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    m_characters = new QComboBox(this);
    m_characters->setToolTip(tr("The shipped character the clip is played on"));
    for (const CharacterEntry& entry : list_characters(default_characters_dir())) m_characters->addItem(QString::fromStdString(entry.name));
    controls->addWidget(new QLabel(tr("Character"), this));
    controls->addWidget(m_characters);
    const char* axes[3] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        m_xyz[axis] = new QDoubleSpinBox(this);
        m_xyz[axis]->setRange(-5.0, 5.0);
        m_xyz[axis]->setDecimals(3);
        m_xyz[axis]->setSingleStep(0.02);
        m_xyz[axis]->setSuffix(" m");
        m_xyz[axis]->setToolTip(tr("The target, world metres (the character stands at the origin facing +Z); Shift+drag it in the view"));
        controls->addWidget(new QLabel(axes[axis], this));
        controls->addWidget(m_xyz[axis]);
        connect(m_xyz[axis], &QDoubleSpinBox::valueChanged, this, [this] {
            if (m_dragging) return;
            set_target(Eigen::Vector3d(m_xyz[0]->value(), m_xyz[1]->value(), m_xyz[2]->value()));
        });
    }
    layout->addLayout(controls);
    m_view = new view::SceneView(this);
    m_view->setMinimumSize(240, 240);
    m_view->installEventFilter(this);
    layout->addWidget(m_view, 1);
    auto* buttons = new QHBoxLayout;
    m_play = new QPushButton(tr("Pause"), this);
    m_natural = new QPushButton(tr("Natural Hit"), this);
    m_natural->setToolTip(tr("Put the target where the clip's own hit lands on this character"));
    m_filmstrip = new QPushButton(tr("Save Filmstrip..."), this);
    buttons->addWidget(m_play);
    buttons->addWidget(m_natural);
    buttons->addStretch(1);
    buttons->addWidget(m_filmstrip);
    layout->addLayout(buttons);
    m_figures = new QLabel(this);
    m_figures->setWordWrap(true);
    m_figures->setMinimumHeight(4 * m_figures->fontMetrics().lineSpacing());
    m_figures->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_figures);

    m_rebuild_timer = new QTimer(this);
    m_rebuild_timer->setSingleShot(true);
    m_rebuild_timer->setInterval(250); // a handle drag edits many times: bake once it settles
    connect(m_rebuild_timer, &QTimer::timeout, this, &PreviewPanel::rebuild);
    m_play_timer = new QTimer(this);
    m_play_timer->setInterval(33);
    connect(m_play_timer, &QTimer::timeout, this, [this] {
        if (!m_playback) return;
        m_frame = (m_frame + 1) % std::max(1, m_playback->motion.frame_count() + 15); // a short hold at the end
        show_frame();
    });
    connect(m_play, &QPushButton::clicked, this, [this] {
        if (m_play_timer->isActive()) m_play_timer->stop();
        else m_play_timer->start();
        m_play->setText(m_play_timer->isActive() ? tr("Pause") : tr("Play"));
    });
    connect(m_natural, &QPushButton::clicked, this, &PreviewPanel::put_target_at_natural_hit);
    connect(m_filmstrip, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Filmstrip"), "filmstrip.png", tr("PNG images (*.png)"));
        QString error;
        if (!path.isEmpty() && !save_filmstrip(path, &error)) m_document.report_error(error.toStdString(), path);
    });
    // Another character or clip starts at its natural hit; edits of the clip keep the target where it is.
    connect(m_characters, &QComboBox::currentTextChanged, this, [this] {
        m_character.reset();
        m_framed = false;
        m_target_at_natural_hit = true;
        rebuild();
    });
    connect(&m_document, &AnnotationDocument::selection_changed, this, [this] {
        m_framed = false;
        m_target_at_natural_hit = true;
        schedule_rebuild();
    });
    connect(&m_document, &AnnotationDocument::clip_changed, this, [this](int index) {
        if (index == m_document.selected_clip()) schedule_rebuild();
    });
    connect(&m_document, &AnnotationDocument::clips_reset, this, &PreviewPanel::schedule_rebuild);
    m_play_timer->start();
    show_message(tr("Select a strike clip (with its hit segment and hit frame) to see it on a character."));
}

PreviewPanel::~PreviewPanel() = default;

QString PreviewPanel::status_text() const { return m_figures->text(); }
Eigen::Vector3d PreviewPanel::target() const { return m_target; }

QStringList PreviewPanel::character_names() const {
    QStringList names;
    for (int i = 0; i < m_characters->count(); ++i) names << m_characters->itemText(i);
    return names;
}

void PreviewPanel::set_character(const QString& name) { m_characters->setCurrentText(name); }

void PreviewPanel::schedule_rebuild() { m_rebuild_timer->start(); }

void PreviewPanel::rebuild_now() {
    m_rebuild_timer->stop();
    rebuild();
}

void PreviewPanel::show_message(const QString& text) {
    m_playback.reset();
    m_view->scene().clear();
    m_view->update();
    m_figures->setText(text);
    m_filmstrip->setEnabled(false);
}

bool PreviewPanel::load_character() {
    const std::string name = m_characters->currentText().toStdString();
    if (m_character && m_character->name == name) return true;
    m_character.reset();
    Result<BvhFile> file = kumite::load_character(default_characters_dir(), name);
    if (!file) {
        show_message(tr("No character to preview on: %1").arg(QString::fromStdString(file.error().message)));
        return false;
    }
    auto character = std::make_unique<Character>();
    character->name = name;
    character->file = std::move(*file);
    Result<RestAnatomy> anatomy = rest_anatomy_build(character->file.clip, character->file.body_map);
    if (!anatomy) {
        show_message(tr("Character %1: %2").arg(QString::fromStdString(name), QString::fromStdString(anatomy.error().message)));
        return false;
    }
    character->anatomy = std::move(*anatomy);
    character->rig = std::make_unique<CharacterRig>(character->file.clip.skeleton, character->anatomy);
    // Its body, when it has one; a body that does not fit is left out (the capsules still show the strike).
    if (Result<std::optional<SkinnedMesh>> body = load_character_body(default_characters_dir(), name, character->file.clip.skeleton); body && *body) {
        character->body = std::make_shared<const SkinnedMesh>(std::move(**body));
    }
    m_character = std::move(character);
    return true;
}

void PreviewPanel::rebuild() {
    const int selected = m_document.selected_clip();
    if (selected < 0 || selected >= m_document.clip_count()) return show_message(tr("Select a strike clip to see it on a character."));
    RawAnnotatedClip clip = m_document.clip(selected);
    if (!clip.is_strike() || !clip.segment || !clip.hit_frame) {
        return show_message(tr("%1 is not a strike with a hit segment and a hit frame: nothing to preview.").arg(QString::fromStdString(clip.name)));
    }
    clip.mirror = false;
    if (!load_character()) return;
    const std::optional<double> fps = m_document.capture_fps(clip.source);
    if (!m_baked || !clips_equal(m_baked->clip, clip) || m_baked->fps != fps) {
        RawAnnotations alone;
        alone.clips.push_back(clip);
        if (fps) alone.capture_fps[clip.source] = *fps;
        bake::BakeOptions options;
        options.mocap_root = m_document.captures().mocap_root();
        options.clusters = 1;
        options.jobs = 1;
        Result<bake::BakeResult> baked = bake::bake_database(alone, "preview", options);
        if (!baked) return show_message(tr("Cannot preview %1: %2").arg(QString::fromStdString(clip.name), QString::fromStdString(baked.error().message)));
        m_baked = std::make_unique<Baked>(Baked{clip, fps, std::move(baked->database)});
    }
    // The clip's own hit on this character: its hit frame decoded on the character (through the MIR, as the
    // strike is), from its first frame placed at the origin facing +Z; the limb's extremity there.
    const MotionDatabaseView db = m_baked->database.view();
    const DbClip& record = db.clips[0];
    const FloorAlignment placed = clip_alignment(db, 0, 0, m_character->anatomy.leg_length, HeadingFrame{});
    Pose at_hit;
    m_character->rig->decode(at_hit, db, record.first_pose + record.hit_frame, placed);
    m_character->rig->measure(at_hit.view());
    const int limb = limb_of_segment(*clip.segment);
    m_natural_hit = m_character->rig->positions()[m_character->anatomy.limbs[limb].extremity];
    if (m_target_at_natural_hit || !m_playback) m_target = m_natural_hit;
    m_target_at_natural_hit = false;
    replay();
}

void PreviewPanel::replay() {
    if (!m_baked || !m_character) return;
    const MotionDatabaseView db = m_baked->database.view();
    const double leg = m_character->anatomy.leg_length;
    const FloorAlignment placed = clip_alignment(db, 0, 0, leg, HeadingFrame{});
    Pose standing;
    m_character->rig->decode(standing, db, db.clips[0].first_pose, placed);
    const StrikePlan plan{0, 0, db.clips[0].hit_frame, placed, m_target};
    m_playback = std::make_unique<StrikePlayback>(strike_playback_run(*m_character->rig, db, standing, plan, k_lead_frames));
    const StrikePlayback& p = *m_playback;
    const char* reach = p.reach_at_contact == Reach::limb ? "the limb" : p.reach_at_contact == Reach::torso ? "limb and trunk" : "out of reach";
    m_figures->setText(tr("%1 on %2: contact at frame %3 (%4), error %5 mm, %6 mm past the target after it, %7 m/s at contact, "
                          "%8 joint-limit violations, support foot drift %9 mm")
                           .arg(QString::fromStdString(m_baked->clip.name), QString::fromStdString(m_character->name))
                           .arg(p.contact_frame)
                           .arg(reach)
                           .arg(1000.0 * p.contact_error_m, 0, 'f', 1)
                           .arg(1000.0 * p.overshoot_m, 0, 'f', 1)
                           .arg(p.effector_speed_at_contact_mps, 0, 'f', 2)
                           .arg(p.joint_limit_violations)
                           .arg(1000.0 * p.foot_drift_m, 0, 'f', 1));
    m_filmstrip->setEnabled(true);
    update_target_boxes();
    m_frame = std::min(m_frame, p.motion.frame_count() - 1);
    show_frame();
    if (!m_framed) {
        m_framed = true;
        m_view->frame_scene();
    }
    emit replayed();
}

void PreviewPanel::show_frame() {
    if (!m_playback) return;
    const int frame = std::clamp(m_frame, 0, m_playback->motion.frame_count() - 1);
    view::Scene& scene = m_view->scene();
    view::strike_frame_scene(*m_playback, frame, 0, scene);
    if (m_character && m_character->body) {
        view::add_skinned_body(scene, m_character->body, m_playback->motion.skeleton, m_playback->motion.pose(frame));
        for (view::Capsule& capsule : scene.capsules) capsule.of_body = true; // the character's bones: QPainter draws them
    }
    m_view->update();
}

void PreviewPanel::seek(int frame) {
    m_frame = frame;
    show_frame();
}

void PreviewPanel::pause() {
    m_play_timer->stop();
    m_play->setText(tr("Play"));
}

void PreviewPanel::update_target_boxes() {
    for (int axis = 0; axis < 3; ++axis) {
        const QSignalBlocker blocker(m_xyz[axis]);
        m_xyz[axis]->setValue(m_target[axis]);
    }
}

void PreviewPanel::set_target(const Eigen::Vector3d& target_world) {
    m_target = target_world;
    replay();
}

void PreviewPanel::put_target_at_natural_hit() { set_target(m_natural_hit); }

bool PreviewPanel::save_filmstrip(const QString& path, QString* error) const {
    if (!m_playback) {
        if (error) *error = tr("nothing to draw: no strike is previewed");
        return false;
    }
    const Result<void> saved = view::strike_filmstrip_save(*m_playback, QString::fromStdString(m_baked->clip.name + " on " + m_character->name),
                                                           path.toStdString());
    if (!saved && error) *error = QString::fromStdString(saved.error().message);
    return saved.has_value();
}

bool PreviewPanel::eventFilter(QObject* watched, QEvent* event) {
    // Shift+left drag moves the target in the plane through it that faces the camera; everything else is the
    // view's (orbit, pan, zoom).
    if (watched != m_view || !m_playback) return QWidget::eventFilter(watched, event);
    const auto* mouse = dynamic_cast<QMouseEvent*>(event);
    if (!mouse) return QWidget::eventFilter(watched, event);
    if (event->type() == QEvent::MouseButtonPress && mouse->button() == Qt::LeftButton && (mouse->modifiers() & Qt::ShiftModifier)) {
        m_dragging = true;
        return true;
    }
    if (event->type() == QEvent::MouseMove && m_dragging) {
        const QPointF at = mouse->position();
        const Eigen::Vector2f ndc(float(2.0 * at.x() / std::max(1, m_view->width()) - 1.0), float(1.0 - 2.0 * at.y() / std::max(1, m_view->height())));
        const view::ViewProjection vp = m_view->view_projection(float(m_view->width()) / float(std::max(1, m_view->height())));
        Eigen::Vector3f moved;
        if (view::point_on_facing_plane(vp, ndc, m_target.cast<float>(), moved)) set_target(moved.cast<double>());
        return true;
    }
    if (event->type() == QEvent::MouseButtonRelease && m_dragging) {
        m_dragging = false;
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace kumite::annotate
