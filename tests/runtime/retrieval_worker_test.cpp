// The retrieval worker: answers match a direct query, newer requests supersede older ones, and the mailbox
// between threads only ever moves forward.

#include "kumite/core/character_rig.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/retrieval_worker.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

using namespace kumite;

namespace {

struct Fixture {
    MotionDatabase database;
    BvhFile character;
    RestAnatomy anatomy;
    std::array<float, k_feature_dimensions> feature{};
    HeadingFrame heading;
    CharacterSize size;

    Fixture() {
        Result<MotionDatabase> opened = MotionDatabase::open(kumite::test::source_dir() / "data/golden/golden-v2.kdb");
        REQUIRE(opened.has_value());
        database = std::move(*opened);
        Result<BvhFile> file = bvh_read_file(kumite::test::source_dir() / "data/characters/scout.bvh");
        REQUIRE(file.has_value());
        character = std::move(*file);
        Result<RestAnatomy> built = rest_anatomy_build(character.clip, character.body_map);
        REQUIRE(built.has_value());
        anatomy = std::move(*built);
        CharacterRig rig(character.clip.skeleton, anatomy);
        Pose pose;
        rig.stand_at_origin(pose, database.view());
        rig.still_feature(feature);
        heading = rig.heading();
        size = rig.size();
    }

    void fill(RetrievalRequest& request, const Retriever& retriever, int i) const {
        request.pose_feature = feature;
        request.heading = heading;
        request.character = size;
        request.semantics = retriever.semantics_id(i % 2 ? "kick" : "punch");
        request.side = Side::none;
        request.target_world = Eigen::Vector3d(0.01 * (i % 50) - 0.25, 0.9 + 0.005 * (i % 100), 0.6);
    }

    RetrievalResult direct(const Retriever& retriever, const RetrievalRequest& request) const {
        RetrievalWorkspace workspace = retriever.make_workspace();
        return retriever.query(request.query(), workspace);
    }
};

// Polls like a frame loop (1 ms frames) until `done` or 10 s.
template <class Done>
bool poll(Done&& done) {
    for (int frame = 0; frame < 10000; ++frame) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
}

} // namespace

TEST_CASE("retrieval_worker: an answer picked up at a later frame equals the direct query", "[runtime]") {
    const Fixture fixture;
    const Retriever retriever(fixture.database.view());
    RetrievalWorker worker(retriever);
    fixture.fill(worker.request(), retriever, 3);
    const RetrievalRequest sent = worker.request();
    const std::uint64_t ticket = worker.post();
    const RetrievalAnswer* answer = nullptr;
    REQUIRE(poll([&] { return (answer = worker.take_answer()) != nullptr; }));
    CHECK(answer->ticket == ticket);
    const RetrievalResult expected = fixture.direct(retriever, sent);
    REQUIRE(answer->result.found);
    CHECK(answer->result.clip == expected.clip);
    CHECK(answer->result.start_frame == expected.start_frame);
    CHECK(answer->result.score == expected.score);
    CHECK(worker.take_answer() == nullptr); // taken once
}

TEST_CASE("retrieval_worker: a burst of requests ends with the answer to the newest", "[runtime]") {
    const Fixture fixture;
    const Retriever retriever(fixture.database.view());
    RetrievalWorker worker(retriever);
    std::uint64_t last_ticket = 0;
    RetrievalRequest last;
    for (int i = 0; i < 300; ++i) {
        fixture.fill(worker.request(), retriever, i);
        last = worker.request();
        last_ticket = worker.post();
    }
    std::uint64_t newest_seen = 0;
    RetrievalResult newest;
    REQUIRE(poll([&] {
        while (const RetrievalAnswer* answer = worker.take_answer()) {
            CHECK(answer->ticket > newest_seen); // answers only move forward
            newest_seen = answer->ticket;
            newest = answer->result;
        }
        return newest_seen == last_ticket;
    }));
    CHECK(worker.answered() <= 300);
    CHECK(newest.score == fixture.direct(retriever, last).score);
}

TEST_CASE("latest_value: a consumer sees increasing values and finally the last one", "[runtime]") {
    LatestValue<std::array<long, 8>> mailbox;
    constexpr long count = 200000;
    std::thread producer([&] {
        for (long value = 1; value <= count; ++value) {
            mailbox.slot().fill(value); // a torn read would show mixed values
            mailbox.publish();
        }
    });
    long last = 0;
    bool consistent = true, increasing = true;
    while (last < count) {
        if (!mailbox.take()) continue;
        const std::array<long, 8>& value = mailbox.current();
        for (long v : value) consistent &= v == value[0];
        increasing &= value[0] > last;
        last = value[0];
    }
    producer.join();
    CHECK(consistent);
    CHECK(increasing);
    CHECK(last == count);
}
