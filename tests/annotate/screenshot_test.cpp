// `kumite-annotate FILE.bvh --screenshot OUT.png` under QT_QPA_PLATFORM=offscreen: the window renders after
// loading, and the picture shows the skeleton, the proposed strike's trajectory and its box, not a blank frame.

#include "qt_application.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <QColor>
#include <QImage>

#include <set>

using namespace kumite;

namespace {

const std::string k_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

// Pixels within `tolerance` (per channel) of `color`.
int count_near(const QImage& image, QColor color, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor pixel = image.pixelColor(x, y);
            if (std::abs(pixel.red() - color.red()) <= tolerance && std::abs(pixel.green() - color.green()) <= tolerance &&
                std::abs(pixel.blue() - color.blue()) <= tolerance) {
                ++count;
            }
        }
    }
    return count;
}

test::CommandOutput run_annotate(const std::string& arguments) {
    return test::run_command("QT_QPA_PLATFORM=offscreen " + (test::bin_dir() / "kumite-annotate").string() + " " + arguments);
}

} // namespace

TEST_CASE("screenshot: the kick capture renders with skeleton, trajectory and box", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path output = test::make_temp_dir("annotate-shot") / "kick.png";
    const test::CommandOutput run = run_annotate((test::mocap_root() / k_kick_capture).string() + " --screenshot " + output.string() +
                                                 " --mocap-root " + test::mocap_root().string());
    INFO(run.err);
    REQUIRE(run.status == 0);
    QImage image;
    REQUIRE(image.load(QString::fromStdString(output.string()), "PNG"));
    CHECK(image.width() >= 800);
    CHECK(image.height() >= 500);

    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
    }
    CHECK(colours.size() > 200); // a blank or flat window has a handful
    // The proposal's trajectory dots and box are green (scene_builder.cpp), the contact point red.
    CHECK(count_near(image, QColor(115, 242, 115), 40) > 40);
    CHECK(count_near(image, QColor(255, 51, 51), 60) > 20);
}

TEST_CASE("screenshot: a malformed capture still renders, with the error on stderr", "[annotate]") {
    test::qt_application();
    const std::filesystem::path folder = test::make_temp_dir("annotate-shot-bad");
    const std::filesystem::path bad = folder / "broken.bvh";
    { std::FILE* file = std::fopen(bad.c_str(), "w"); std::fputs("HIERARCHY\nROOT Hips\n{\n", file); std::fclose(file); }
    const test::CommandOutput run = run_annotate(bad.string() + " --screenshot " + (folder / "shot.png").string());
    CHECK(run.status == 0);
    CHECK_THAT(run.err, Catch::Contains("broken.bvh"));
    CHECK(std::filesystem::exists(folder / "shot.png"));
}

TEST_CASE("screenshot: an unknown flag exits with status 2, --help prints usage and exits 0", "[annotate]") {
    const test::CommandOutput run = run_annotate("--no-such-flag");
    CHECK(run.status == 2);
    CHECK_FALSE(run.err.empty());
    for (const char* flag : {"--help", "--help-all"}) {
        const test::CommandOutput help = run_annotate(flag);
        CHECK(help.status == 0);
        CHECK_THAT(help.out, Catch::Contains("--screenshot"));
    }
    // Flags are read before any window system is needed: usage and errors work without a display too.
    const std::string no_display = "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + (test::bin_dir() / "kumite-annotate").string();
    CHECK(test::run_command(no_display + " --help").status == 0);
    CHECK(test::run_command(no_display + " --no-such-flag").status == 2);
}
