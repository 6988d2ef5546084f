// The C API's frame calls allocate nothing: feeding the user, stepping (orders included), reading the joints'
// world transforms and skin matrices. libkumite's calls to operator new resolve to this executable's counting one.

#include "kumite.h"
#include "support/allocation_counter.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <vector>

TEST_CASE("c api: set_user, step and the transform reads allocate nothing", "[c_api]") {
    kumite_database* database = nullptr;
    REQUIRE(kumite_database_open((kumite::test::source_dir() / "data/golden/golden-v2.kdb").c_str(), &database) == KUMITE_OK);
    kumite_bout_options options;
    kumite_bout_options_init(&options);
    const std::string characters = (kumite::test::source_dir() / "data/characters").string();
    options.characters_dir = characters.c_str();
    kumite_bout* bout = nullptr;
    REQUIRE(kumite_bout_create(database, &options, &bout) == KUMITE_OK);
    const int joints = kumite_bout_joint_count(bout, 0);
    std::vector<float> matrices(std::size_t(16 * joints)), skin(std::size_t(16 * joints));
    const bool body = kumite_bout_has_body(bout, 0) == 1;
    const double head[3] = {0.0, 1.65, 1.3}, hand[3] = {0.25, 1.4, 1.0};
    auto frame = [&](int f) {
        REQUIRE(kumite_bout_set_user(bout, head, hand, nullptr) == KUMITE_OK);
        REQUIRE(kumite_bout_step(bout, f / 60.0) == KUMITE_OK);
        REQUIRE(kumite_bout_world_transforms(bout, 0, matrices.data(), matrices.size()) == KUMITE_OK);
        if (body) REQUIRE(kumite_bout_skin_matrices(bout, 0, skin.data(), skin.size()) == KUMITE_OK);
    };
    // Warm up: the first strikes size the adapter's buffers.
    REQUIRE(kumite_bout_command(bout, "punch") == KUMITE_OK);
    for (int f = 0; f < 240; ++f) frame(f);
    REQUIRE(kumite_bout_command(bout, "kick") == KUMITE_OK); // the line is queued (allocation), taken at the step
    long allocations = 0;
    {
        kumite::test::AllocationScope scope;
        for (int f = 240; f < 600; ++f) frame(f);
        allocations = scope.count();
    }
    CHECK(allocations == 0);
    CHECK(body); // the brawler has a glTF body: the skin matrices were read
    // The counter does see inside libkumite: formatting an event allocates (kumite.h says so).
    REQUIRE(kumite_bout_command(bout, "punch") == KUMITE_OK);
    long formatting = 0;
    int events = 0;
    char text[8192];
    for (int f = 600; f < 700; ++f) {
        frame(f);
        kumite::test::AllocationScope scope;
        while (kumite_bout_next_event(bout, text, sizeof text, nullptr) == 1) ++events;
        formatting += scope.count();
    }
    CHECK(events > 0);
    CHECK(formatting > 0);
    kumite_bout_destroy(bout);
    kumite_database_close(database);
}
