// Retrieval queries allocate nothing once the retriever and the caller's workspace exist.

#include "kumite/core/character_rig.h"
#include "kumite/core/retrieval.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"
#include "support/allocation_counter.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

TEST_CASE("retrieval: fast and exhaustive queries allocate nothing", "[core]") {
    Result<MotionDatabase> database = MotionDatabase::open(kumite::test::source_dir() / "data/golden/golden-v1.kdb");
    Result<BvhFile> character = bvh_read_file(kumite::test::source_dir() / "data/characters/brawler.bvh");
    REQUIRE(database.has_value());
    REQUIRE(character.has_value());
    Result<RestAnatomy> anatomy = rest_anatomy_build(character->clip, character->body_map);
    REQUIRE(anatomy.has_value());
    const Retriever retriever(database->view());
    RetrievalWorkspace workspace = retriever.make_workspace();
    CharacterRig rig(character->clip.skeleton, *anatomy);
    Pose pose;
    rig.stand_at_origin(pose, database->view());
    std::array<float, k_feature_dimensions> feature;
    rig.still_feature(feature);
    RetrievalQuery query;
    query.pose_feature = feature;
    query.heading = rig.heading();
    query.character = rig.size();
    int found = 0;
    kumite::test::AllocationScope scope;
    for (int i = 0; i < 50; ++i) {
        query.semantics = retriever.semantics_id(i % 2 ? "kick" : "punch");
        query.side = i % 3 == 0 ? Side::none : i % 3 == 1 ? Side::left : Side::right;
        query.target_world = Eigen::Vector3d(0.02 * (i - 25), 0.8 + 0.02 * i, 0.5 + 0.01 * i);
        found += retriever.query(query, workspace).found;
        found += retriever.query_exhaustive(query).found;
    }
    CHECK(scope.count() == 0);
    CHECK(found > 50);
}
