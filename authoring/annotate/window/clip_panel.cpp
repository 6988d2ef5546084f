#include "clip_panel.h"

#include "clip_labels.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>
#include <filesystem>

namespace kumite::annotate {
namespace {

const QStringList k_semantics = {"punch", "kick", "knee", "elbow", "block", "reach", "rest", "step_forward", "step_back", "step_left", "step_right", "hit_reaction"};
int g_next_spin_session = 1'000'000; // apart from the timeline's drag sessions

QString part_text(BodyPart part) {
    const std::string_view name = body_part_name(part);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

} // namespace

ClipPanel::ClipPanel(AnnotationDocument& document, QWidget* parent) : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("clip_list"));
    layout->addWidget(m_list, 1);
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add Clip"), this);
    add->setToolTip(tr("A new clip of the current capture around the current frame"));
    m_remove = new QPushButton(tr("Remove Clip"), this);
    buttons->addWidget(add);
    buttons->addWidget(m_remove);
    layout->addLayout(buttons);

    m_fields = new QWidget(this);
    auto* form = new QFormLayout(m_fields);
    m_name = new QLineEdit(m_fields);
    m_source = new QLabel(m_fields);
    m_source->setWordWrap(true);
    m_semantics = new QComboBox(m_fields);
    m_semantics->setObjectName(QStringLiteral("clip_semantics"));
    m_semantics->setEditable(true); // other lower-case semantics are allowed by the file format
    m_semantics->addItems(k_semantics);
    m_side = new QComboBox(m_fields);
    m_side->addItems({tr("none"), tr("left"), tr("right")});
    m_kind = new QComboBox(m_fields);
    m_kind->setObjectName(QStringLiteral("clip_kind"));
    m_kind->setToolTip(tr("The strike's kind: only those of its semantics (a hook is a punch); none leaves it unlabelled"));
    m_height = new QComboBox(m_fields);
    m_height->setObjectName(QStringLiteral("clip_height"));
    for (int height = 0; height < k_strike_height_count; ++height) {
        m_height->addItem(QString::fromLatin1(strike_height_name(static_cast<StrikeHeight>(height))));
    }
    m_height->setToolTip(tr("Where the strike lands: low below the hip, high above the shoulder; none: unlabelled"));
    m_segment = new QComboBox(m_fields);
    m_segment->addItem(tr("(none)"));
    for (int part = 0; part < k_body_part_count; ++part) m_segment->addItem(part_text(static_cast<BodyPart>(part)));
    m_segment->setToolTip(tr("The hit body part; or click a bone in the viewport"));
    m_first = new QSpinBox(m_fields);
    m_last = new QSpinBox(m_fields);
    m_hit = new QSpinBox(m_fields);
    m_hit->setSpecialValueText(tr("(none)"));
    m_mirror = new QCheckBox(tr("also bake the mirrored clip"), m_fields);
    m_messages = new QLabel(m_fields);
    m_messages->setWordWrap(true);
    m_messages->setStyleSheet(QStringLiteral("color: #d04040;"));
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Capture"), m_source);
    form->addRow(tr("Semantics"), m_semantics);
    form->addRow(tr("Side"), m_side);
    form->addRow(tr("Kind"), m_kind);
    form->addRow(tr("Height"), m_height);
    form->addRow(tr("Hit segment"), m_segment);
    form->addRow(tr("In frame"), m_first);
    form->addRow(tr("Out frame"), m_last);
    auto* hit_row = new QHBoxLayout;
    hit_row->addWidget(m_hit, 1);
    auto* suggest_hit = new QPushButton(tr("Suggest"), m_fields);
    suggest_hit->setToolTip(tr("Put the hit frame at the hit segment's extension peak inside the trim range"));
    hit_row->addWidget(suggest_hit);
    form->addRow(tr("Hit frame"), hit_row);
    form->addRow(QString(), m_mirror);
    form->addRow(m_messages);
    layout->addWidget(m_fields);

    connect(add, &QPushButton::clicked, this, [this] { add_clip_at(-1); });
    connect(m_remove, &QPushButton::clicked, this, [this] { m_document.remove_clip(m_document.selected_clip()); });
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row != m_document.selected_clip()) m_document.select_clip(row);
    });
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        edit(ClipField::name, [this](RawAnnotatedClip& clip) { clip.name = m_name->text().trimmed().toStdString(); });
    });
    // Typing in the editable box would make a step per key: the value counts once chosen or typed out. A kind
    // the new semantics does not allow goes in the same step (punch -> kick turns a hook into none).
    auto apply_semantics = [this] {
        const std::string text = m_semantics->currentText().trimmed().toStdString();
        edit(ClipField::semantics, [&](RawAnnotatedClip& clip) { clip = clip_with_semantics(std::move(clip), text); });
    };
    connect(m_semantics, &QComboBox::textActivated, this, apply_semantics);
    connect(m_semantics->lineEdit(), &QLineEdit::editingFinished, this, apply_semantics);
    connect(m_side, &QComboBox::currentIndexChanged, this, [this](int index) {
        edit(ClipField::side, [&](RawAnnotatedClip& clip) { clip.side = static_cast<Side>(index); });
    });
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index < 0) return;
        const auto kind = static_cast<StrikeKind>(m_kind->itemData(index).toInt());
        edit(ClipField::kind, [&](RawAnnotatedClip& clip) { clip.kind = kind; });
    });
    connect(m_height, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index < 0) return;
        edit(ClipField::height, [&](RawAnnotatedClip& clip) { clip.height = static_cast<StrikeHeight>(index); });
    });
    connect(m_segment, &QComboBox::currentIndexChanged, this, [this](int index) {
        edit(ClipField::segment, [&](RawAnnotatedClip& clip) {
            clip.segment = index <= 0 ? std::nullopt : std::optional<BodyPart>(static_cast<BodyPart>(index - 1));
        });
    });
    auto connect_spin = [this](QSpinBox* spin, ClipField field, auto apply) {
        connect(spin, &QSpinBox::valueChanged, this, [this, field, apply](int value) {
            edit(field, [&](RawAnnotatedClip& clip) { apply(clip, value); }, m_spin_session);
        });
        connect(spin, &QSpinBox::editingFinished, this, [this] { m_spin_session = g_next_spin_session++; });
    };
    m_spin_session = g_next_spin_session++;
    connect_spin(m_first, ClipField::first_frame, [](RawAnnotatedClip& clip, int value) { clip.first_frame = value; });
    connect_spin(m_last, ClipField::last_frame, [](RawAnnotatedClip& clip, int value) { clip.last_frame = value; });
    connect_spin(m_hit, ClipField::hit_frame, [](RawAnnotatedClip& clip, int value) {
        clip.hit_frame = value < 0 ? std::nullopt : std::optional<int>(value);
    });
    connect(suggest_hit, &QPushButton::clicked, this, [this] { suggest_hit_frame(); });
    connect(m_mirror, &QCheckBox::toggled, this, [this](bool on) { edit(ClipField::mirror, [&](RawAnnotatedClip& clip) { clip.mirror = on; }); });

    connect(&document, &AnnotationDocument::clips_reset, this, &ClipPanel::rebuild_list);
    connect(&document, &AnnotationDocument::clip_changed, this, [this](int index) {
        refresh_list_item(index);
        refresh_fields();
    });
    connect(&document, &AnnotationDocument::selection_changed, this, [this](int index) {
        const QSignalBlocker block(m_list);
        m_list->setCurrentRow(index);
        m_spin_session = g_next_spin_session++;
        refresh_fields();
    });
    connect(&document, &AnnotationDocument::captures_changed, this, &ClipPanel::rebuild_list);
    rebuild_list();
}

void ClipPanel::add_clip_at(int frame) {
    const LoadedCapture* capture = m_document.current_capture();
    if (!capture) return;
    const int last_frame = std::max(0, capture->file.clip.frame_count() - 1);
    const int around = frame < 0 ? last_frame / 2 : std::clamp(frame, 0, last_frame);
    // Half a second each way (50 frames when the capture has no rate).
    const int half_span = capture->file.clip.has_frame_rate() ? std::max(1, int(0.5 / capture->file.clip.frame_time_s)) : 50;
    RawAnnotatedClip clip;
    clip.source = capture->source;
    clip.name = std::filesystem::path(capture->source).stem().string() + "_clip";
    clip.first_frame = std::max(0, around - half_span);
    clip.last_frame = std::min(last_frame, around + half_span);
    clip.semantics = "rest"; // valid as it is; the animator turns it into a strike by picking semantics
    m_document.add_clip(std::move(clip));
}

void ClipPanel::suggest_hit_frame() {
    const int selected = m_document.selected_clip();
    if (selected < 0) return;
    const RawAnnotatedClip& clip = m_document.clip(selected);
    const LoadedCapture* capture = m_document.capture_of(selected);
    if (!clip.segment || !capture) {
        m_messages->setText(tr("Choose the hit segment first (click a bone in the viewport)."));
        return;
    }
    const std::optional<int> hit = hit_frame_suggest(*capture, *clip.segment, clip.first_frame, clip.last_frame);
    if (!hit) {
        m_messages->setText(tr("No extension peak of %1 inside %2-%3.").arg(part_text(*clip.segment)).arg(clip.first_frame).arg(clip.last_frame));
        return;
    }
    edit(ClipField::hit_frame, [&](RawAnnotatedClip& changed) { changed.hit_frame = *hit; });
}

void ClipPanel::edit(ClipField field, const std::function<void(RawAnnotatedClip&)>& change, int session) {
    const int selected = m_document.selected_clip();
    if (selected < 0) return;
    RawAnnotatedClip clip = m_document.clip(selected);
    change(clip);
    m_document.edit_clip(selected, clip, field, session);
}

void ClipPanel::rebuild_list() {
    const QSignalBlocker block(m_list);
    m_list->clear();
    for (int index = 0; index < m_document.clip_count(); ++index) {
        m_list->addItem(QString());
        refresh_list_item(index);
    }
    m_list->setCurrentRow(m_document.selected_clip());
    refresh_fields();
}

void ClipPanel::refresh_list_item(int index) {
    QListWidgetItem* item = m_list->item(index);
    if (!item) return;
    const RawAnnotatedClip& clip = m_document.clip(index);
    const bool fine = m_document.clip_messages(index).empty();
    item->setText(QString::fromStdString(clip.name) + QStringLiteral("  (%1, %2-%3)")
                                                          .arg(clip_labels_text(clip))
                                                          .arg(clip.first_frame)
                                                          .arg(clip.last_frame));
    item->setIcon(style()->standardIcon(fine ? QStyle::SP_DialogApplyButton : QStyle::SP_MessageBoxWarning));
}

void ClipPanel::refresh_fields() {
    const int selected = m_document.selected_clip();
    m_fields->setEnabled(selected >= 0);
    m_remove->setEnabled(selected >= 0);
    if (selected < 0) { // empty fields: nothing to suggest a value that is not there
        const QSignalBlocker b1(m_name), b2(m_semantics), b3(m_side), b4(m_segment);
        m_name->clear();
        m_source->clear();
        m_semantics->setCurrentIndex(-1);
        m_side->setCurrentIndex(-1);
        m_segment->setCurrentIndex(-1);
        refresh_labels(nullptr);
        m_messages->clear();
        return;
    }
    const RawAnnotatedClip& clip = m_document.clip(selected);
    const LoadedCapture* capture = m_document.capture_of(selected);
    const int max_frame = capture ? std::max(0, capture->file.clip.frame_count() - 1) : 1'000'000;
    const QSignalBlocker b1(m_name), b2(m_semantics), b3(m_side), b4(m_segment), b5(m_first), b6(m_last), b7(m_hit), b8(m_mirror);
    m_name->setText(QString::fromStdString(clip.name));
    m_source->setText(QString::fromStdString(clip.source));
    m_semantics->setCurrentText(QString::fromStdString(clip.semantics));
    m_side->setCurrentIndex(static_cast<int>(clip.side));
    m_segment->setCurrentIndex(clip.segment ? static_cast<int>(*clip.segment) + 1 : 0);
    refresh_labels(&clip);
    m_first->setRange(0, max_frame);
    m_last->setRange(0, max_frame);
    m_hit->setRange(-1, max_frame);
    m_first->setValue(clip.first_frame);
    m_last->setValue(clip.last_frame);
    m_hit->setValue(clip.hit_frame.value_or(-1));
    m_mirror->setChecked(clip.mirror);
    QStringList messages;
    for (const std::string& message : m_document.clip_messages(selected)) messages << QString::fromStdString(message);
    m_messages->setText(messages.join(QStringLiteral("\n")));
}

// The kind box holds the kinds of the clip's semantics, which an edit may have changed; a kind the file holds that
// does not fit stays listed so that it shows (the messages say what is wrong).
void ClipPanel::refresh_labels(const RawAnnotatedClip* clip) {
    const QSignalBlocker b1(m_kind), b2(m_height);
    const bool strike = clip && clip->is_strike();
    m_kind->setEnabled(strike);
    m_height->setEnabled(strike);
    if (!clip) {
        m_kind->clear();
        m_height->setCurrentIndex(-1);
        return;
    }
    std::vector<StrikeKind> kinds = strike_kinds_offered(clip->semantics);
    if (std::find(kinds.begin(), kinds.end(), clip->kind) == kinds.end()) kinds.push_back(clip->kind);
    bool same_items = m_kind->count() == int(kinds.size());
    for (int index = 0; same_items && index < m_kind->count(); ++index) {
        same_items = m_kind->itemData(index).toInt() == static_cast<int>(kinds[size_t(index)]);
    }
    if (!same_items) { // rebuilt only when the list changes: this runs inside the box's own change signal too
        m_kind->clear();
        for (StrikeKind kind : kinds) m_kind->addItem(QString::fromLatin1(strike_kind_name(kind)), static_cast<int>(kind));
    }
    m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(clip->kind)));
    m_height->setCurrentIndex(static_cast<int>(clip->height));
}

} // namespace kumite::annotate
