#pragma once
// Bake from the window: the same bake_database call as `kumite bake` (default clusters, every core) on a worker
// thread, its progress in a modal QProgressDialog, then the .kdb written atomically (motion_database_write).
// The bake cannot be interrupted half way, so the dialog has no Cancel button.

#include "kumite/core/motion_database.h"
#include "kumite/formats/annotation_file.h"

#include <QString>

#include <filesystem>
#include <memory>

class QWidget;

namespace kumite::annotate {

struct BakedDatabase {
    std::shared_ptr<const MotionDatabaseContent> content;
    QString path;          // the .kdb written
    double seconds = 0.0;  // the bake's own time
};

Result<BakedDatabase> bake_with_progress(QWidget* parent, const RawAnnotations& annotations, const std::string& annotations_name,
                                         const std::filesystem::path& mocap_root, const QString& output_path);

} // namespace kumite::annotate
