#pragma once
// The undo commands of the annotation document. Each holds the values before and after, so undo and redo are
// exact. Edits of one field of one clip during one drag (same nonzero session) merge into a single step.

#include "kumite/formats/annotation_file.h"

#include <QUndoCommand>

#include <optional>
#include <string>
#include <vector>

namespace kumite::annotate {

class AnnotationDocument;

enum class ClipField { other = 0, name, first_frame, last_frame, hit_frame, semantics, segment, side, mirror, source, kind, height };

QString clip_field_command_text(ClipField field); // "Move In Point", "Set Hit Frame", ...
// Every field, the strike labels (kind, height) and the unknown keys included.
bool clips_equal(const RawAnnotatedClip& a, const RawAnnotatedClip& b);

class SetClipCommand : public QUndoCommand {
public:
    SetClipCommand(AnnotationDocument& document, int index, RawAnnotatedClip before, RawAnnotatedClip after, ClipField field,
                   int drag_session);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    AnnotationDocument& m_document;
    int m_index;
    RawAnnotatedClip m_before, m_after;
    ClipField m_field;
    int m_drag_session;
};

class InsertClipCommand : public QUndoCommand {
public:
    InsertClipCommand(AnnotationDocument& document, int index, RawAnnotatedClip clip, const QString& text);
    void undo() override;
    void redo() override;

private:
    AnnotationDocument& m_document;
    int m_index;
    RawAnnotatedClip m_clip;
};

class RemoveClipCommand : public QUndoCommand {
public:
    RemoveClipCommand(AnnotationDocument& document, int index);
    void undo() override;
    void redo() override;

private:
    AnnotationDocument& m_document;
    int m_index;
    RawAnnotatedClip m_clip;
};

class ReplaceClipsCommand : public QUndoCommand {
public:
    ReplaceClipsCommand(AnnotationDocument& document, std::vector<RawAnnotatedClip> after, const QString& text);
    void undo() override;
    void redo() override;

private:
    AnnotationDocument& m_document;
    std::vector<RawAnnotatedClip> m_before, m_after;
};

// "Set Frame Rate" of a capture whose file gives none: the rate before and after (none: not given).
class SetCaptureRateCommand : public QUndoCommand {
public:
    SetCaptureRateCommand(AnnotationDocument& document, std::string source, std::optional<double> before, std::optional<double> after);
    void undo() override;
    void redo() override;

private:
    AnnotationDocument& m_document;
    std::string m_source;
    std::optional<double> m_before, m_after;
};

} // namespace kumite::annotate
