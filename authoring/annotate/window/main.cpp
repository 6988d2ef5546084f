// kumite-annotate [FILE.bvh | ANNOTATIONS.json | FOLDER]... [--mocap-root DIR] [--screenshot OUT.png]
// The animator's annotation window (../../shared/docs/CLI.md). --screenshot renders the window once the files are
// loaded, writes the PNG and exits, also with QT_QPA_PLATFORM=offscreen.

#include "main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

#include <cstdio>
#include <optional>

namespace {

struct CommandLine {
    QStringList files;
    QString screenshot;       // empty: no screenshot
    std::optional<QString> mocap_root;
};

// Reads the flags with a plain QCoreApplication, so --help and bad flags need no display (Qt's own flags such as
// -platform are not accepted; use QT_QPA_PLATFORM). Returns an exit status when the program should stop here.
std::optional<int> parse_command_line(int argc, char** argv, CommandLine& line) {
    QCoreApplication core(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "The animator's window: open captures, trim them, tag strikes (hit segment, semantics, side, kind, height, hit\n"
        "frame), check the hit trajectory and its box, save the annotation file, bake the database and look at its\n"
        "pose-distance heatmap."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("files"), QStringLiteral("captures (.bvh), folders of captures or an annotation file (.json)"),
                                 QStringLiteral("[FILE.bvh | ANNOTATIONS.json | FOLDER]..."));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QStringLiteral("render the window after loading into OUT.png and exit"),
                                        QStringLiteral("OUT.png"));
    const QCommandLineOption mocap_root(QStringLiteral("mocap-root"),
                                        QStringLiteral("folder annotation sources are relative to (default $KUMITE_MOCAP_ROOT or data/mocap)"),
                                        QStringLiteral("DIR"));
    parser.addOption(screenshot);
    parser.addOption(mocap_root);
    if (!parser.parse(QCoreApplication::arguments())) {
        std::fprintf(stderr, "kumite-annotate: %s (see --help)\n", qPrintable(parser.errorText()));
        return 2;
    }
    if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("help-all"))) {
        std::printf("%s", qPrintable(parser.helpText()));
        return 0;
    }
    line.files = parser.positionalArguments();
    line.screenshot = parser.value(screenshot);
    if (parser.isSet(mocap_root)) line.mocap_root = parser.value(mocap_root);
    return std::nullopt;
}

} // namespace

int main(int argc, char** argv) {
    CommandLine line;
    if (const std::optional<int> status = parse_command_line(argc, argv, line)) return *status;

    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("kumite"));
    QApplication::setApplicationName(QStringLiteral("kumite-annotate"));
    const bool taking_screenshot = !line.screenshot.isEmpty();
    const std::filesystem::path root =
        line.mocap_root ? std::filesystem::path(line.mocap_root->toStdString()) : kumite::annotate::default_mocap_root();
    kumite::annotate::MainWindow window(root, /*interactive=*/!taking_screenshot);
    window.show();
    for (const QString& path : line.files) window.open_path(path);

    if (taking_screenshot) {
        for (const kumite::annotate::Issue& issue : window.document().issues()) {
            std::fprintf(stderr, "kumite-annotate: %s%s%s\n", qPrintable(issue.file),
                         issue.line > 0 ? qPrintable(QStringLiteral(":%1: ").arg(issue.line)) : ": ", qPrintable(issue.message));
        }
        const QString output = line.screenshot;
        int status = 0;
        // After the first paint of every widget: layouts settled, the viewport drawn.
        QTimer::singleShot(100, &window, [&] {
            if (!window.write_screenshot(output)) {
                std::fprintf(stderr, "kumite-annotate: cannot write the screenshot %s\n", qPrintable(output));
                status = 1;
            }
            QApplication::exit(status);
        });
        const int loop_status = QApplication::exec();
        return status != 0 ? status : loop_status;
    }
    return QApplication::exec();
}
