#include "clip_commands.h"

#include "annotation_document.h"

namespace kumite::annotate {

QString clip_field_command_text(ClipField field) {
    switch (field) {
    case ClipField::name: return QObject::tr("Rename Clip");
    case ClipField::first_frame: return QObject::tr("Move In Point");
    case ClipField::last_frame: return QObject::tr("Move Out Point");
    case ClipField::hit_frame: return QObject::tr("Move Hit Frame");
    case ClipField::semantics: return QObject::tr("Set Semantics");
    case ClipField::segment: return QObject::tr("Set Hit Segment");
    case ClipField::side: return QObject::tr("Set Side");
    case ClipField::mirror: return QObject::tr("Toggle Mirror");
    case ClipField::source: return QObject::tr("Set Source");
    case ClipField::kind: return QObject::tr("Set Strike Kind");
    case ClipField::height: return QObject::tr("Set Strike Height");
    case ClipField::other: break;
    }
    return QObject::tr("Edit Clip");
}

bool clips_equal(const RawAnnotatedClip& a, const RawAnnotatedClip& b) {
    return a.name == b.name && a.source == b.source && a.first_frame == b.first_frame && a.last_frame == b.last_frame &&
           a.semantics == b.semantics && a.segment == b.segment && a.side == b.side && a.hit_frame == b.hit_frame &&
           a.mirror == b.mirror && a.kind == b.kind && a.height == b.height && a.extra_json == b.extra_json;
}

SetClipCommand::SetClipCommand(AnnotationDocument& document, int index, RawAnnotatedClip before, RawAnnotatedClip after,
                               ClipField field, int drag_session)
    : QUndoCommand(clip_field_command_text(field)), m_document(document), m_index(index), m_before(std::move(before)),
      m_after(std::move(after)), m_field(field), m_drag_session(drag_session) {}

void SetClipCommand::undo() { m_document.apply_set_clip(m_index, m_before); }
void SetClipCommand::redo() { m_document.apply_set_clip(m_index, m_after); }

// One id per field: QUndoStack only offers merging to commands of the same id.
int SetClipCommand::id() const { return m_drag_session != 0 ? 1000 + static_cast<int>(m_field) : -1; }

bool SetClipCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const SetClipCommand*>(other);
    if (!next || next->m_index != m_index || next->m_field != m_field || next->m_drag_session != m_drag_session) return false;
    m_after = next->m_after;
    // A drag that ends where it started changes nothing: drop the step instead of keeping a no-op.
    if (clips_equal(m_before, m_after)) setObsolete(true);
    return true;
}

InsertClipCommand::InsertClipCommand(AnnotationDocument& document, int index, RawAnnotatedClip clip, const QString& text)
    : QUndoCommand(text), m_document(document), m_index(index), m_clip(std::move(clip)) {}

void InsertClipCommand::undo() { m_document.apply_remove_clip(m_index); }
void InsertClipCommand::redo() { m_document.apply_insert_clip(m_index, m_clip); }

RemoveClipCommand::RemoveClipCommand(AnnotationDocument& document, int index)
    : QUndoCommand(QObject::tr("Remove Clip")), m_document(document), m_index(index), m_clip(document.clip(index)) {}

void RemoveClipCommand::undo() { m_document.apply_insert_clip(m_index, m_clip); }
void RemoveClipCommand::redo() { m_document.apply_remove_clip(m_index); }

ReplaceClipsCommand::ReplaceClipsCommand(AnnotationDocument& document, std::vector<RawAnnotatedClip> after, const QString& text)
    : QUndoCommand(text), m_document(document), m_before(document.annotations().clips), m_after(std::move(after)) {}

void ReplaceClipsCommand::undo() { m_document.apply_replace_clips(m_before); }
void ReplaceClipsCommand::redo() { m_document.apply_replace_clips(m_after); }

SetCaptureRateCommand::SetCaptureRateCommand(AnnotationDocument& document, std::string source, std::optional<double> before,
                                             std::optional<double> after)
    : QUndoCommand(QObject::tr("Set Frame Rate")), m_document(document), m_source(std::move(source)), m_before(before), m_after(after) {}

void SetCaptureRateCommand::undo() { m_document.apply_set_capture_fps(m_source, m_before); }
void SetCaptureRateCommand::redo() { m_document.apply_set_capture_fps(m_source, m_after); }

} // namespace kumite::annotate
