// Retrieval on the reference database (baked here from data/annotations/reference.json) for all five characters:
// orders are obeyed, the contact is where the strike's limb still travels (90% of its way to the annotated hit) scored by the hit
// point there, the fast path agrees with the
// exhaustive reference, and concurrent queries on one retriever give the single-threaded answers.

#include "support/reference_database.h"

#include "kumite/core/character_rig.h"
#include "kumite/core/retrieval.h"
#include "kumite/core/split_mix.h"
#include "kumite/formats/bvh_reader.h"
#include "support/standing_character.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <thread>
#include <vector>

using namespace kumite;

namespace {

using kumite::test::reference_database;

using Standing = kumite::test::StandingCharacter;

const char* k_characters[] = {"kid", "scout", "brawler", "runner", "giant"};

bool arm_part(int segment) { return segment >= int(BodyPart::clavicle_l) && segment <= int(BodyPart::hand_r); }
bool left_part(int segment) { return body_part_name(static_cast<BodyPart>(segment)).ends_with("_l"); }

} // namespace

TEST_CASE("retrieval: orders are obeyed for every character", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();
    SplitMix64 random{5};
    for (const char* name : k_characters) {
        Standing standing(name, db);
        for (int i = 0; i < 60; ++i) {
            const bool kick = i % 2;
            const Side side = static_cast<Side>(i % 3);
            RetrievalQuery query = standing.query;
            query.semantics = retriever.semantics_id(kick ? "kick" : "punch");
            query.side = side;
            query.target_world = Eigen::Vector3d(random.uniform(-0.4, 0.4), random.uniform(standing.pelvis_y, standing.head_y),
                                                 random.uniform(0.3, 1.0));
            const RetrievalResult result = retriever.query(query, workspace);
            INFO(name << " query " << i);
            REQUIRE(result.found);
            const DbClip& clip = db.clips[result.clip];
            CHECK(db.string(clip.semantics) == (kick ? "kick" : "punch"));
            CHECK(arm_part(clip.segment) == !kick); // a punch never returns a foot, a kick never a hand
            if (side != Side::none) {
                CHECK(clip.side == std::uint32_t(side));
                CHECK(left_part(clip.segment) == (side == Side::left)); // a left punch never returns a right hand
            }
            // At least the lead before the contact, or the clip's very first frame when its wind-up is shorter.
            CHECK((result.start_frame + retriever.settings().min_lead_frames <= result.contact_frame || result.start_frame == 0));
            // The strike lands where its limb still travels, at or a little before its own annotated hit.
            CHECK(result.contact_frame == db_clip_contact_frame(db, clip, retriever.settings().contact_extension, retriever.settings().contact_speed_share));
            CHECK(result.contact_frame <= clip.hit_frame);
            CHECK(result.time_to_contact_s >= 0.0);
        }
        RetrievalQuery unknown = standing.query;
        unknown.semantics = retriever.semantics_id("headbutt");
        CHECK(unknown.semantics == -1);
        CHECK_FALSE(retriever.query(unknown, workspace).found);
    }
}

TEST_CASE("retrieval: the contact is where the hit point has covered 90% of its way to the hit, scored by where it is then", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    RetrievalSettings target_only = retriever.settings();
    target_only.pose_weight = 0.0;
    const Retriever by_target(db, target_only);
    RetrievalWorkspace workspace = retriever.make_workspace();
    for (const char* name : k_characters) {
        Standing standing(name, db);
        for (const char* semantics : {"punch", "kick"}) {
            RetrievalQuery query = standing.query;
            query.semantics = retriever.semantics_id(semantics);
            const double high_y = standing.head_y, low_y = standing.pelvis_y;
            query.target_world = Eigen::Vector3d(0.0, high_y, 0.6);
            const RetrievalResult high = retriever.query(query, workspace);
            query.target_world = Eigen::Vector3d(0.0, low_y, 0.6);
            const RetrievalResult low = retriever.query(query, workspace);
            INFO(name << " " << semantics << ": high contact at " << high.contact_point_world.transpose() << ", low contact at "
                      << low.contact_point_world.transpose());
            REQUIRE(high.found);
            REQUIRE(low.found);
            // The target term is the distance from the target to the hit point at the contact frame.
            CHECK(high.contact_frame == db_clip_contact_frame(db, db.clips[high.clip], 0.9, RetrievalSettings{}.contact_speed_share));
            CHECK(high.d_target_m == Approx((high.contact_point_world - Eigen::Vector3d(0.0, high_y, 0.6)).norm()).margin(1e-6));
            CHECK(low.d_target_m == Approx((low.contact_point_world - Eigen::Vector3d(0.0, low_y, 0.6)).norm()).margin(1e-6));
            CHECK(high.contact_point_world.y() >= low.contact_point_world.y() - 1e-9);
            CHECK(std::abs(high.contact_point_world.y() - high_y) <= std::abs(low.contact_point_world.y() - high_y) + 1e-9);
            CHECK(high.contact_point_world.z() > 0.2); // in front
            // Scored on the target alone, no start of the order has its hit point nearer the target.
            query.target_world = Eigen::Vector3d(0.0, high_y, 0.6);
            const RetrievalResult nearest = by_target.query_exhaustive(query);
            REQUIRE(nearest.found);
            CHECK(nearest.d_target_m <= high.d_target_m + 1e-9);
            CHECK(by_target.query(query, workspace).d_target_m == Approx(nearest.d_target_m).margin(1e-9));
        }
    }
}

TEST_CASE("retrieval: with a speed share the contact comes before the hit point slows, at its speed", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    int strikes = 0, earlier = 0;
    std::vector<double> speed_share_at_contact;
    for (const DbClip& clip : db.clips) {
        if (!db_clip_is_strike(clip) || clip.hit_frame < 0) continue;
        ++strikes;
        const int by_extension = db_clip_contact_frame(db, clip, 0.9);
        const int contact = db_clip_contact_frame(db, clip, 0.9, 0.85);
        CHECK(contact >= 0);
        CHECK(contact <= by_extension); // never later than by extension alone
        earlier += contact < by_extension;
        auto point = [&](int f) {
            const float* p = db.poses[clip.first_pose + f].hit_point;
            return Eigen::Vector3d(p[0], p[1], p[2]);
        };
        // The step into the contact against the fastest step from the start to it.
        double fastest = 0.0;
        for (int f = 1; f <= contact; ++f) fastest = std::max(fastest, (point(f) - point(f - 1)).norm());
        if (contact > 0 && fastest > 0.0) speed_share_at_contact.push_back((point(contact) - point(contact - 1)).norm() / fastest);
    }
    REQUIRE(strikes > 100);
    CHECK(earlier > strikes / 4); // the punches that decelerate before nine tenths of their way
    std::sort(speed_share_at_contact.begin(), speed_share_at_contact.end());
    // Most strikes meet their target at (nearly) their top speed; a few wind up faster than they strike.
    CHECK(speed_share_at_contact[speed_share_at_contact.size() / 2] >= 0.85);
}

TEST_CASE("retrieval: a contact frame between the travel's farthest point and the hit, the hit itself at full extension", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    int strikes = 0, earlier = 0;
    for (const DbClip& clip : db.clips) {
        if (!db_clip_is_strike(clip) || clip.hit_frame < 0) {
            CHECK(db_clip_contact_frame(db, clip, 0.9) == -1);
            continue;
        }
        ++strikes;
        CHECK(db_clip_contact_frame(db, clip, 1.0) == clip.hit_frame);
        const int contact = db_clip_contact_frame(db, clip, 0.9);
        CHECK(contact >= 0);
        CHECK(contact <= clip.hit_frame);
        CHECK(db_clip_contact_frame(db, clip, 0.5) <= contact); // half way comes first
        earlier += contact < clip.hit_frame;
        // There the hit point is within a tenth of its way from the hit.
        const float* at = db.poses[clip.first_pose + contact].hit_point;
        const float* hit = db.poses[clip.first_pose + clip.hit_frame].hit_point;
        double farthest = 0.0;
        for (int f = 0; f <= clip.hit_frame; ++f) {
            const float* p = db.poses[clip.first_pose + f].hit_point;
            farthest = std::max(farthest, Eigen::Vector3d(p[0] - hit[0], p[1] - hit[1], p[2] - hit[2]).norm());
        }
        CHECK(Eigen::Vector3d(at[0] - hit[0], at[1] - hit[1], at[2] - hit[2]).norm() <= 0.1 * farthest + 1e-6);
    }
    REQUIRE(strikes > 100);
    CHECK(earlier > strikes / 3); // 423 of 928 in the reference database still travel a frame or more before their annotated hit
    // With contact_extension 1 the retrieval lands strikes at their annotated hits (the paper's contact).
    RetrievalSettings at_hit;
    at_hit.contact_extension = 1.0;
    const Retriever retriever(db, at_hit);
    RetrievalWorkspace workspace = retriever.make_workspace();
    const Standing standing("brawler", db);
    RetrievalQuery query = standing.query;
    query.semantics = retriever.semantics_id("punch");
    query.target_world = Eigen::Vector3d(0.0, standing.head_y, 0.6);
    const RetrievalResult found = retriever.query(query, workspace);
    REQUIRE(found.found);
    CHECK(found.contact_frame == db.clips[found.clip].hit_frame);
}

TEST_CASE("retrieval: the fast path agrees with the exhaustive reference, with every index layout", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    // The default, deep trees (a candidate per leaf), and trees per cluster with the centroid bound on every order.
    RetrievalSettings deep, per_cluster;
    deep.leaf_size = 1;
    per_cluster.trees_per_cluster = true;
    per_cluster.leaf_size = 4;
    per_cluster.scan_below = 0;
    for (const RetrievalSettings& settings : {RetrievalSettings{}, deep, per_cluster}) {
        const Retriever retriever(db, settings);
        RetrievalWorkspace workspace = retriever.make_workspace();
        SplitMix64 random{17};
        int agreed = 0, total = 0, pruned = 0;
        for (const char* name : k_characters) {
            Standing standing(name, db);
            for (int i = 0; i < 60; ++i) {
                RetrievalQuery query = standing.query;
                query.semantics = retriever.semantics_id(i % 3 == 0 ? "kick" : i % 3 == 1 ? "punch" : "slash");
                query.side = static_cast<Side>(i % 3);
                query.target_world = Eigen::Vector3d(random.uniform(-0.6, 0.6), random.uniform(0.3, 2.2), random.uniform(-0.2, 1.5));
                const RetrievalResult fast = retriever.query(query, workspace);
                const RetrievalResult exhaustive = retriever.query_exhaustive(query);
                REQUIRE(fast.found == exhaustive.found);
                ++total;
                agreed += fast.score <= exhaustive.score * (1.0 + 1e-9) + 1e-12;
                CHECK(fast.counts.target_scored <= exhaustive.counts.target_scored);
                pruned += fast.counts.candidates_seen < exhaustive.counts.candidates_seen;
            }
        }
        CHECK(agreed == total);
        CHECK(pruned > total / 2); // the bounds skip candidates without looking at them
    }
}

TEST_CASE("retrieval: concurrent queries on one retriever give the single-threaded answers", "[retrieval][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    Standing standing("runner", db);
    std::vector<RetrievalQuery> queries;
    SplitMix64 random{23};
    for (int i = 0; i < 400; ++i) {
        RetrievalQuery query = standing.query;
        query.semantics = retriever.semantics_id(i % 2 ? "kick" : "punch");
        query.target_world = Eigen::Vector3d(random.uniform(-0.5, 0.5), random.uniform(0.8, 1.8), random.uniform(0.3, 1.0));
        queries.push_back(query);
    }
    std::vector<RetrievalResult> alone(queries.size()), together(queries.size());
    RetrievalWorkspace workspace = retriever.make_workspace();
    for (std::size_t i = 0; i < queries.size(); ++i) alone[i] = retriever.query(queries[i], workspace);
    auto run = [&](std::size_t first) {
        RetrievalWorkspace own = retriever.make_workspace();
        for (std::size_t i = first; i < queries.size(); i += 2) together[i] = retriever.query(queries[i], own);
    };
    std::thread other(run, 1);
    run(0);
    other.join();
    for (std::size_t i = 0; i < queries.size(); ++i) {
        CHECK(together[i].clip == alone[i].clip);
        CHECK(together[i].start_frame == alone[i].start_frame);
        CHECK(together[i].score == alone[i].score);
    }
}
