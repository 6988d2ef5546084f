#pragma once
// Autosave: while a document has unsaved changes, its text is written to a sidecar within half a second of an edit, so a
// killed process loses nothing. The sidecar is `<file>.autosave` beside the annotation file, or, for a document
// never saved, `<capture>.annotations.json.autosave` beside its first capture. It is removed when the document
// is saved or undone back to its clean state, and offered for recovery when the file or capture is opened again.

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

namespace kumite::annotate {

class AnnotationDocument;

QString autosave_sidecar_for_file(const QString& annotation_path);  // "<file>.autosave"
QString autosave_sidecar_for_capture(const QString& capture_path);  // "<capture>.annotations.json.autosave"

// The sidecar to offer when opening `opened_path` (an annotation file or a capture): it exists and holds
// something else than the file itself. Empty when there is nothing to recover.
QString autosave_pending_for(const QString& opened_path, bool is_capture);

class Autosaver : public QObject {
    Q_OBJECT
public:
    // Writes at most `delay_ms` after the first edit not yet autosaved (0: at the next event loop turn).
    Autosaver(AnnotationDocument& document, int delay_ms = 500, QObject* parent = nullptr);

    // Where the document's autosave goes now; empty when it has neither a file nor a capture.
    QString sidecar_path() const;
    // Writes the sidecar now if the document is dirty; false (and `last_error`) when it could not be written.
    bool write_now();
    // Removes every sidecar this session wrote or recovered from.
    void remove_sidecars();
    QString last_error() const { return m_last_error; }

signals:
    void written(const QString& path);
    void failed(const QString& message); // the sidecar could not be written (a read-only capture folder, ...)

private:
    void on_document_changed();

    AnnotationDocument& m_document;
    QTimer m_timer;
    QStringList m_sidecars; // written or recovered, to remove once the edits are safe in the file
    QString m_last_error;
};

} // namespace kumite::annotate
