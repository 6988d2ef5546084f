// Warnings of commands that read many files (suggest, bake): one line per kind of warning, its first in full with
// how many there are, and every one with --verbose; the grouping itself (warning_groups.h) on its own.

#include "support/test_paths.h"
#include "warning_groups.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>

using kumite::test::read_text;
using kumite::test::run_command;

namespace {

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }

std::vector<std::string> warning_lines(const std::string& err) {
    std::vector<std::string> lines;
    std::istringstream stream(err);
    for (std::string line; std::getline(stream, line);) {
        if (line.starts_with("warning: ")) lines.push_back(line);
    }
    return lines;
}

// A copy of a shipped character's skeleton (a humanoid, one frame) with `change` applied to its text.
std::filesystem::path character_copy(const std::filesystem::path& folder, const std::string& name, void (*change)(std::string&)) {
    std::string text = read_text(kumite::test::source_dir() / "data/characters/kid.bvh");
    change(text);
    const std::filesystem::path path = folder / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

void no_frame_rate(std::string& text) {
    const std::size_t at = text.find("Frame Time:");
    text.replace(at, text.find('\n', at) - at, "Frame Time: 0");
}
void named_end_site(std::string& text) { text.replace(text.find("End Site"), 8, "End toe"); }

} // namespace

TEST_CASE("warning_groups: a kind is the message with its numbers and quotes masked", "[cli]") {
    using kumite::cli::warning_kind;
    CHECK(warning_kind("the root never moves (the foot it stands on slid 14 cm); moving up to 5 cm") ==
          warning_kind("the root never moves (the foot it stands on slid 9 cm); moving up to 12 cm"));
    CHECK(warning_kind("slid 14 cm") == "slid # cm");
    CHECK(warning_kind("'Frame Time: 0': read at 100.5 fps (--fps)") == "'...': read at # fps (--fps)");
    CHECK(warning_kind("offset -0.25 from \"End toe\"") == "offset # from \"...\"");
    CHECK(warning_kind("x-1 joints") == "x-# joints"); // a hyphen inside a word is no sign
    CHECK(warning_kind("an unclosed 'quote 3") == "an unclosed 'quote #");
    CHECK(warning_kind("slid 14 cm") != warning_kind("slid 14 m"));
}

TEST_CASE("warning_groups: one line per kind with its count and first example, or every warning verbose", "[cli]") {
    kumite::cli::WarningGroups groups;
    groups.add_from_reader("a.bvh", "a.bvh:129: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)");
    groups.add_from_reader("b.bvh", "b.bvh:129: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)");
    groups.add("ref.json: clip kick_7", "the support foot is never planted before the hit");
    groups.add_from_reader("c.bvh", "c.bvh:130: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)");
    groups.add_from_reader("d.bvh", "no source named here");
    CHECK(groups.count() == 5);
    CHECK(groups.kind_count() == 3);
    std::ostringstream grouped;
    groups.print(grouped, false);
    CHECK(grouped.str() == "warning: a.bvh:129: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps) "
                           "[3 like this in all; --verbose lists them]\n"
                           "warning: ref.json: clip kick_7: the support foot is never planted before the hit\n"
                           "warning: d.bvh: no source named here\n");
    std::ostringstream verbose;
    groups.print(verbose, true);
    CHECK(verbose.str() == "warning: a.bvh:129: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)\n"
                           "warning: b.bvh:129: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)\n"
                           "warning: ref.json: clip kick_7: the support foot is never planted before the hit\n"
                           "warning: c.bvh:130: 'Frame Time: 0': the capture has no frame rate; read at 100 fps (--fps)\n"
                           "warning: d.bvh: no source named here\n");
}

TEST_CASE("cli: suggest over many captures gives one warning line per kind, --verbose every warning", "[cli]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-warnings");
    std::vector<std::filesystem::path> files;
    for (const char* name : {"a.bvh", "b.bvh", "c.bvh"}) files.push_back(character_copy(folder, name, no_frame_rate));
    files.push_back(character_copy(folder, "d.bvh", named_end_site)); // two other kinds: the End name, a rate replaced
    std::string command = kumite_exe() + " suggest";
    for (const std::filesystem::path& file : files) command += " " + file.string();
    command += " --fps 100";

    const auto grouped = run_command(command);
    REQUIRE(grouped.status == 0);
    const std::vector<std::string> lines = warning_lines(grouped.err);
    REQUIRE(lines.size() == 3);
    CHECK_THAT(lines[0], Catch::StartsWith("warning: " + files[0].string() + ":") && Catch::Contains("Frame Time: 0") &&
                             Catch::EndsWith("[3 like this in all; --verbose lists them]"));
    CHECK_THAT(grouped.err, Catch::Contains("d.bvh:") && Catch::Contains("End toe"));
    CHECK(grouped.err.find("b.bvh") == std::string::npos); // only the first of a kind is named
    CHECK_THAT(grouped.out, Catch::Contains("a.bvh: 0 strikes") && Catch::Contains("d.bvh: 0 strikes"));

    const auto verbose = run_command(command + " --verbose");
    REQUIRE(verbose.status == 0);
    const std::vector<std::string> every = warning_lines(verbose.err);
    REQUIRE(every.size() == 5);
    for (int f = 0; f < 3; ++f) CHECK_THAT(every[f], Catch::StartsWith("warning: " + files[f].string() + ":") && Catch::Contains("Frame Time: 0"));
    CHECK(verbose.err.find("like this in all") == std::string::npos);

    const auto json = run_command(command + " --json");
    REQUIRE(json.status == 0);
    CHECK(nlohmann::json::parse(json.out)["files"].size() == 4); // stdout holds the one document, warnings go to stderr
    CHECK(warning_lines(json.err).size() == 3);
}

TEST_CASE("cli: bake says a quirk shared by many captures once, with how many", "[cli][corpus]") {
    const nlohmann::json reference = nlohmann::json::parse(read_text(kumite::test::source_dir() / "data/annotations/reference.json"));
    if (!std::filesystem::exists(kumite::test::mocap_root() / "hachaj-shorinryu")) {
        WARN("no hachaj-shorinryu captures under " << kumite::test::mocap_root());
        return;
    }
    // Three clips of three Shorin-ryu captures: their roots are pinned, the bake repairs each and says so.
    nlohmann::json annotations = reference;
    annotations["clips"] = nlohmann::json::array();
    std::set<std::string> sources;
    for (const nlohmann::json& clip : reference["clips"]) {
        const std::string source = clip["source"];
        if (source.starts_with("hachaj-shorinryu/") && sources.size() < 3 && sources.insert(source).second) annotations["clips"].push_back(clip);
    }
    REQUIRE(sources.size() == 3);
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-bake-warnings");
    const std::filesystem::path path = folder / "three.json";
    std::ofstream(path) << annotations.dump(2);
    const std::string command = kumite_exe() + " bake " + path.string() + " -o " + (folder / "three.kdb").string() +
                                " --mocap-root " + kumite::test::mocap_root().string() + " --jobs 2";

    const auto grouped = run_command(command);
    REQUIRE(grouped.status == 0);
    const std::vector<std::string> lines = warning_lines(grouped.err);
    REQUIRE(lines.size() == 1);
    CHECK_THAT(lines[0], Catch::Contains("hachaj-shorinryu/") && Catch::Contains("the root never moves") &&
                             Catch::EndsWith("[3 like this in all; --verbose lists them]"));

    const auto verbose = run_command(command + " --verbose");
    REQUIRE(verbose.status == 0);
    const std::vector<std::string> every = warning_lines(verbose.err);
    REQUIRE(every.size() == 3);
    for (const std::string& source : sources) {
        CHECK(std::count_if(every.begin(), every.end(), [&](const std::string& line) { return line.find(source) != std::string::npos; }) == 1);
    }
}
