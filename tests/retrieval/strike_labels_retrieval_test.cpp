// Retrieval by kind and height on the reference database, for all five characters: every (semantics, kind,
// height, side) the database holds is served with exactly that, the fast path agrees with the exhaustive one, an
// order nothing serves finds nothing, and excluded clips with a score limit give the next best other clip.

#include "support/reference_database.h"

#include "kumite/core/retrieval.h"
#include "support/standing_character.h"

#include <catch2/catch.hpp>

#include <set>
#include <tuple>

using namespace kumite;

namespace {

const char* k_characters[] = {"kid", "scout", "brawler", "runner", "giant"};

// Every (semantics, kind, height, side) of the database's strikes.
std::set<std::tuple<std::string, int, int, std::uint32_t>> labelled_orders(const MotionDatabaseView& db) {
    std::set<std::tuple<std::string, int, int, std::uint32_t>> orders;
    for (const DbClip& clip : db.clips) {
        if (db_clip_is_strike(clip)) orders.insert({std::string(db.string(clip.semantics)), clip.kind, clip.height, clip.side});
    }
    return orders;
}

} // namespace

TEST_CASE("retrieval: every kind, height and side the database holds is served with exactly that, on every character", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const auto orders = labelled_orders(db);
    REQUIRE(orders.size() >= 6); // several heights of punches and slashes, both sides
    for (const char* name : k_characters) {
        const kumite::test::StandingCharacter standing(name, db);
        for (const auto& [semantics, kind, height, side] : orders) {
            RetrievalQuery query = standing.query;
            query.semantics = retriever.semantics_id(semantics);
            query.side = static_cast<Side>(side);
            query.kind = static_cast<StrikeKind>(kind);
            query.height = static_cast<StrikeHeight>(height);
            // A target at the order's height on the character: low at the hips, high above the head.
            const double y = height == int(StrikeHeight::low) ? standing.pelvis_y : height == int(StrikeHeight::high) ? standing.head_y : 0.5 * (standing.pelvis_y + standing.head_y);
            query.target_world = Eigen::Vector3d(0.0, y, 0.6 * (standing.head_y / 1.7));
            INFO(name << ": " << semantics << " " << strike_kind_name(query.kind) << " " << strike_height_name(query.height) << " side " << side);
            CHECK(retriever.candidate_count(query.semantics, query.side, query.kind, query.height) > 0);
            const RetrievalResult fast = retriever.query(query, workspace);
            REQUIRE(fast.found);
            const DbClip& clip = db.clips[fast.clip];
            CHECK(db.string(clip.semantics) == semantics);
            CHECK(int(clip.kind) == kind);
            CHECK(int(clip.height) == height);
            CHECK(clip.side == side);
            const RetrievalResult exhaustive = retriever.query_exhaustive(query);
            REQUIRE(exhaustive.found);
            CHECK(exhaustive.score == Approx(fast.score).margin(1e-9));
        }
    }
}

TEST_CASE("retrieval: an order the database cannot serve finds nothing, and counts none", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const kumite::test::StandingCharacter standing("brawler", db);
    const int punch = retriever.semantics_id("punch");
    bool has_uppercut = false;
    for (const DbClip& clip : db.clips) has_uppercut = has_uppercut || (db.string(clip.semantics) == "punch" && clip.strike_kind() == StrikeKind::uppercut);
    REQUIRE_FALSE(has_uppercut); // the shared captures hold no clear uppercut (if one is annotated, pick another missing kind)
    RetrievalQuery query = standing.query;
    query.semantics = punch;
    query.kind = StrikeKind::uppercut;
    query.target_world = Eigen::Vector3d(0.0, standing.head_y, 0.6);
    CHECK(retriever.candidate_count(punch, Side::none, StrikeKind::uppercut) == 0);
    CHECK_FALSE(retriever.query(query, workspace).found);
    CHECK_FALSE(retriever.query_exhaustive(query).found);
    // Unlabelled orders still see every punch.
    CHECK(retriever.candidate_count(punch, Side::none) == retriever.candidate_count(punch, Side::left) + retriever.candidate_count(punch, Side::right));
    int by_height = 0;
    for (StrikeHeight height : {StrikeHeight::low, StrikeHeight::middle, StrikeHeight::high}) by_height += retriever.candidate_count(punch, Side::none, StrikeKind::none, height);
    CHECK(by_height == retriever.candidate_count(punch, Side::none));
}

TEST_CASE("retrieval: excluded clips and a score limit give the best other clip within the margin", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const kumite::test::StandingCharacter standing("scout", db);
    RetrievalQuery query = standing.query;
    query.semantics = retriever.semantics_id("punch");
    query.side = Side::right;
    query.target_world = Eigen::Vector3d(0.05, standing.head_y - 0.1, 0.55);
    const RetrievalResult best = retriever.query(query, workspace);
    REQUIRE(best.found);
    std::vector<int> excluded{best.clip};
    query.excluded_clips = excluded;
    const RetrievalResult other = retriever.query(query, workspace);
    REQUIRE(other.found);
    CHECK(other.clip != best.clip);
    CHECK(other.score >= best.score);
    const RetrievalResult other_exhaustive = retriever.query_exhaustive(query);
    CHECK(other_exhaustive.clip == other.clip);
    CHECK(other_exhaustive.score == Approx(other.score).margin(1e-9));
    // A limit below the other's score leaves nothing; one above it keeps it.
    query.score_limit = other.score - 1e-6;
    CHECK_FALSE(retriever.query(query, workspace).found);
    query.score_limit = other.score + 1e-6;
    const RetrievalResult within = retriever.query(query, workspace);
    REQUIRE(within.found);
    CHECK(within.clip == other.clip);
}
