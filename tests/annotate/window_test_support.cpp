#include "window_test_support.h"

#include "support/test_paths.h"

#include <QElapsedTimer>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>

namespace kumite::test {

QApplication& gui_application() {
    static int argc = 1;
    static char name[] = "annotate_window_tests";
    static char* argv[] = {name, nullptr};
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true); // recent files go to a test QSettings, not the user's
    // And to one of this process alone: ctest runs test cases side by side, and another window's recent files
    // must not land in the list a test checks.
    static const std::filesystem::path settings = make_temp_dir("annotate-settings");
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, QString::fromStdString(settings.string()));
    // Never destroyed: a QApplication torn down by static destruction, after Qt's own globals, crashes at exit.
    static QApplication* application = new QApplication(argc, argv);
    return *application;
}

void settle(int ms) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms) QApplication::processEvents(QEventLoop::AllEvents, 10);
    QApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // replaced list widgets really go
}

std::filesystem::path temp_mocap_root(const std::string& stem) {
    const std::filesystem::path root = make_temp_dir(stem);
    std::filesystem::create_directories(root / "bandai-namco-1");
    std::filesystem::copy_file(mocap_root() / k_window_kick_capture, root / k_window_kick_capture);
    return root;
}

int click_accept_buttons(QWidget& window, int at_most) {
    int clicked = 0;
    while (clicked < at_most) {
        QPushButton* accept = nullptr;
        for (QPushButton* button : window.findChildren<QPushButton*>()) {
            if (button->text() == "Accept" && button->isEnabled()) accept = button;
        }
        if (!accept) break;
        accept->click();
        settle(5);
        ++clicked;
    }
    return clicked;
}

bool have_captures() { return std::filesystem::exists(mocap_root() / k_window_kick_capture); }

} // namespace kumite::test
