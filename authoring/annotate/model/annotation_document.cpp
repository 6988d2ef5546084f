#include "annotation_document.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <set>

namespace kumite::annotate {

AnnotationDocument::AnnotationDocument(std::filesystem::path mocap_root, QObject* parent)
    : QObject(parent), m_captures(std::move(mocap_root)) {
    connect(&m_undo_stack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit dirty_changed(!clean); });
}

QString AnnotationDocument::display_name() const {
    return m_file_path.isEmpty() ? tr("untitled") : QFileInfo(m_file_path).fileName();
}

Result<void> AnnotationDocument::open_annotations(const QString& path) {
    Result<RawAnnotations> read = annotations_read_file(path.toStdString());
    if (!read) return read.error();
    m_undo_stack.clear();
    m_annotations = std::move(*read);
    m_file_path = path;
    m_selected_clip = -1;
    m_current_source.clear();
    load_clip_captures();
    emit clips_reset();
    emit file_path_changed(m_file_path);
    emit dirty_changed(false);
    if (clip_count() > 0) select_clip(0);
    return {};
}

void AnnotationDocument::load_clip_captures() {
    std::set<std::string> sources;
    for (const RawAnnotatedClip& clip : m_annotations.clips) sources.insert(clip.source);
    for (const std::string& source : sources) {
        const bool known = m_captures.find(source) != nullptr;
        Result<const LoadedCapture*> loaded = m_captures.load(source, capture_fps(source));
        if (!loaded) report_error(loaded.error().message, QString::fromStdString(source));
        else if (!known) report_capture_warnings(**loaded, {});
    }
    emit captures_changed();
}

void AnnotationDocument::report_capture_warnings(const LoadedCapture& capture, const QString& fallback_file) {
    // What the reader tolerated ("file:line: ..."), then a body map too poor for trajectories.
    for (const std::string& warning : capture.file.warnings) report(issue_from_message(warning, fallback_file, IssueSeverity::warning));
    if (!capture.anatomy) report(issue_from_message(capture.anatomy_error, fallback_file, IssueSeverity::warning));
}

Result<void> AnnotationDocument::open_capture(const QString& path) {
    const bool known = m_captures.find(path.toStdString()) != nullptr;
    const std::string source = source_relative_to_root(m_captures.resolve(path.toStdString()), m_captures.mocap_root());
    Result<const LoadedCapture*> loaded = m_captures.load(path.toStdString(), capture_fps(source));
    if (!loaded) return loaded.error();
    if (!known) report_capture_warnings(**loaded, path);
    emit captures_changed();
    set_current_source((*loaded)->source);
    return {};
}

void AnnotationDocument::reset() {
    m_undo_stack.clear();
    m_annotations = RawAnnotations{};
    m_file_path.clear();
    m_captures.clear();
    m_current_source.clear();
    m_selected_clip = -1;
    emit clips_reset();
    emit captures_changed();
    emit current_capture_changed();
    emit selection_changed(-1);
    emit file_path_changed(m_file_path);
    emit dirty_changed(false);
}

Result<void> AnnotationDocument::save_as(const QString& path) {
    if (path.isEmpty()) return make_error(ErrorCode::io, "no file name to save to");
    if (Result<void> valid = m_annotations.validate(path.toStdString()); !valid) return valid.error();
    const std::string content = annotations_write_string(m_annotations);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return make_error(ErrorCode::io, path.toStdString() + ": cannot write: " + file.errorString().toStdString());
    }
    file.write(content.data(), static_cast<qint64>(content.size()));
    if (!file.commit()) return make_error(ErrorCode::io, path.toStdString() + ": cannot write: " + file.errorString().toStdString());
    const bool renamed = path != m_file_path;
    m_file_path = path;
    m_undo_stack.setClean();
    if (renamed) emit file_path_changed(m_file_path);
    emit saved(m_file_path);
    return {};
}

void AnnotationDocument::select_clip(int index) {
    if (index < -1 || index >= clip_count()) index = -1;
    m_selected_clip = index;
    if (index >= 0 && clip(index).source != m_current_source) {
        m_current_source = clip(index).source;
        emit current_capture_changed();
    }
    emit selection_changed(index);
}

void AnnotationDocument::set_current_source(const std::string& source) {
    if (m_selected_clip >= 0 && clip(m_selected_clip).source != source) {
        m_selected_clip = -1;
        emit selection_changed(-1);
    }
    if (source == m_current_source) return;
    m_current_source = source;
    emit current_capture_changed();
}

std::vector<std::string> AnnotationDocument::clip_messages(int index) const {
    std::vector<std::string> messages;
    const RawAnnotatedClip& subject = clip(index);
    RawAnnotations alone;
    alone.clips.push_back(subject);
    if (Result<void> valid = alone.validate(display_name().toStdString()); !valid) messages.push_back(valid.error().message);
    for (int other = 0; other < index; ++other) {
        if (clip(other).name == subject.name) {
            messages.push_back("the name " + subject.name + " is used by clip " + std::to_string(other + 1) + " too");
            break;
        }
    }
    if (const LoadedCapture* capture = m_captures.find(subject.source)) {
        if (Result<void> frames = raw_clip_validate_frames(subject, capture->file.clip.frame_count()); !frames) {
            messages.push_back(frames.error().message);
        }
        if (subject.segment && !capture->file.body_map.has(*subject.segment)) {
            messages.push_back("the capture has no joint for " + std::string(body_part_name(*subject.segment)));
        }
    } else {
        messages.push_back("capture " + subject.source + " is not loaded (see the issues panel)");
    }
    return messages;
}

int AnnotationDocument::find_clip(const std::string& name) const {
    for (int index = 0; index < clip_count(); ++index) {
        if (clip(index).name == name) return index;
    }
    return -1;
}

std::string AnnotationDocument::unique_clip_name(const std::string& base) const {
    if (find_clip(base) < 0) return base;
    for (int suffix = 2;; ++suffix) {
        const std::string candidate = base + "_" + std::to_string(suffix);
        if (find_clip(candidate) < 0) return candidate;
    }
}

void AnnotationDocument::add_clip(RawAnnotatedClip clip) {
    clip.name = unique_clip_name(clip.name.empty() ? std::string("clip") : clip.name);
    m_undo_stack.push(new InsertClipCommand(*this, clip_count(), std::move(clip), tr("Add Clip")));
}

void AnnotationDocument::add_suggestion(const StrikeSuggestion& strike, const std::string& source) {
    RawAnnotatedClip clip = clip_from_suggestion(strike, source);
    clip.name = unique_clip_name(clip.name);
    m_undo_stack.push(new InsertClipCommand(*this, clip_count(), std::move(clip), tr("Accept Suggestion")));
}

std::optional<double> AnnotationDocument::capture_fps(const std::string& source) const {
    const auto found = m_annotations.capture_fps.find(source);
    return found == m_annotations.capture_fps.end() ? std::nullopt : std::optional<double>(found->second);
}

void AnnotationDocument::set_capture_fps(const std::string& source, std::optional<double> fps) {
    if (source.empty() || capture_fps(source) == fps) return;
    m_undo_stack.push(new SetCaptureRateCommand(*this, source, capture_fps(source), fps));
}

void AnnotationDocument::apply_set_capture_fps(const std::string& source, std::optional<double> fps) {
    if (fps) m_annotations.capture_fps[source] = *fps;
    else m_annotations.capture_fps.erase(source);
    if (m_captures.find(source)) {
        Result<const LoadedCapture*> loaded = m_captures.reload(source, fps);
        if (!loaded) report_error(loaded.error().message, QString::fromStdString(source));
        emit captures_changed();
        if (source == m_current_source) emit current_capture_changed();
    }
}

void AnnotationDocument::remove_clip(int index) {
    if (index < 0 || index >= clip_count()) return;
    m_undo_stack.push(new RemoveClipCommand(*this, index));
}

void AnnotationDocument::edit_clip(int index, const RawAnnotatedClip& changed, ClipField field, int drag_session) {
    if (index < 0 || index >= clip_count() || clips_equal(clip(index), changed)) return;
    m_undo_stack.push(new SetClipCommand(*this, index, clip(index), changed, field, drag_session));
}

Result<void> AnnotationDocument::recover_autosave(const QString& sidecar_path) {
    QFile file(sidecar_path);
    if (!file.open(QIODevice::ReadOnly)) {
        return make_error(ErrorCode::io, sidecar_path.toStdString() + ": cannot read: " + file.errorString().toStdString());
    }
    const QByteArray bytes = file.readAll();
    Result<RawAnnotations> recovered = annotations_parse(std::string_view(bytes.constData(), static_cast<size_t>(bytes.size())),
                                                         sidecar_path.toStdString());
    if (!recovered) return recovered.error();
    m_undo_stack.push(new ReplaceClipsCommand(*this, std::move(recovered->clips), tr("Recover Autosaved Edits")));
    load_clip_captures();
    emit autosave_recovered(sidecar_path);
    if (clip_count() > 0 && m_selected_clip < 0) select_clip(0);
    return {};
}

void AnnotationDocument::report(const Issue& issue) {
    m_issues.push_back(issue);
    emit issues_changed();
}

void AnnotationDocument::report_error(std::string_view message, const QString& fallback_file) {
    report(issue_from_message(message, fallback_file));
}

void AnnotationDocument::clear_issues() {
    m_issues.clear();
    emit issues_changed();
}

void AnnotationDocument::apply_set_clip(int index, const RawAnnotatedClip& clip) {
    m_annotations.clips[static_cast<size_t>(index)] = clip;
    emit clip_changed(index);
    select_clip(index);
}

void AnnotationDocument::apply_insert_clip(int index, const RawAnnotatedClip& clip) {
    m_annotations.clips.insert(m_annotations.clips.begin() + index, clip);
    if (!m_captures.find(clip.source)) {
        Result<const LoadedCapture*> loaded = m_captures.load(clip.source, capture_fps(clip.source));
        if (!loaded) report_error(loaded.error().message, QString::fromStdString(clip.source));
        emit captures_changed();
    }
    emit clips_reset();
    m_selected_clip = -1;
    select_clip(index);
}

void AnnotationDocument::apply_remove_clip(int index) {
    m_annotations.clips.erase(m_annotations.clips.begin() + index);
    emit clips_reset();
    m_selected_clip = -1;
    select_clip(std::min(index, clip_count() - 1));
}

void AnnotationDocument::apply_replace_clips(const std::vector<RawAnnotatedClip>& clips) {
    m_annotations.clips = clips;
    emit clips_reset();
    m_selected_clip = -1;
    select_clip(clip_count() > 0 ? 0 : -1);
}

} // namespace kumite::annotate
