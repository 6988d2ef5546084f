#include "bake_runner.h"

#include "bake.h"
#include "kumite/formats/motion_database_file.h"

#include <QEventLoop>
#include <QProgressDialog>
#include <QThread>

#include <optional>

namespace kumite::annotate {

Result<BakedDatabase> bake_with_progress(QWidget* parent, const RawAnnotations& annotations, const std::string& annotations_name,
                                         const std::filesystem::path& mocap_root, const QString& output_path) {
    QProgressDialog dialog(QObject::tr("Reading captures..."), QString(), 0, 0, parent);
    dialog.setWindowTitle(QObject::tr("Bake"));
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setCancelButton(nullptr);
    dialog.setMinimumDuration(0);
    dialog.setAutoClose(false);
    dialog.setAutoReset(false);

    bake::BakeOptions options;
    options.mocap_root = mocap_root;
    // Called on bake threads: hand the numbers to the dialog's thread, never touch the widget here.
    options.progress = [&dialog](const bake::BakeProgress& step) {
        QMetaObject::invokeMethod(
            &dialog,
            [&dialog, stage = QString::fromStdString(step.stage), done = step.done, total = step.total] {
                dialog.setLabelText(stage);
                dialog.setMaximum(std::max(total, 1));
                dialog.setValue(std::min(done, std::max(total, 1)));
            },
            Qt::QueuedConnection);
    };

    std::optional<Result<BakedDatabase>> outcome;
    const std::string output = output_path.toStdString();
    QThread* worker = QThread::create([&] {
        Result<bake::BakeResult> baked = bake::bake_database(annotations, annotations_name, options);
        if (!baked) {
            outcome.emplace(baked.error());
            return;
        }
        auto content = std::make_shared<MotionDatabaseContent>(std::move(baked->database));
        if (Result<void> written = motion_database_write(output, content->view()); !written) {
            outcome.emplace(written.error());
            return;
        }
        outcome.emplace(BakedDatabase{std::move(content), output_path, baked->seconds});
    });
    QEventLoop loop;
    QObject::connect(worker, &QThread::finished, &loop, &QEventLoop::quit);
    dialog.show();
    worker->start();
    loop.exec();
    worker->wait();
    delete worker;
    dialog.close();
    return std::move(*outcome);
}

} // namespace kumite::annotate
