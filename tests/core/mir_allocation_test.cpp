// The per-frame retargeting path must not allocate (STYLE.md 5): global operator new is counted while encode and
// decode run, after a first call has sized the reused frame and pose. Its own executable, since it replaces the
// global allocation functions (support/allocation_counter.cpp).

#include "kumite/core/mir.h"
#include "kumite/formats/bvh_reader.h"
#include "support/allocation_counter.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

TEST_CASE("mir: encode and decode allocate nothing per frame", "[core][corpus]") {
    const std::filesystem::path capture = kumite::test::mocap_root() / "bandai-namco-1/dataset-1_kick_normal_001.bvh";
    const std::filesystem::path character = kumite::test::source_dir() / "data/characters/scout.bvh";
    if (!std::filesystem::exists(capture)) return;
    Result<BvhFile> source = bvh_read_file(capture);
    Result<BvhFile> target = bvh_read_file(character);
    REQUIRE(source.has_value());
    REQUIRE(target.has_value());
    Result<RestAnatomy> source_anatomy = rest_anatomy_build(source->clip, source->body_map);
    Result<RestAnatomy> target_anatomy = rest_anatomy_build(target->clip, target->body_map);
    REQUIRE(source_anatomy.has_value());
    REQUIRE(target_anatomy.has_value());
    MirEncoder encoder(source->clip.skeleton, *source_anatomy);
    MirDecoder decoder(target->clip.skeleton, *target_anatomy, source->clip.skeleton.names);
    MirFrame frame;
    Pose pose;
    LimbPins pins;
    pins.pinned[2] = true;
    pins.extremity_world[2] = Eigen::Vector3d(0.1, 0.08, 0.2);
    encoder.encode(frame, source->clip.pose(0)); // sizes the reused frame and pose
    decoder.decode(pose, frame);

    {
        kumite::test::AllocationScope scope;
        for (int f = 0; f < source->clip.frame_count(); ++f) {
            encoder.encode(frame, source->clip.pose(f));
            decoder.decode(pose, frame);
            decoder.decode(pose, frame, pins);
        }
        CHECK(scope.count() == 0);
    }
    // The counter does count: a vector inside the window is seen.
    kumite::test::AllocationScope scope;
    std::vector<int> probe(3);
    CHECK(scope.count() == 1);
}
