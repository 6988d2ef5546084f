// End-to-end on the real captures: every shared file parses, with a plausible unit, height and body map.

#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace kumite;

namespace {

Result<BvhFile> read_reference(const std::string& relative) {
    const std::filesystem::path path = kumite::test::mocap_root() / relative;
    if (!std::filesystem::exists(path)) return make_error(ErrorCode::io, "missing " + path.string());
    return bvh_read_file(path);
}

} // namespace

TEST_CASE("bvh_corpus: every shared capture parses with a human height", "[formats][corpus]") {
    const std::vector<std::filesystem::path> files = kumite::test::corpus_files();
    if (files.empty()) {
        WARN("no captures under " << kumite::test::mocap_root() << " (run scripts/fetch_mocap.sh)");
        return;
    }
    int humanoids = 0;
    for (const std::filesystem::path& path : files) {
        Result<BvhFile> file = bvh_read_file(path);
        INFO(path.string() << ": " << (file ? "" : file.error().message));
        REQUIRE(file.has_value());
        CHECK(file->clip.frame_count() > 0);
        CHECK(file->clip.skeleton.joint_count() > 0);
        // A rate from the file is a plausible capture rate; a file without one says so in a warning.
        if (file->frame_rate_in_file) {
            CHECK(1.0 / file->clip.frame_time_s >= 10.0);
            CHECK(1.0 / file->clip.frame_time_s <= 1000.0);
        } else {
            CHECK_FALSE(file->clip.has_frame_rate());
            CHECK(std::any_of(file->warnings.begin(), file->warnings.end(),
                              [](const std::string& warning) { return warning.find("no frame rate") != std::string::npos; }));
        }
        if (file->body_map.mapped_count() >= 13) {
            ++humanoids;
            CHECK(file->height_m > 1.0);
            CHECK(file->height_m < 2.2);
        }
    }
    CHECK(humanoids >= static_cast<int>(files.size()) - 2); // the two synthetic sinusoid chains are not humans
}

TEST_CASE("bvh_corpus: units of the reference captures", "[formats][corpus]") {
    struct Case { const char* file; const char* unit; };
    for (const Case& c : {Case{"bandai-namco-1/dataset-1_kick_normal_001.bvh", "cm"}, Case{"cmu-hahne-mb/02_05.bvh", "cmu"},
                          Case{"cmu131-bvh11/scaled_131_01.bvh", "m"}, Case{"cmu-iclone-cc4/002_05.bvh", "cm"},
                          Case{"mass-snu/balance.bvh", "cm"}}) {
        Result<BvhFile> file = read_reference(c.file);
        if (!file) {
            WARN(file.error().message);
            continue;
        }
        INFO(c.file);
        CHECK(file->unit.name == c.unit);
    }
}

TEST_CASE("bvh_corpus: body map complete for Bandai, CMU, Mixamo, MotionBuilder and CC4 skeletons", "[formats][corpus]") {
    for (const char* relative : {"bandai-namco-1/dataset-1_kick_normal_001.bvh", "cmu-hahne-mb/02_05.bvh",
                                 "bvh-python-tests/test_freebvh.bvh", "mass-snu/balance.bvh", "cmu-iclone-cc4/002_05.bvh",
                                 "cmu131-bvh11/131_01.bvh", "fairmotion-tests/pfnn_hierarchy.bvh"}) {
        Result<BvhFile> file = read_reference(relative);
        if (!file) {
            WARN(file.error().message);
            continue;
        }
        INFO(relative);
        CHECK(file->body_map.mapped_count() == k_body_part_count);
    }
}

TEST_CASE("bvh_corpus: one skeleton gets one height across its clips", "[formats][corpus]") {
    Result<BvhFile> kick = read_reference("bandai-namco-1/dataset-1_kick_normal_001.bvh");
    Result<BvhFile> walk = read_reference("bandai-namco-1/dataset-1_walk_normal_001.bvh");
    if (!kick || !walk) {
        WARN("Bandai captures missing");
        return;
    }
    CHECK(kick->height_m == Approx(walk->height_m).margin(0.02));
}
