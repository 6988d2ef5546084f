// MainWindow's file handling: open (capture, folder, annotation file, recent, drag and drop), autosave recovery,
// save, the question on close, bake and screenshots.

#include "main_window.h"

#include "bake_runner.h"
#include "heatmap_panel.h"

#include <QCloseEvent>
#include <QDirIterator>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>

namespace kumite::annotate {
namespace {

constexpr int k_max_recent = 8;
const char* const k_recent_key = "recent_files";

} // namespace

bool MainWindow::open_path(const QString& path) {
    const QFileInfo info(path);
    if (!info.exists()) {
        m_document->report(Issue{IssueSeverity::error, path, 0, tr("no such file or folder")});
        return false;
    }
    if (info.isDir()) return open_folder(path);
    if (info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0) return open_annotations(path);
    return open_capture(path);
}

bool MainWindow::open_annotations(const QString& path) {
    if (!maybe_save()) return false;
    if (Result<void> opened = m_document->open_annotations(path); !opened) {
        m_document->report_error(opened.error().message, path);
        return false;
    }
    remember_recent(path);
    offer_recovery(path, false);
    return true;
}

bool MainWindow::open_capture(const QString& path) {
    if (Result<void> opened = m_document->open_capture(path); !opened) {
        m_document->report_error(opened.error().message, path);
        return false;
    }
    remember_recent(path);
    // A never-saved session autosaves beside its first capture: offer it back when that capture opens again.
    if (m_document->file_path().isEmpty() && m_document->clip_count() == 0) offer_recovery(path, true);
    return true;
}

bool MainWindow::open_folder(const QString& path) {
    QStringList captures;
    QDirIterator files(path, {QStringLiteral("*.bvh"), QStringLiteral("*.BVH")}, QDir::Files, QDirIterator::Subdirectories);
    while (files.hasNext()) captures << files.next();
    captures.sort();
    if (captures.isEmpty()) {
        m_document->report(Issue{IssueSeverity::warning, path, 0, tr("no .bvh files in this folder")});
        return false;
    }
    int opened = 0;
    std::string first_source;
    for (const QString& capture : captures) {
        if (Result<void> result = m_document->open_capture(capture); result) {
            if (++opened == 1) first_source = m_document->current_capture()->source;
        } else {
            m_document->report_error(result.error().message, capture);
        }
    }
    if (opened > 0) m_document->set_current_source(first_source); // the folder's first, not its last

    remember_recent(path);
    statusBar()->showMessage(tr("Opened %1 of %2 captures from %3").arg(opened).arg(captures.size()).arg(path), 5000);
    return opened > 0;
}

void MainWindow::offer_recovery(const QString& opened_path, bool is_capture) {
    const QString sidecar = autosave_pending_for(opened_path, is_capture);
    if (sidecar.isEmpty()) return;
    if (!m_interactive) {
        m_document->report(Issue{IssueSeverity::warning, sidecar, 0, tr("unsaved edits from an earlier session; open the file "
                                                                         "in the window to recover them")});
        return;
    }
    const QMessageBox::StandardButton answer = QMessageBox::question(
        this, tr("Recover unsaved edits?"),
        tr("%1 holds edits that were never saved (the window closed or crashed).\n\nRecover them? They stay unsaved "
           "until you save. Discard deletes them; Ignore leaves the file until the next autosave replaces it.")
            .arg(sidecar),
        QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Ignore, QMessageBox::Yes);
    if (answer == QMessageBox::Discard) {
        QFile::remove(sidecar);
    } else if (answer == QMessageBox::Yes) {
        if (Result<void> recovered = m_document->recover_autosave(sidecar); !recovered) {
            m_document->report_error(recovered.error().message, sidecar);
        }
    }
}

bool MainWindow::maybe_save() {
    if (!m_document->is_dirty() || !m_interactive) return true;
    const QMessageBox::StandardButton answer =
        QMessageBox::warning(this, tr("Unsaved changes"), tr("%1 has unsaved changes. Save them?").arg(m_document->display_name()),
                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    if (answer == QMessageBox::Discard) {
        m_autosaver->remove_sidecars(); // the animator threw the edits away on purpose
        return true;
    }
    return false;
}

bool MainWindow::save() {
    if (m_document->file_path().isEmpty()) return save_as();
    if (Result<void> saved = m_document->save(); !saved) {
        m_document->report_error(saved.error().message, m_document->file_path());
        if (m_interactive) QMessageBox::warning(this, tr("Not saved"), QString::fromStdString(saved.error().message));
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(m_document->file_path()), 4000);
    return true;
}

bool MainWindow::save_as() {
    QString suggested = m_document->file_path();
    if (suggested.isEmpty()) {
        const LoadedCapture* capture = m_document->current_capture();
        suggested = capture ? QString::fromStdString(capture->path.parent_path().string() + "/annotations.json") : QStringLiteral("annotations.json");
    }
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Annotations"), suggested, tr("Annotation files (*.json)"));
    if (path.isEmpty()) return false;
    if (Result<void> saved = m_document->save_as(path); !saved) {
        m_document->report_error(saved.error().message, path);
        QMessageBox::warning(this, tr("Not saved"), QString::fromStdString(saved.error().message));
        return false;
    }
    remember_recent(path);
    statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
    return true;
}

void MainWindow::bake() {
    if (m_document->clip_count() == 0) {
        QMessageBox::information(this, tr("Bake"), tr("The file has no clips yet: accept suggestions or add clips first."));
        return;
    }
    if (Result<void> valid = m_document->annotations().validate(m_document->display_name().toStdString()); !valid) {
        m_document->report_error(valid.error().message);
        QMessageBox::warning(this, tr("Bake"), QString::fromStdString(valid.error().message));
        return;
    }
    const QString base = m_document->file_path().isEmpty() ? QStringLiteral("database.kdb")
                                                           : QFileInfo(m_document->file_path()).path() + "/" +
                                                                 QFileInfo(m_document->file_path()).completeBaseName() + ".kdb";
    const QString output = QFileDialog::getSaveFileName(this, tr("Bake Database"), base, tr("Motion databases (*.kdb)"));
    if (output.isEmpty()) return;
    const std::string name = m_document->file_path().isEmpty() ? "untitled" : m_document->file_path().toStdString();
    Result<BakedDatabase> baked =
        bake_with_progress(this, m_document->annotations(), name, m_document->captures().mocap_root(), output);
    if (!baked) {
        m_document->report_error(baked.error().message);
        QMessageBox::warning(this, tr("Bake failed"), QString::fromStdString(baked.error().message));
        return;
    }
    const MotionDatabaseView view = baked->content->view();
    statusBar()->showMessage(tr("Baked %1: %2 clips, %3 poses, %4 clusters in %5 s")
                                 .arg(output)
                                 .arg(view.clips.size())
                                 .arg(view.poses.size())
                                 .arg(view.clusters.size())
                                 .arg(baked->seconds, 0, 'f', 2));
    m_heatmap->set_database(baked->content, output);
    m_heatmap_dock->show();
    m_heatmap_dock->raise();
}

bool MainWindow::write_screenshot(const QString& path) {
    const QImage image = grab().toImage();
    return !image.isNull() && image.save(path, "PNG");
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybe_save()) event->accept();
    else event->ignore();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    for (const QUrl& url : event->mimeData()->urls()) {
        if (url.isLocalFile()) open_path(url.toLocalFile());
    }
    event->acceptProposedAction();
}

void MainWindow::new_document() {
    if (!maybe_save()) return;
    m_document->reset();
}

void MainWindow::open_dialog() {
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Open Captures or Annotations"), QString(),
                                                            tr("Captures and annotations (*.bvh *.json);;All files (*)"));
    for (const QString& path : paths) open_path(path);
}

void MainWindow::open_folder_dialog() {
    const QString path = QFileDialog::getExistingDirectory(this, tr("Open a Folder of Captures"));
    if (!path.isEmpty()) open_path(path);
}

void MainWindow::remember_recent(const QString& path) {
    if (!m_interactive) return; // screenshots and tests leave the animator's recent list alone
    QSettings settings;
    QStringList recent = settings.value(k_recent_key).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > k_max_recent) recent.removeLast();
    settings.setValue(k_recent_key, recent);
    rebuild_recent_menu();
}

void MainWindow::rebuild_recent_menu() {
    m_recent_menu->clear();
    const QStringList recent = QSettings().value(k_recent_key).toStringList();
    for (const QString& path : recent) m_recent_menu->addAction(path, this, [this, path] { open_path(path); });
    m_recent_menu->setEnabled(!recent.isEmpty());
}

} // namespace kumite::annotate
