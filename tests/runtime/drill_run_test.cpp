// A drill as a bout runs it: parts in turn from 0 s, attacks at the cadence (fixed, or drawn with the part's seed,
// the same every time), in turn or at random, the part's end after its last attack, status for the supervisor's
// window, and a drill whose attacks or levels the runtime does not know refused with its line.

#include "kumite/runtime/drill_run.h"

#include <catch2/catch.hpp>

using kumite::DrillRun;

namespace {

DrillRun compiled(const std::string& text) {
    kumite::Result<kumite::Drill> drill = kumite::drill_parse(text, "d.toml");
    REQUIRE(drill);
    kumite::Result<DrillRun> run = DrillRun::compile(std::move(*drill), "d.toml");
    INFO((run ? std::string() : run.error().message));
    REQUIRE(run);
    return std::move(*run);
}

std::vector<DrillRun::Line> handed_out(DrillRun& run, double until_s) {
    std::vector<DrillRun::Line> lines;
    for (double t = 0.0; t <= until_s; t += 1.0 / 60.0) run.due(t, [&](const DrillRun::Line& line) { lines.push_back(line); });
    return lines;
}

const char* k_two_parts = R"(name = "d"
[[part]]
name = "in turn"
attacks = ["punch right", "kick left", "combo one-two"]
order = "in turn"
cadence_s = 2.0
count = 5
[[part]]
name = "random"
attacks = ["punch right", "punch left"]
cadence_s = [1.0, 3.0]
duration_s = 30
seed = 9
difficulty = "person"
[[part]]
name = "sparring"
free_sparring = true
duration_s = 10
)";

} // namespace

TEST_CASE("drill run: parts in turn, attacks at their moments, the same for the same seed", "[runtime][drill]") {
    DrillRun run = compiled(k_two_parts);
    REQUIRE(run.parts().size() == 3);
    CHECK(run.parts()[0].end_s == Approx(5 * 2.0 + kumite::k_count_part_tail_s));
    CHECK(run.parts()[1].start_s == Approx(13.0));
    CHECK(run.parts()[1].end_s == Approx(43.0));
    CHECK(run.duration_s() == Approx(53.0));
    CHECK(run.parts()[2].attacks == 0);

    const std::vector<DrillRun::Line> lines = handed_out(run, 60.0);
    std::vector<const DrillRun::Line*> first, second;
    int starts = 0, ends = 0;
    for (const DrillRun::Line& line : lines) {
        starts += line.kind == DrillRun::Line::Kind::part_start;
        ends += line.kind == DrillRun::Line::Kind::end;
        if (line.kind != DrillRun::Line::Kind::attack) continue;
        (line.part == 0 ? first : second).push_back(&line);
    }
    CHECK(starts == 3);
    CHECK(ends == 1);
    REQUIRE(first.size() == 5);
    CHECK(first[0]->text == "punch right");
    CHECK(first[1]->text == "kick left");
    CHECK(first[2]->text == "combo one-two");
    CHECK(first[3]->text == "punch right");
    CHECK(first[4]->t_s == Approx(10.0));
    // Random cadence within [1, 3] s over the 30 s part, both attacks drawn; none at or after its end.
    REQUIRE(second.size() >= 10);
    REQUIRE(second.size() <= 30);
    double previous = 13.0;
    bool left = false, right = false;
    for (const DrillRun::Line* line : second) {
        CHECK(line->t_s - previous >= 1.0 - 1e-9);
        CHECK(line->t_s - previous <= 3.0 + 1e-9);
        CHECK(line->t_s < 43.0);
        previous = line->t_s;
        left = left || line->text == "punch left";
        right = right || line->text == "punch right";
    }
    CHECK((left && right));
    DrillRun again = compiled(k_two_parts);
    CHECK(again.lines().size() == run.lines().size());
    for (std::size_t i = 0; i < run.lines().size(); ++i) {
        CHECK(again.lines()[i].t_s == run.lines()[i].t_s);
        CHECK(again.lines()[i].text == run.lines()[i].text);
    }
}

TEST_CASE("drill run: the status says the part, the next attack and how many are left", "[runtime][drill]") {
    DrillRun run = compiled(k_two_parts);
    DrillRun::Status status = run.status(3.0);
    CHECK(status.part == 0);
    CHECK(status.parts == 3);
    REQUIRE(status.next);
    CHECK(status.next->text == "kick left");
    CHECK(status.next->t_s == Approx(4.0));
    CHECK(status.attacks_left == 4);
    status = run.status(48.0);
    CHECK(status.part == 2);
    CHECK(status.part_info->free_sparring);
    CHECK(status.next == nullptr);
    CHECK(status.part_left_s == Approx(5.0));
    CHECK(run.status(53.5).part == -1);
}

TEST_CASE("drill run: attacks and levels the runtime does not know are refused with their line", "[runtime][drill]") {
    const auto refused = [](const std::string& text) {
        kumite::Result<kumite::Drill> drill = kumite::drill_parse(text, "d.toml");
        REQUIRE(drill);
        kumite::Result<DrillRun> run = DrillRun::compile(std::move(*drill), "d.toml");
        REQUIRE(!run);
        return run.error().message;
    };
    const std::string head = "name = \"d\"\n[[part]]\nname = \"p\"\ncount = 3\n";
    CHECK(refused(head + "attacks = [\"punch\",\n  \"punch sideways\"]\n").starts_with("d.toml:6: 'punch sideways'"));
    CHECK(refused(head + "attacks = [\"quit\"]\n").starts_with("d.toml:5: 'quit' is not an attack"));
    CHECK(refused(head + "attacks = [\"combo one-three\"]\n").starts_with("d.toml:5: 'combo one-three'"));
    CHECK(refused(head + "attacks = [\"punch\"]\ndifficulty = \"hardest\"\n").starts_with("d.toml:6: difficulty takes beginner"));
}
