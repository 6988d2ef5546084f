// Drill files (formats/drill_file.h): the shipped drills read; malformed ones are refused with file, line and reason.

#include "support/test_paths.h"

#include "kumite/formats/drill_file.h"

#include <catch2/catch.hpp>

using namespace kumite;

TEST_CASE("drill file: the shipped drills read, with their parts as written", "[formats]") {
    const auto folder = kumite::test::source_dir() / "data/drills";
    const Result<Drill> reaction = drill_read((folder / "reaction-test.toml").string());
    REQUIRE(reaction.has_value());
    CHECK(reaction->name == "reaction test");
    REQUIRE(reaction->parts.size() == 1);
    const DrillPart& attacks = reaction->parts[0];
    CHECK(attacks.count == 20);
    CHECK(attacks.attacks.size() == 5);
    CHECK(attacks.attacks[0].text == "punch right straight high");
    CHECK(attacks.attacks[0].line == 8); // each attack keeps its line, for the command's own checks
    CHECK(attacks.cadence_min_s == 3.0);
    CHECK(attacks.cadence_max_s == 6.0);
    CHECK_FALSE(attacks.in_turn);
    CHECK(attacks.difficulty.text == "person");

    const Result<Drill> sparring = drill_read((folder / "free-sparring.toml").string());
    REQUIRE(sparring.has_value());
    REQUIRE(sparring->parts.size() == 2);
    CHECK(sparring->parts[1].free_sparring);
    CHECK(sparring->parts[1].duration_s == 300.0);
    CHECK(sparring->parts[1].attacks.empty());

    const Result<Drill> combinations = drill_read((folder / "combinations.toml").string());
    REQUIRE(combinations.has_value());
    CHECK(combinations->parts[0].in_turn);
    CHECK(combinations->parts[0].cadence_min_s == 4.0);
    CHECK(combinations->parts[0].cadence_max_s == 4.0);
}

TEST_CASE("drill file: a malformed drill is refused with its file, line and reason", "[formats]") {
    const std::string part = "name = \"d\"\n[[part]]\nname = \"p\"\n";
    struct Case {
        std::string text;
        std::string says; // in the message, after "FILE:LINE: "
        int line;
    };
    const std::vector<Case> cases = {
        {"name = \"d\"\n[[part]]\nname = \"p\"\nattacks = [\"punch\"\ncount = 3\n", "separator", 5}, // an unclosed list: where it shows
        {part + "attacks = [\"punch\"]\ncount = 3\ncadance_s = 2\n", "unknown key 'cadance_s'", 6},
        {part + "attacks = [\"punch\"]\n", "needs one of count and duration_s", 2},
        {part + "attacks = [\"punch\"]\ncount = 3\nduration_s = 10\n", "needs one of count and duration_s", 2},
        {part + "count = 3\n", "neither attacks nor free_sparring", 2},
        {part + "free_sparring = true\nattacks = [\"punch\"]\ncount = 3\n", "takes no attacks", 5},
        {part + "attacks = [\"punch\"]\ncount = 0\n", "count must be", 5},
        {part + "attacks = [\"punch\"]\ncount = 3\ncadence_s = [4, 2]\n", "high end is under its low end", 6},
        {part + "attacks = [\"punch\"]\ncount = 3\ncadence_s = 0.01\n", "cadence_s must be within", 6},
        {part + "attacks = [\"punch\"]\ncount = 3\norder = \"shuffled\"\n", "order must be", 6},
        {part + "attacks = [\"punch\", 3]\ncount = 3\n", "an attack must be a string", 4},
        {part + "attacks = [\"punch\"]\ncount = 3\nseed = -1\n", "seed must be", 6},
        {"[[part]]\nname = \"p\"\nattacks = [\"punch\"]\ncount = 3\n", "has no name", 1},
        {"name = \"d\"\n", "has no parts", 1},
        {"name = \"d\"\ncolour = \"red\"\n[[part]]\n", "unknown key 'colour'", 2},
        {"name = \"d\"\n[[part]]\nattacks = [\"punch\"]\ncount = 3\n", "has no name", 2},
        {"name = 3\n", "name must be a string", 1},
        {std::string("name = \"d\"\n") + std::string(40, '[') + "\n", "nested deeper", 1},
        {"name = \"d\"\n\x01\x02\xff", "control character", 2},
        {std::string("name = \"d\"\n\n'n\257aea'nr\335\024") + std::string(1, '\0'), "not UTF-8", 3}, // toml11 read past this
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const Result<Drill> drill = drill_parse(c.text, "bad.toml");
        REQUIRE_FALSE(drill.has_value());
        INFO(drill.error().message);
        CHECK_THAT(drill.error().message, Catch::StartsWith("bad.toml:" + std::to_string(c.line) + ": "));
        CHECK_THAT(drill.error().message, Catch::Contains(c.says));
        CHECK(drill.error().message.size() > std::string("bad.toml:1: ").size() + 5);
    }
    const Result<Drill> missing = drill_read("/nonexistent/drill.toml");
    REQUIRE_FALSE(missing.has_value());
    CHECK_THAT(missing.error().message, Catch::Contains("/nonexistent/drill.toml"));
}
