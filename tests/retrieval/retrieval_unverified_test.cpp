// Retrieval over a database whose per-pose values were not verified: what the opener does not read (a pose
// record's clip and frame, cluster members, features) may be anything, and the retriever still answers inside the
// clip table the opener checked. It bounds what the verifier would refuse where it reads it.

#include "kumite/core/retrieval.h"
#include "support/small_database.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kumite;

namespace {

RetrievalQuery punch_query(const MotionDatabaseView& db, const Retriever& retriever) {
    RetrievalQuery query;
    query.pose_feature = db.feature(3);
    query.semantics = retriever.semantics_id("punch");
    query.target_world = Eigen::Vector3d(0.0, 1.4, 0.5);
    query.character = {0.8, 0.55};
    return query;
}

} // namespace

TEST_CASE("retrieval: an unverified database answers inside its clip table whatever its pose records and members hold", "[retrieval]") {
    // The punch's only start (pose 3) says frame 999; a rest pose names clip 5000; a member names pose 70; a rest
    // pose's feature is NaN. A mapped file opened without verify can hold any of these.
    MotionDatabaseContent content = kumite::test::small_database();
    content.poses[3].frame = 999;
    content.poses[0].clip = 5000;
    content.members[6] = 70;
    content.features[k_feature_dimensions + 4] = NAN;
    const MotionDatabaseView db = content.view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const RetrievalQuery query = punch_query(db, retriever);
    for (const RetrievalResult& result : {retriever.query(query, workspace), retriever.query_exhaustive(query)}) {
        REQUIRE(result.found);
        CHECK(result.clip == 1);
        CHECK(result.start_pose == 3);
        CHECK(result.start_frame == 0); // from the clip table (pose 3 is the punch's first), not the record's 999
        CHECK(result.contact_frame == 2);
    }
    const int punch_clip[] = {1};
    RetrievalQuery excluding = query;
    excluding.excluded_clips = punch_clip;
    CHECK_FALSE(retriever.query(excluding, workspace).found);
}

TEST_CASE("retrieval: NaN features in some poses leave the others found", "[retrieval]") {
    MotionDatabaseContent content = kumite::test::small_database();
    for (std::size_t i = 0; i < 3 * std::size_t(k_feature_dimensions); i += 7) content.features[i] = NAN; // the rest clip's poses
    const MotionDatabaseView db = content.view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const RetrievalQuery query = punch_query(db, retriever);
    const RetrievalResult result = retriever.query(query, workspace);
    REQUIRE(result.found);
    CHECK(result.clip == 1);
    CHECK(result.start_frame == 0);
    CHECK(retriever.query_exhaustive(query).start_pose == result.start_pose);
}
