// Strike suggestions on the reference captures: the frames an animator would mark, within 4 frames, and at most
// one false strike per file.

#include "kumite/core/strike_detection.h"
#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

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

namespace {

std::vector<StrikeSuggestion> detect(const std::string& relative) {
    const std::filesystem::path path = kumite::test::mocap_root() / relative;
    if (!std::filesystem::exists(path)) return {};
    Result<BvhFile> file = bvh_read_file(path);
    REQUIRE(file.has_value());
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    REQUIRE(anatomy.has_value());
    return strikes_detect(file->clip, *anatomy);
}

} // namespace

TEST_CASE("strike_labels: CMU 02_05's nine strikes, three high, then middle, then low from a crouch, all straight", "[core][corpus]") {
    // Hand-checked: the subject strikes three times above the shoulder, three at the chest and three low from a
    // crouch (hand 0.4 arm length under the shoulder, which the old 0.3 rule missed).
    const std::vector<StrikeSuggestion> strikes = detect("cmu-hahne-mb/02_05.bvh");
    if (strikes.empty()) return;
    REQUIRE(strikes.size() == 9);
    const StrikeHeight expected[] = {StrikeHeight::high,   StrikeHeight::high,   StrikeHeight::high,
                                     StrikeHeight::middle, StrikeHeight::middle, StrikeHeight::middle,
                                     StrikeHeight::low,    StrikeHeight::low,    StrikeHeight::low};
    for (std::size_t k = 0; k < strikes.size(); ++k) {
        INFO("strike " << k << " at frame " << strikes[k].hit_frame << ", hit " << strikes[k].labels.hit_height_m << " m");
        CHECK(strikes[k].labels.kind == StrikeKind::straight);
        CHECK(strikes[k].labels.height == expected[k]);
        CHECK(strikes[k].labels.hip_height_m < strikes[k].labels.shoulder_height_m);
    }
    // The 8th lands on the hip line (1 cm over it at its peak extension, under it as the fist arrives, which is
    // the hit): the rule is a threshold, and it says so in the numbers.
    CHECK(std::abs(strikes[7].labels.hit_height_m - strikes[7].labels.hip_height_m) < 0.05);
}

TEST_CASE("strike_labels: the Bandai punches are straight, its kicks front kicks at middle height", "[core][corpus]") {
    for (const char* file : {"bandai-namco-1/dataset-1_punch_normal_001.bvh", "bandai-namco-1/dataset-1_punch_normal_002.bvh"}) {
        for (const StrikeSuggestion& strike : detect(file)) {
            INFO(file << " frame " << strike.hit_frame);
            CHECK(strike.labels.kind == StrikeKind::straight);
            CHECK(strike.labels.height != StrikeHeight::low);
        }
    }
    for (const StrikeSuggestion& strike : detect("bandai-namco-1/dataset-1_kick_normal_001.bvh")) {
        INFO("kick at frame " << strike.hit_frame);
        CHECK(strike.labels.kind == StrikeKind::front);
        CHECK(strike.labels.height == StrikeHeight::middle);
        CHECK(strike.labels.approach_up_m > 0.3); // the foot rises into the hit
    }
}

TEST_CASE("strike_labels: names, kinds per semantics and the height thresholds", "[core]") {
    for (int k = 0; k < k_strike_kind_count; ++k) {
        const StrikeKind kind = static_cast<StrikeKind>(k);
        CHECK(strike_kind_from_name(strike_kind_name(kind)) == kind);
    }
    for (int h = 0; h < k_strike_height_count; ++h) {
        const StrikeHeight height = static_cast<StrikeHeight>(h);
        CHECK(strike_height_from_name(strike_height_name(height)) == height);
    }
    CHECK_FALSE(strike_kind_from_name("haymaker").has_value());
    CHECK(strike_kind_fits("punch", StrikeKind::hook));
    CHECK_FALSE(strike_kind_fits("punch", StrikeKind::roundhouse));
    CHECK(strike_kind_fits("kick", StrikeKind::side));
    CHECK_FALSE(strike_kind_fits("kick", StrikeKind::uppercut));
    CHECK(strike_kind_fits("slash", StrikeKind::other));
    CHECK_FALSE(strike_kind_fits("slash", StrikeKind::straight));
    const StrikeHeightThresholds thresholds{0.9, 1.4};
    CHECK(strike_height_of(0.5, thresholds) == StrikeHeight::low);
    CHECK(strike_height_of(1.1, thresholds) == StrikeHeight::middle);
    CHECK(strike_height_of(1.6, thresholds) == StrikeHeight::high);
}

TEST_CASE("strike_detection: karate techniques one per file: kicks, knees, elbows and blocks found on their side, blocks not taken for strikes",
          "[core][corpus]") {
    const std::filesystem::path folder = kumite::test::mocap_root() / "hachaj-shorinryu";
    if (!std::filesystem::exists(folder)) {
        WARN("missing " << folder);
        return;
    }
    struct Tally {
        int files = 0, found = 0, extra = 0, kinds_agree = 0;
    };
    std::map<std::string, Tally> tallies;
    BvhReadOptions at_100; // the files say 'Frame Time: 0'; the same author's captures are at 100 fps
    at_100.frame_rate_hz = 100.0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".bvh") continue;
        const std::string technique = name.substr(3, name.find("_left") != std::string::npos ? name.find("_left") - 3 : name.find("_right") - 3);
        const Side side = name.find("_left_") != std::string::npos ? Side::left : Side::right;
        Result<BvhFile> file = bvh_read_file(entry.path(), at_100);
        REQUIRE(file.has_value());
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        REQUIRE(anatomy.has_value());
        const std::vector<StrikeSuggestion> strikes = strikes_detect(file->clip, *anatomy);
        const bool is_block = technique == "age_uke" || technique == "gedan_barai";
        const StrikeSemantics expected = technique == "hiza_geri" ? StrikeSemantics::knee
                                         : technique == "empi"    ? StrikeSemantics::elbow
                                         : is_block               ? StrikeSemantics::block
                                                                  : StrikeSemantics::kick;
        const StrikeKind expected_block = technique == "age_uke" ? StrikeKind::rising : StrikeKind::downward;
        Tally& tally = tallies[technique];
        ++tally.files;
        int matched = 0;
        for (const StrikeSuggestion& strike : strikes) {
            const bool right = strike.semantics == expected && strike.side == side;
            matched += right;
            // Some series-2 gedan-barai files open with a block of the other arm: a block still, not a strike.
            tally.extra += !right && !(is_block && strike.semantics == StrikeSemantics::block);
            if (right && is_block) tally.kinds_agree += strike.labels.kind == expected_block;
        }
        tally.found += matched > 0;
    }
    for (const auto& [technique, tally] : tallies) {
        INFO(technique << ": " << tally.found << " of " << tally.files << " found, " << tally.extra << " other proposals");
        if (technique == "age_uke" || technique == "gedan_barai") {
            CHECK(tally.extra == 0); // no block proposed as a strike
            CHECK(tally.found >= tally.files * 3 / 4); // measured: age-uke 40 of 40, gedan-barai 31 of 40
            CHECK(tally.kinds_agree >= tally.found * 9 / 10);
        } else {
            CHECK(tally.found >= tally.files * 9 / 10);
            CHECK(tally.extra <= tally.files / 10);
        }
    }
}

TEST_CASE("strike_detection: in whole kata, arms swung across the forearm or down and knees lifted slowly are not strikes",
          "[core][corpus]") {
    // Fukyugata Ni (100 fps, as the folder's other files): looked at frame by frame. The left fist circles over the
    // head before 696 and 1942 (blocks) and sweeps down to 2314 (a downward block); the knee is lifted slowly at
    // 2129 and 2832 (stance changes); the left elbow is pulled back behind the shoulder at 3076 (hikite). The left
    // fist is thrust out at head height at 2698 and at the chest at 1082: punches.
    const std::vector<StrikeSuggestion> strikes = detect("hachaj-kata/fukyugata_ni.bvh");
    if (strikes.empty()) {
        WARN("missing hachaj-kata/fukyugata_ni.bvh");
        return;
    }
    auto near = [&](StrikeSemantics semantics, int frame) {
        return std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& strike) {
            return strike.semantics == semantics && std::abs(strike.hit_frame - frame) <= 15;
        });
    };
    for (int frame : {696, 1942, 2314}) {
        INFO("no punch near frame " << frame);
        CHECK_FALSE(near(StrikeSemantics::punch, frame));
    }
    for (int frame : {2129, 2832}) {
        INFO("no knee strike near frame " << frame);
        CHECK_FALSE(near(StrikeSemantics::knee, frame));
    }
    CHECK_FALSE(near(StrikeSemantics::elbow, 3076));
    CHECK(near(StrikeSemantics::punch, 2698));
    CHECK(near(StrikeSemantics::punch, 1082));
    CHECK(near(StrikeSemantics::elbow, 1906)); // the elbow strike after the left front kick
}

TEST_CASE("strike_detection: an arm opened with the fist still by the body is not a punch", "[core][corpus]") {
    // Looked at on filmstrips: in Fukyugata Ni (the first performer) the right arm opens to 100 degrees in front of
    // the face at 1274 before rising, the left holds a middle block at chest height at 2705; in Pinan Shodan the
    // right opens by the face at 285. Each extends the arm past 0.78 of its length, the fist 0.60-0.77 arm lengths
    // from the chest; the straight punches of the same kata reach 0.86 or more.
    struct Case {
        const char* file;
        int frame;
    };
    for (const Case& c : {Case{"hachaj-kata/0.2-fukyugata_ni.bvh", 1274}, Case{"hachaj-kata/0.2-fukyugata_ni.bvh", 2705},
                          Case{"hachaj-kata/1-pinian_shodan.bvh", 285}}) {
        const std::vector<StrikeSuggestion> strikes = detect(c.file);
        if (strikes.empty()) {
            WARN("missing " << c.file);
            continue;
        }
        INFO(c.file << ": no punch near frame " << c.frame);
        CHECK_FALSE(std::any_of(strikes.begin(), strikes.end(), [&](const StrikeSuggestion& strike) {
            return strike.semantics == StrikeSemantics::punch && std::abs(strike.hit_frame - c.frame) <= 15;
        }));
        // The same kata's punches are still found.
        CHECK(std::count_if(strikes.begin(), strikes.end(), [](const StrikeSuggestion& s) { return s.semantics == StrikeSemantics::punch; }) >= 4);
    }
}
