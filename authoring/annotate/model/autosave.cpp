#include "autosave.h"

#include "annotation_document.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace kumite::annotate {

QString autosave_sidecar_for_file(const QString& annotation_path) { return annotation_path + QStringLiteral(".autosave"); }

QString autosave_sidecar_for_capture(const QString& capture_path) {
    return capture_path + QStringLiteral(".annotations.json.autosave");
}

QString autosave_pending_for(const QString& opened_path, bool is_capture) {
    const QString sidecar = is_capture ? autosave_sidecar_for_capture(opened_path) : autosave_sidecar_for_file(opened_path);
    QFile autosaved(sidecar);
    if (!autosaved.open(QIODevice::ReadOnly)) return {};
    if (is_capture) return sidecar;
    QFile original(opened_path);
    if (original.open(QIODevice::ReadOnly) && original.readAll() == autosaved.readAll()) return {};
    return sidecar;
}

Autosaver::Autosaver(AnnotationDocument& document, int delay_ms, QObject* parent)
    : QObject(parent), m_document(document) {
    m_timer.setSingleShot(true);
    m_timer.setInterval(delay_ms);
    connect(&m_timer, &QTimer::timeout, this, [this] { write_now(); });
    connect(document.undo_stack(), &QUndoStack::indexChanged, this, [this] { on_document_changed(); });
    connect(&document, &AnnotationDocument::saved, this, [this] { remove_sidecars(); });
    connect(&document, &AnnotationDocument::autosave_recovered, this, [this](const QString& path) {
        if (!m_sidecars.contains(path)) m_sidecars.append(path);
    });
}

QString Autosaver::sidecar_path() const {
    if (!m_document.file_path().isEmpty()) return autosave_sidecar_for_file(m_document.file_path());
    const auto& captures = m_document.captures().captures();
    if (captures.empty()) return {};
    return autosave_sidecar_for_capture(QString::fromStdString(captures.front()->path.string()));
}

void Autosaver::on_document_changed() {
    if (m_document.is_dirty()) {
        // Not restarted by later edits: a long drag still autosaves every `delay_ms`, so a kill loses at most that.
        if (!m_timer.isActive()) m_timer.start();
    } else {
        m_timer.stop();
        remove_sidecars(); // undone back to what the file holds: nothing to recover
    }
}

bool Autosaver::write_now() {
    if (!m_document.is_dirty()) return true;
    const QString path = sidecar_path();
    if (path.isEmpty()) {
        m_last_error = tr("nowhere to autosave: the document has no file and no capture");
        emit failed(m_last_error);
        return false;
    }
    const std::string content = m_document.text();
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content.data(), static_cast<qint64>(content.size())) < 0 || !file.commit()) {
        m_last_error = path + QStringLiteral(": cannot autosave: ") + file.errorString();
        emit failed(m_last_error);
        return false;
    }
    if (!m_sidecars.contains(path)) m_sidecars.append(path);
    emit written(path);
    return true;
}

void Autosaver::remove_sidecars() {
    for (const QString& path : std::as_const(m_sidecars)) QFile::remove(path);
    m_sidecars.clear();
}

} // namespace kumite::annotate
