// kumite play's fighter settings: the table (play_settings.h), the settings file and --set as a user gives them, the
// help that names them, and docs/settings.md, which must be what --print-settings prints.

#include "play_settings.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>

using kumite::test::read_text;
using kumite::test::run_command;
using namespace kumite;
using namespace kumite::cli;

namespace {

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }
std::string golden() { return (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string(); }

std::filesystem::path write_text(const std::string& name, const std::string& text) {
    const std::filesystem::path path = kumite::test::make_temp_dir("cli_settings") / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

} // namespace

TEST_CASE("play settings: every setting is named once, holds its default in its range, and reads back its own text", "[cli]") {
    std::set<std::string> names;
    const BoutOptions defaults;
    for (const Setting& setting : play_settings()) {
        INFO(setting.name);
        CHECK(names.insert(setting.name).second);
        CHECK(play_setting_named(setting.name) == &setting);
        CHECK(std::string(setting.help).size() > 10);
        BoutOptions options;
        const std::string text = play_setting_text(defaults, setting);
        REQUIRE(play_setting_assign(options, setting, text));
        CHECK(play_setting_text(options, setting) == text);
        // Numbers accept their range's ends and refuse just past them.
        if (std::holds_alternative<double*>(setting.field(options)) || std::holds_alternative<int*>(setting.field(options))) {
            CHECK(setting.min <= setting.max);
            const bool whole = std::holds_alternative<int*>(setting.field(options));
            const auto text_of = [&](double value) { return whole ? std::to_string(static_cast<long long>(value)) : std::to_string(value); };
            CHECK(play_setting_assign(options, setting, text_of(setting.min)));
            CHECK(play_setting_assign(options, setting, text_of(setting.max)));
            CHECK_FALSE(play_setting_assign(options, setting, text_of(setting.max + 1.0)));
            CHECK_FALSE(play_setting_assign(options, setting, text_of(setting.min - 1.0)));
            CHECK_FALSE(play_setting_assign(options, setting, "nan"));
            CHECK_FALSE(play_setting_assign(options, setting, ""));
        }
    }
    CHECK(play_setting_named("no_such_setting") == nullptr);
    CHECK(names.count("defence.captured_blocks"));
    CHECK(names.count("strike_follow_s"));
    CHECK(names.count("aim"));
}

TEST_CASE("play settings: a value that is not what the setting takes is refused with the setting's name and range", "[cli]") {
    BoutOptions options;
    const Result<void> bad_number = play_setting_assign(options, "defence.hold_s=abc");
    REQUIRE_FALSE(bad_number);
    CHECK_THAT(bad_number.error().message, Catch::Contains("defence.hold_s must be a number from 0 to 5 s, not 'abc'"));
    CHECK_FALSE(play_setting_assign(options, "human_speed=yes"));
    CHECK_FALSE(play_setting_assign(options, "variety_recent=2.5"));
    CHECK_FALSE(play_setting_assign(options, "aim=sideways"));
    CHECK_FALSE(play_setting_assign(options, "human_speed"));
    const Result<void> unknown = play_setting_assign(options, "superhuman=true");
    REQUIRE_FALSE(unknown);
    CHECK_THAT(unknown.error().message, Catch::Contains("no setting named 'superhuman'"));
    // Nothing refused changed anything.
    CHECK(play_settings_text(options) == play_settings_text(BoutOptions{}));
    REQUIRE(play_setting_assign(options, " max_speedup = 1.25 "));
    CHECK(options.fighter.max_speedup == 1.25);
}

TEST_CASE("play settings: a settings file round-trips through --print-settings and --settings", "[cli]") {
    const auto printed = run_command(kumite_exe() + " play --print-settings --set strike_follow_s=0.3 --set defence.captured_blocks=true"
                                     " --set variety_recent=2 --set contact_speed_share=0.1 --aim predicted --no-defence");
    REQUIRE(printed.status == 0);
    CHECK_THAT(printed.out, Catch::Contains("\nstrike_follow_s = 0.3\n"));
    CHECK_THAT(printed.out, Catch::Contains("\ndefence.captured_blocks = true\n"));
    CHECK_THAT(printed.out, Catch::Contains("\ndefence.enabled = false\n"));
    CHECK_THAT(printed.out, Catch::Contains("\naim = predicted\n"));
    const std::filesystem::path file = write_text("round.settings", printed.out);
    const auto again = run_command(kumite_exe() + " play --settings " + file.string() + " --print-settings");
    REQUIRE(again.status == 0);
    CHECK(again.out == printed.out);
    // Each setting is documented once: one value line, under its comment, which says its default.
    std::size_t previous = 0;
    for (const Setting& setting : play_settings()) {
        INFO(setting.name);
        const std::string line = "\n" + std::string(setting.name) + " = ";
        const std::size_t at = printed.out.find(line);
        REQUIRE(at != std::string::npos);
        CHECK(printed.out.find(line, at + 1) == std::string::npos);
        const std::size_t comment = printed.out.rfind("default ", at);
        CHECK((comment != std::string::npos && comment > previous));
        previous = at;
    }
}

TEST_CASE("play settings: --set, a settings file, and the everyday flags give the same bout", "[cli]") {
    const std::string base = kumite_exe() + " play " + golden() + " --headless --duration 4 --tracker simulate:punch";
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_settings_bout");
    const std::filesystem::path file = write_text("bout.settings", "# no defence, kept distance off\ndefence.enabled = false\nkeep_distance=false\n");
    const auto flags = run_command(base + " --no-defence --set keep_distance=false --events " + (folder / "a.jsonl").string());
    const auto set = run_command(base + " --set defence.enabled=false --set keep_distance=false --events " + (folder / "b.jsonl").string());
    const auto from_file = run_command(base + " --settings " + file.string() + " --events " + (folder / "c.jsonl").string());
    const auto defaults = run_command(base + " --events " + (folder / "d.jsonl").string());
    REQUIRE(flags.status == 0);
    REQUIRE(set.status == 0);
    REQUIRE(from_file.status == 0);
    REQUIRE(defaults.status == 0);
    const std::string a = read_text(folder / "a.jsonl");
    CHECK(a.size() > 100);
    CHECK(read_text(folder / "b.jsonl") == a);
    CHECK(read_text(folder / "c.jsonl") == a);
    CHECK(read_text(folder / "d.jsonl") != a); // the settings matter
}

TEST_CASE("play settings: a bad settings file or --set is refused with where and why", "[cli]") {
    const std::string base = kumite_exe() + " play " + golden() + " --headless --duration 1";
    const std::filesystem::path unknown = write_text("unknown.settings", "# fine\nlead_s = 0.5\n\nsuperhuman_strikes = true\n");
    const auto refused_unknown = run_command(base + " --settings " + unknown.string());
    CHECK(refused_unknown.status == 1);
    CHECK_THAT(refused_unknown.err, Catch::Contains(unknown.string() + ":4: no setting named 'superhuman_strikes'"));
    const std::filesystem::path twice = write_text("twice.settings", "lead_s = 0.5\nlead_s = 0.6\n");
    const auto refused_twice = run_command(base + " --settings " + twice.string());
    CHECK(refused_twice.status == 1);
    CHECK_THAT(refused_twice.err, Catch::Contains(":2: lead_s is given twice (first on line 1)"));
    const std::filesystem::path garbage = write_text("garbage.settings", std::string("\x01\xff\x00zz", 5));
    const auto refused_garbage = run_command(base + " --settings " + garbage.string());
    CHECK(refused_garbage.status == 1);
    CHECK_THAT(refused_garbage.err, Catch::Contains(":1: expected 'name = value'"));
    const auto missing = run_command(base + " --settings /nonexistent/kumite.settings");
    CHECK(missing.status == 1);
    CHECK_THAT(missing.err, Catch::Contains("/nonexistent/kumite.settings"));
    const auto bad_set = run_command(base + " --set max_speedup=2.5");
    CHECK(bad_set.status == 2);
    CHECK_THAT(bad_set.err, Catch::Contains("max_speedup must be a number from 1 to 1.9"));
    const auto no_equals = run_command(base + " --set human_speed");
    CHECK(no_equals.status == 2);
    CHECK_THAT(no_equals.err, Catch::Contains("--set takes name=value"));
    // A captured block's speed limit without captured blocks would do nothing: refused before anything is opened.
    const auto limit_alone = run_command(base + " --set defence.block_clip_max_speed_ratio=1");
    CHECK(limit_alone.status == 2);
    CHECK_THAT(limit_alone.err, Catch::Contains("defence.captured_blocks"));
}

TEST_CASE("play settings: --help stays short and names where the settings are", "[cli]") {
    const auto help = run_command(kumite_exe() + " play --help");
    REQUIRE(help.status == 0);
    CHECK(std::count(help.out.begin(), help.out.end(), '\n') <= 45);
    CHECK_THAT(help.out, Catch::Contains("--settings FILE"));
    CHECK_THAT(help.out, Catch::Contains("--print-settings"));
    CHECK_THAT(help.out, Catch::Contains("docs/settings.md"));
    for (const char* gone : {"--superhuman", "--play-out-strikes", "--no-block-handover", "--captured-blocks"}) {
        CHECK_THAT(help.out, !Catch::Contains(gone));
    }
}

TEST_CASE("play settings: docs/settings.md lists every setting as --print-settings prints the defaults", "[cli]") {
    const auto printed = run_command(kumite_exe() + " play --print-settings");
    REQUIRE(printed.status == 0);
    const std::string page = read_text(kumite::test::source_dir() / "docs/settings.md");
    const std::string open = "```ini\n";
    const std::size_t begin = page.find(open);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = page.find("```\n", begin + open.size());
    REQUIRE(end != std::string::npos);
    INFO("regenerate the block with: build/bin/kumite play --print-settings");
    CHECK(page.substr(begin + open.size(), end - begin - open.size()) == printed.out);
}
