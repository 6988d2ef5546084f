#include "qt_application.h"

#include "support/test_paths.h"

#include <QElapsedTimer>
#include <QThread>

namespace kumite::test {

QCoreApplication& qt_application() {
    static int argc = 1;
    static char name[] = "annotate_tests";
    static char* argv[] = {name, nullptr};
    static QCoreApplication application(argc, argv);
    return application;
}

bool process_events_until(const std::function<bool()>& done, int timeout_ms) {
    qt_application();
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeout_ms) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(5);
    }
    return true;
}

std::filesystem::path copy_capture_to_temp(const std::string& relative_to_mocap_root, const std::string& stem) {
    const std::filesystem::path source = mocap_root() / relative_to_mocap_root;
    const std::filesystem::path target = make_temp_dir(stem) / source.filename();
    std::filesystem::copy_file(source, target);
    return target;
}

} // namespace kumite::test
