#include "timeline_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace kumite::annotate {
namespace {

// The suggestion list's columns, the Accept button last.
enum SuggestionColumn {
    strike_column, kind_column, height_column, segment_column, hit_column, frames_column, confidence_column, accept_column
};

bool suggestion_accepted(const AnnotationDocument& document, const StrikeSuggestion& strike, const std::string& source) {
    for (int index = 0; index < document.clip_count(); ++index) {
        const RawAnnotatedClip& clip = document.clip(index);
        if (clip.source == source && clip.hit_frame == strike.hit_frame && clip.segment == strike.segment) return true;
    }
    return false;
}

} // namespace

TimelinePanel::TimelinePanel(AnnotationDocument& document, QWidget* parent) : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    m_capture = new QComboBox(this);
    m_capture->setObjectName(QStringLiteral("capture_selector"));
    m_capture->setToolTip(tr("The capture on show: every capture opened in this session"));
    m_capture->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_capture->setMaximumWidth(360);
    controls->addWidget(m_capture);
    auto add_button = [&](QStyle::StandardPixmap icon, const QString& tip) {
        auto* button = new QPushButton(style()->standardIcon(icon), QString(), this);
        button->setToolTip(tip);
        controls->addWidget(button);
        return button;
    };
    QPushButton* to_in = add_button(QStyle::SP_MediaSkipBackward, tr("Go to the in point"));
    QPushButton* back = add_button(QStyle::SP_MediaSeekBackward, tr("Step back one frame"));
    m_play = add_button(QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
    QPushButton* forward = add_button(QStyle::SP_MediaSeekForward, tr("Step forward one frame"));
    QPushButton* to_out = add_button(QStyle::SP_MediaSkipForward, tr("Go to the out point"));
    m_slider = new QSlider(Qt::Horizontal, this);
    controls->addWidget(m_slider, 1);
    m_readout = new QLabel(this);
    m_readout->setMinimumWidth(190);
    controls->addWidget(m_readout);
    layout->addLayout(controls);
    m_strip = new TimelineStrip(this);
    layout->addWidget(m_strip);

    m_suggestions = new QTreeWidget(this);
    m_suggestions->setObjectName(QStringLiteral("suggestion_list"));
    m_suggestions->setHeaderLabels({tr("Suggested strike"), tr("Kind"), tr("Height"), tr("Hit segment"), tr("Hit frame"), tr("Frames"),
                                    tr("Confidence"), QString()});
    m_suggestions->setRootIsDecorated(false);
    m_suggestions->header()->setStretchLastSection(false);
    m_suggestions->setMinimumHeight(80);
    layout->addWidget(m_suggestions);

    connect(to_in, &QPushButton::clicked, this, [this] { set_current_frame(play_range().first); });
    connect(to_out, &QPushButton::clicked, this, [this] { set_current_frame(play_range().second); });
    connect(back, &QPushButton::clicked, this, [this] { step(-1); });
    connect(forward, &QPushButton::clicked, this, [this] { step(1); });
    connect(m_play, &QPushButton::clicked, this, [this] { toggle_playing(); });
    connect(m_slider, &QSlider::valueChanged, this, [this](int frame) { set_current_frame(frame); });
    connect(m_strip, &TimelineStrip::scrubbed, this, [this](int frame) { set_current_frame(frame); });
    connect(m_strip, &TimelineStrip::handle_dragged, this, &TimelinePanel::on_handle_dragged);
    connect(&m_play_timer, &QTimer::timeout, this, &TimelinePanel::advance_playback);
    connect(m_suggestions, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item) return;
        m_preview = item->data(0, Qt::UserRole).toInt();
        if (m_document.selected_clip() >= 0) m_document.select_clip(-1); // a proposal and a clip are not shown together
        const LoadedCapture* capture = m_document.current_capture();
        if (capture && *m_preview < int(capture->suggestions.size())) set_current_frame(capture->suggestions[size_t(*m_preview)].hit_frame);
        emit preview_changed();
    });
    connect(m_capture, &QComboBox::activated, this,
            [this](int index) { m_document.set_current_source(m_capture->itemData(index).toString().toStdString()); });
    connect(&document, &AnnotationDocument::captures_changed, this, &TimelinePanel::rebuild_captures);
    connect(&document, &AnnotationDocument::current_capture_changed, this, &TimelinePanel::on_capture_changed);
    connect(&document, &AnnotationDocument::selection_changed, this, &TimelinePanel::on_selection_changed);
    connect(&document, &AnnotationDocument::clip_changed, this, &TimelinePanel::on_selection_changed);
    connect(&document, &AnnotationDocument::clips_reset, this, &TimelinePanel::rebuild_suggestions);
    rebuild_captures();
    on_capture_changed();
}

void TimelinePanel::rebuild_captures() {
    const QSignalBlocker block(m_capture);
    m_capture->clear();
    for (const auto& capture : m_document.captures().captures()) {
        const QString source = QString::fromStdString(capture->source);
        m_capture->addItem(QString::fromStdString(capture->path.filename().string()), source);
        m_capture->setItemData(m_capture->count() - 1, source, Qt::ToolTipRole);
    }
    const LoadedCapture* current = m_document.current_capture();
    m_capture->setCurrentIndex(current ? m_capture->findData(QString::fromStdString(current->source)) : -1);
}

void TimelinePanel::set_current_frame(int frame) {
    const LoadedCapture* capture = m_document.current_capture();
    const int frame_count = capture ? capture->file.clip.frame_count() : 0;
    frame = std::clamp(frame, 0, std::max(0, frame_count - 1));
    const bool changed = frame != m_frame;
    m_frame = frame;
    const QSignalBlocker block(m_slider);
    m_slider->setValue(frame);
    m_strip->set_current_frame(frame);
    update_readout();
    if (changed) emit frame_changed(frame);
}

void TimelinePanel::toggle_playing() {
    const LoadedCapture* capture = m_document.current_capture();
    if (m_play_timer.isActive() || !capture) {
        m_play_timer.stop();
    } else {
        // A capture without a rate plays at 100 fps until the animator gives one (Edit > Capture Frame Rate).
        const double frame_time_s = capture->file.clip.has_frame_rate() ? capture->file.clip.frame_time_s : 0.01;
        m_play_timer.start(std::max(1, int(frame_time_s * 1000.0)));
    }
    m_play->setIcon(style()->standardIcon(m_play_timer.isActive() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void TimelinePanel::step(int frames) { set_current_frame(m_frame + frames); }

std::pair<int, int> TimelinePanel::play_range() const {
    if (const int selected = m_document.selected_clip(); selected >= 0) {
        return {m_document.clip(selected).first_frame, m_document.clip(selected).last_frame};
    }
    const LoadedCapture* capture = m_document.current_capture();
    return {0, capture ? std::max(0, capture->file.clip.frame_count() - 1) : 0};
}

void TimelinePanel::advance_playback() {
    const auto [first, last] = play_range();
    set_current_frame(m_frame >= last || m_frame < first ? first : m_frame + 1);
}

void TimelinePanel::on_capture_changed() {
    const LoadedCapture* capture = m_document.current_capture();
    {
        const QSignalBlocker block(m_capture);
        m_capture->setCurrentIndex(capture ? m_capture->findData(QString::fromStdString(capture->source)) : -1);
    }
    const int frame_count = capture ? capture->file.clip.frame_count() : 0;
    m_slider->setRange(0, std::max(0, frame_count - 1));
    m_strip->set_frame_count(frame_count);
    m_preview.reset();
    rebuild_suggestions();
    if (m_document.selected_clip() < 0 && capture && !capture->suggestions.empty()) {
        m_suggestions->setCurrentItem(m_suggestions->topLevelItem(0)); // previews it and moves to its hit
    } else {
        if (m_document.selected_clip() < 0) set_current_frame(0); // frames of another capture mean nothing here
        on_selection_changed();
    }
    emit preview_changed();
}

void TimelinePanel::on_selection_changed() {
    const int selected = m_document.selected_clip();
    if (selected < 0) {
        m_strip->set_trim(std::nullopt, -1);
        update_readout();
        return;
    }
    const RawAnnotatedClip& clip = m_document.clip(selected);
    m_strip->set_trim(std::pair{clip.first_frame, clip.last_frame}, clip.hit_frame.value_or(-1));
    if (m_preview) {
        m_preview.reset();
        const QSignalBlocker block(m_suggestions);
        m_suggestions->setCurrentItem(nullptr);
        emit preview_changed();
    }
    if (m_frame < clip.first_frame || m_frame > clip.last_frame) set_current_frame(clip.hit_frame.value_or(clip.first_frame));
    update_readout();
}

void TimelinePanel::on_handle_dragged(TimelineHandle handle, int frame, int drag_session) {
    const int selected = m_document.selected_clip();
    if (selected < 0) return;
    RawAnnotatedClip clip = m_document.clip(selected);
    ClipField field = ClipField::other;
    // Handles stop at each other: in <= hit <= out always holds after a drag.
    switch (handle) {
    case TimelineHandle::in_point:
        clip.first_frame = std::min(frame, clip.hit_frame.value_or(clip.last_frame));
        field = ClipField::first_frame;
        break;
    case TimelineHandle::out_point:
        clip.last_frame = std::max(frame, clip.hit_frame.value_or(clip.first_frame));
        field = ClipField::last_frame;
        break;
    case TimelineHandle::hit_frame:
        clip.hit_frame = std::clamp(frame, clip.first_frame, clip.last_frame);
        field = ClipField::hit_frame;
        break;
    }
    m_document.edit_clip(selected, clip, field, drag_session);
    set_current_frame(field == ClipField::first_frame ? clip.first_frame
                      : field == ClipField::last_frame ? clip.last_frame : *clip.hit_frame);
}

void TimelinePanel::rebuild_suggestions() {
    const QSignalBlocker block(m_suggestions);
    m_suggestions->clear();
    const LoadedCapture* capture = m_document.current_capture();
    std::vector<std::pair<int, int>> spans;
    if (capture) {
        for (size_t index = 0; index < capture->suggestions.size(); ++index) {
            const StrikeSuggestion& strike = capture->suggestions[index];
            spans.emplace_back(strike.first_frame, strike.last_frame);
            auto* item = new QTreeWidgetItem(m_suggestions);
            item->setText(strike_column, QString::fromLatin1(strike_semantics_name(strike.semantics)) + " " +
                                             (strike.side == Side::left ? tr("left") : tr("right")));
            item->setText(kind_column, QString::fromLatin1(strike_kind_name(strike.labels.kind)));
            item->setText(height_column, QString::fromLatin1(strike_height_name(strike.labels.height)));
            item->setText(segment_column,
                          QString::fromLatin1(body_part_name(strike.segment).data(), qsizetype(body_part_name(strike.segment).size())));
            item->setText(hit_column, QString::number(strike.hit_frame));
            item->setText(frames_column, QStringLiteral("%1-%2").arg(strike.first_frame).arg(strike.last_frame));
            item->setText(confidence_column, QString::number(strike.confidence, 'f', 2));
            item->setData(strike_column, Qt::UserRole, int(index));
            const bool accepted = suggestion_accepted(m_document, strike, capture->source);
            auto* accept = new QPushButton(accepted ? tr("Accepted") : tr("Accept"), m_suggestions);
            accept->setEnabled(!accepted);
            accept->setToolTip(tr("Add this strike to the file as a clip (mirrored too), with its proposed kind and height"));
            const std::string source = capture->source;
            // Once only: the list is rebuilt right after, and the old buttons linger until deleted later.
            connect(accept, &QPushButton::clicked, this, [this, strike, source] {
                if (!suggestion_accepted(m_document, strike, source)) m_document.add_suggestion(strike, source);
            });
            m_suggestions->setItemWidget(item, accept_column, accept);
            if (m_preview && *m_preview == int(index)) m_suggestions->setCurrentItem(item);
        }
    }
    for (int column = 0; column < accept_column; ++column) m_suggestions->resizeColumnToContents(column);
    m_strip->set_spans(std::move(spans));
}

void TimelinePanel::update_readout() {
    const LoadedCapture* capture = m_document.current_capture();
    if (!capture) {
        m_readout->setText(tr("no capture"));
        return;
    }
    const int frame_count = capture->file.clip.frame_count();
    const double frame_time = capture->file.clip.frame_time_s;
    if (!capture->file.clip.has_frame_rate()) {
        m_readout->setText(tr("frame %1 / %2   (no frame rate: Edit > Capture Frame Rate)").arg(m_frame).arg(std::max(0, frame_count - 1)));
        return;
    }
    m_readout->setText(tr("frame %1 / %2   %3 s").arg(m_frame).arg(std::max(0, frame_count - 1)).arg(m_frame * frame_time, 0, 'f', 3));
}

} // namespace kumite::annotate
