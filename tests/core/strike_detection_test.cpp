// Strike suggestions on the reference captures: the frames an animator would mark, within 4 frames, and at most
// one false strike per file.

#include "kumite/core/strike_detection.h"
#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

void check_strikes(const std::string& relative, StrikeSemantics semantics, BodyPart segment, std::vector<int> expected) {
    const std::filesystem::path path = kumite::test::mocap_root() / relative;
    if (!std::filesystem::exists(path)) {
        WARN("missing " << path);
        return;
    }
    Result<BvhFile> file = bvh_read_file(path);
    REQUIRE(file.has_value());
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    REQUIRE(anatomy.has_value());
    const std::vector<StrikeSuggestion> strikes = strikes_detect(file->clip, *anatomy);
    INFO(relative);
    int matched = 0;
    for (int frame : expected) {
        const bool found = std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& strike) {
            return strike.semantics == semantics && strike.segment == segment && std::abs(strike.hit_frame - frame) <= 4;
        });
        INFO("expected a strike near frame " << frame);
        CHECK(found);
        matched += found;
    }
    CHECK(static_cast<int>(strikes.size()) - matched <= 1);
    for (const StrikeSuggestion& strike : strikes) {
        CHECK(strike.first_frame <= strike.hit_frame);
        CHECK(strike.hit_frame <= strike.last_frame);
        CHECK(strike.confidence >= 0.0);
        CHECK(strike.confidence <= 1.0);
    }
}

} // namespace

TEST_CASE("strike_detection: the Bandai right kicks", "[core][corpus]") {
    check_strikes("bandai-namco-1/dataset-1_kick_normal_001.bvh", StrikeSemantics::kick, BodyPart::foot_r, {60, 194, 326});
}

TEST_CASE("strike_detection: the Bandai left and right punches", "[core][corpus]") {
    check_strikes("bandai-namco-1/dataset-1_punch_normal_001.bvh", StrikeSemantics::punch, BodyPart::hand_l, {29, 70, 113, 155, 198});
    check_strikes("bandai-namco-1/dataset-1_punch_normal_002.bvh", StrikeSemantics::punch, BodyPart::hand_r, {53, 107, 153, 205, 252});
}

TEST_CASE("strike_detection: walking and running are not strikes", "[core][corpus]") {
    check_strikes("bandai-namco-1/dataset-1_walk_normal_001.bvh", StrikeSemantics::punch, BodyPart::hand_r, {});
    check_strikes("bandai-namco-1/dataset-1_run_normal_001.bvh", StrikeSemantics::punch, BodyPart::hand_r, {});
}
