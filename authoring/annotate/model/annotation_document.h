#pragma once
// The annotation window's document: one annotation file (RawAnnotations), the captures its clips cut from, the
// selected clip and the issues met while reading. Knows nothing of widgets. Every edit goes through the undo
// stack as a command (clip_commands.h); "dirty" means the stack is not at its clean index. Saves are atomic
// (QSaveFile) and write exactly annotations_write_string's text, the file `kumite bake` reads.

#include "capture_library.h"
#include "clip_commands.h"
#include "issue.h"

#include "kumite/formats/annotation_file.h"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <optional>

#include <vector>

namespace kumite::annotate {

class AnnotationDocument : public QObject {
    Q_OBJECT
public:
    explicit AnnotationDocument(std::filesystem::path mocap_root, QObject* parent = nullptr);

    // --- the file
    const RawAnnotations& annotations() const { return m_annotations; }
    QString file_path() const { return m_file_path; } // empty: not saved yet
    QString display_name() const;                      // file name, or "untitled"
    bool is_dirty() const { return !m_undo_stack.isClean(); }
    QUndoStack* undo_stack() { return &m_undo_stack; }
    std::string text() const { return annotations_write_string(m_annotations); }

    // Replaces the document by the file (undo history cleared) and loads the captures its clips name; a capture
    // that cannot be read becomes an issue, not a failure. Fails (document unchanged) on an unreadable file.
    Result<void> open_annotations(const QString& path);
    // Opens a capture into the session (not the file) and makes it the current one. Errors name file and line.
    Result<void> open_capture(const QString& path);
    // Empties the document: no file, no clips, no captures, no history.
    void reset();
    // Validates, writes atomically, marks clean. Fails with the validation or I/O message; nothing written then.
    Result<void> save_as(const QString& path);
    Result<void> save() { return save_as(m_file_path); }

    // --- clips
    int clip_count() const { return static_cast<int>(m_annotations.clips.size()); }
    const RawAnnotatedClip& clip(int index) const { return m_annotations.clips[static_cast<size_t>(index)]; }
    int selected_clip() const { return m_selected_clip; }
    void select_clip(int index); // -1: none; also makes the clip's capture current
    // Messages about one clip: the file's own checks and its range against the capture; empty when fine.
    std::vector<std::string> clip_messages(int index) const;
    int find_clip(const std::string& name) const; // -1 when absent
    std::string unique_clip_name(const std::string& base) const;

    // --- edits, each one undo command
    void add_clip(RawAnnotatedClip clip);          // "Add Clip", selects it; the name is made unique
    void add_suggestion(const StrikeSuggestion& strike, const std::string& source); // "Accept Suggestion"
    void remove_clip(int index);                   // "Remove Clip"
    // Replaces clip `index` by `changed`. Consecutive edits of the same field of the same clip with the same
    // nonzero `drag_session` merge into one command (a handle drag is one undo step).
    void edit_clip(int index, const RawAnnotatedClip& changed, ClipField field, int drag_session = 0);
    // Replaces every clip by those of an autosave sidecar ("Recover Autosaved Edits"): dirty afterwards.
    Result<void> recover_autosave(const QString& sidecar_path);

    // --- captures
    CaptureLibrary& captures() { return m_captures; }
    const CaptureLibrary& captures() const { return m_captures; }
    const LoadedCapture* current_capture() const { return m_captures.find(m_current_source); }
    void set_current_source(const std::string& source);
    // The rate the animator gave a capture whose file gives none (saved as the file's "captures"), if any.
    std::optional<double> capture_fps(const std::string& source) const;
    // "Set Frame Rate": gives (or, with none, takes back) a capture's rate; the capture is read again at it, so its
    // suggestions, timeline and playback follow. One undo step.
    void set_capture_fps(const std::string& source, std::optional<double> fps);
    // The capture clip `index` cuts from, or null when it is not loaded.
    const LoadedCapture* capture_of(int index) const { return m_captures.find(clip(index).source); }

    // --- issues
    const std::vector<Issue>& issues() const { return m_issues; }
    void report(const Issue& issue);
    void report_error(std::string_view message, const QString& fallback_file = {});
    void clear_issues();

    // Used by the commands only: the raw changes, with their signals.
    void apply_set_clip(int index, const RawAnnotatedClip& clip);
    void apply_insert_clip(int index, const RawAnnotatedClip& clip);
    void apply_remove_clip(int index);
    void apply_replace_clips(const std::vector<RawAnnotatedClip>& clips);
    void apply_set_capture_fps(const std::string& source, std::optional<double> fps);

signals:
    void clips_reset();               // the list changed shape (insert, remove, open, recover)
    void clip_changed(int index);     // one clip's fields changed
    void selection_changed(int index);
    void current_capture_changed();
    void captures_changed();
    void dirty_changed(bool dirty);
    void file_path_changed(const QString& path);
    void issues_changed();
    void saved(const QString& path);
    void autosave_recovered(const QString& sidecar_path);

private:
    void load_clip_captures();
    void report_capture_warnings(const LoadedCapture& capture, const QString& fallback_file);

    RawAnnotations m_annotations;
    QString m_file_path;
    QUndoStack m_undo_stack;
    CaptureLibrary m_captures;
    std::string m_current_source;
    int m_selected_clip = -1;
    std::vector<Issue> m_issues;
};

} // namespace kumite::annotate
