// Captures whose file gives no frame rate ('Frame Time: 0', as hachaj-shorinryu's): read with a warning by what
// needs no time (inspect, positions, convert); refused with a message saying how by what needs time (suggest,
// retarget, bake) until --fps or the annotation file's "captures" gives the rate.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using kumite::test::run_command;

namespace {

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }

// A rate-less capture of the shared corpus, or empty (the test then warns and stops).
std::filesystem::path rateless_capture() {
    const std::filesystem::path path = kumite::test::mocap_root() / "hachaj-shorinryu/s1_mae_geri_right_sample0.bvh";
    return std::filesystem::exists(path) ? path : std::filesystem::path();
}

std::filesystem::path write_annotations(const std::filesystem::path& folder, const std::string& name, const nlohmann::json& captures) {
    nlohmann::json document = {{"format", "kumite-annotations"},
                               {"version", 2},
                               {"clips",
                                {{{"name", "kick"},
                                  {"source", "hachaj-shorinryu/s1_mae_geri_right_sample0.bvh"},
                                  {"first", 0},
                                  {"last", 80},
                                  {"semantics", "kick"},
                                  {"segment", "foot_r"},
                                  {"side", "right"},
                                  {"hit_frame", 50},
                                  {"mirror", true}}}}};
    if (!captures.is_null()) document["captures"] = captures;
    const std::filesystem::path path = folder / name;
    std::ofstream(path) << document.dump(2);
    return path;
}

} // namespace

TEST_CASE("cli: a capture without a frame rate reads with a warning; inspect says no fps until --fps gives one", "[cli][corpus]") {
    const std::filesystem::path capture = rateless_capture();
    if (capture.empty()) {
        WARN("no hachaj-shorinryu captures under " << kumite::test::mocap_root());
        return;
    }
    const auto plain = run_command(kumite_exe() + " inspect " + capture.string() + " --json");
    REQUIRE(plain.status == 0);
    const nlohmann::json document = nlohmann::json::parse(plain.out);
    CHECK(document["fps"].is_null());
    CHECK(document["duration_s"].is_null());
    CHECK(document["fps_source"] == "none");
    REQUIRE(document["warnings"].size() == 1);
    CHECK_THAT(document["warnings"][0].get<std::string>(), Catch::Contains(capture.string() + ":") && Catch::Contains("Frame Time: 0"));
    CHECK_THAT(plain.err, Catch::Contains("warning: " + capture.string() + ":"));

    const auto rated = run_command(kumite_exe() + " inspect " + capture.string() + " --json --fps 100");
    REQUIRE(rated.status == 0);
    const nlohmann::json with_rate = nlohmann::json::parse(rated.out);
    CHECK(with_rate["fps"].get<double>() == Approx(100.0));
    CHECK(with_rate["fps_source"] == "--fps");
    CHECK(with_rate["duration_s"].get<double>() == Approx((with_rate["frames"].get<int>() - 1) * 0.01));

    const auto positions = run_command(kumite_exe() + " positions " + capture.string() + " --frames 0,10 --json");
    CHECK(positions.status == 0);
    CHECK(nlohmann::json::parse(positions.out)["frames"].size() == 2);

    for (const char* bad : {"0", "-5", "abc", "1e999", "nan"}) {
        const auto refused = run_command(kumite_exe() + " inspect " + capture.string() + " --fps " + bad);
        CHECK(refused.status == 2);
        CHECK_THAT(refused.err, Catch::Contains("--fps"));
    }
}

TEST_CASE("cli: suggest and retarget refuse a capture without a frame rate, saying how to give one", "[cli][corpus]") {
    const std::filesystem::path capture = rateless_capture();
    if (capture.empty()) return;
    for (const std::string& command : {"suggest " + capture.string(), "retarget " + capture.string() + " --character scout -o " +
                                                                         (kumite::test::make_temp_dir("fps") / "out.bvh").string()}) {
        const auto refused = run_command(kumite_exe() + " " + command);
        INFO(command);
        CHECK(refused.status == 1);
        CHECK_THAT(refused.err, Catch::Contains(capture.string()) && Catch::Contains("frame rate") && Catch::Contains("--fps N"));
        const auto given = run_command(kumite_exe() + " " + command + " --fps 100 --json");
        CHECK(given.status == 0);
    }
    // suggest --write-annotations keeps the rate it was given for the bake.
    const std::filesystem::path folder = kumite::test::make_temp_dir("fps");
    const auto written = run_command(kumite_exe() + " suggest " + capture.string() + " --fps 100 --mocap-root " +
                                     kumite::test::mocap_root().string() + " --write-annotations " + (folder / "s.json").string());
    REQUIRE(written.status == 0);
    const nlohmann::json annotations = nlohmann::json::parse(kumite::test::read_text(folder / "s.json"));
    CHECK(annotations["captures"]["hachaj-shorinryu/s1_mae_geri_right_sample0.bvh"]["fps"].get<double>() == Approx(100.0));
}

TEST_CASE("cli: bake takes a capture's rate from the annotation file or --fps, and refuses without one", "[cli][corpus]") {
    const std::filesystem::path capture = rateless_capture();
    if (capture.empty()) return;
    const std::filesystem::path folder = kumite::test::make_temp_dir("fps");
    const std::string root = " --mocap-root " + kumite::test::mocap_root().string();
    const std::filesystem::path output = folder / "out.kdb";

    const std::filesystem::path no_rate = write_annotations(folder, "no_rate.json", nullptr);
    const auto refused = run_command(kumite_exe() + " bake " + no_rate.string() + " -o " + output.string() + root);
    CHECK(refused.status == 1);
    CHECK_THAT(refused.err, Catch::Contains("frame rate") && Catch::Contains("\"fps\"") && Catch::Contains("--fps N"));
    CHECK_FALSE(std::filesystem::exists(output)); // nothing half-written

    const auto with_flag = run_command(kumite_exe() + " bake " + no_rate.string() + " -o " + output.string() + root + " --fps 100");
    CHECK(with_flag.status == 0);
    const std::string flag_bytes = kumite::test::read_text(output);
    CHECK_FALSE(flag_bytes.empty());

    const std::filesystem::path in_file = write_annotations(folder, "in_file.json", {{"hachaj-shorinryu/s1_mae_geri_right_sample0.bvh", {{"fps", 100}}}});
    const std::filesystem::path output_2 = folder / "out2.kdb";
    const auto from_file = run_command(kumite_exe() + " bake " + in_file.string() + " -o " + output_2.string() + root);
    CHECK(from_file.status == 0);
    CHECK(kumite::test::read_text(output_2) == flag_bytes); // the same rate, the same bytes

    // A different rate changes the clip's length in database frames: it is really used.
    const auto at_50 = run_command(kumite_exe() + " bake " + no_rate.string() + " -o " + (folder / "out50.kdb").string() + root + " --fps 50");
    CHECK(at_50.status == 0);
    const auto info_100 = nlohmann::json::parse(run_command(kumite_exe() + " db-info " + output.string() + " --json").out);
    const auto info_50 = nlohmann::json::parse(run_command(kumite_exe() + " db-info " + (folder / "out50.kdb").string() + " --json").out);
    CHECK(info_50["poses"].get<int>() > info_100["poses"].get<int>());

    const std::filesystem::path bad = write_annotations(folder, "bad.json", {{"hachaj-shorinryu/s1_mae_geri_right_sample0.bvh", {{"fps", -3}}}});
    const auto bad_rate = run_command(kumite_exe() + " bake " + bad.string() + " -o " + output.string() + root);
    CHECK(bad_rate.status == 1);
    CHECK_THAT(bad_rate.err, Catch::Contains("captures") && Catch::Contains("\"fps\""));
}
