// Strike suggestions on a performer the detection rules were not written on first: the SNU boxer (snu-boxing/),
// whose straights at head height, short jabs, hooks and uppercuts the kata-tuned rules missed or took for elbow
// strikes and blocks, whose covers and parries must not be taken for punches, and whose covers are blocks; and a
// karateka's middle blocks. Ground truth: data/evaluation/snu-boxing-moves.json (the moves of the folder's SOURCE.md)
// and data/annotations/reference.json. The whole leave-one-performer-out evaluation is scripts/suggest_lopo.py.

#include "kumite/core/strike_detection.h"
#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

using namespace kumite;

namespace {

struct Move {
    std::string semantics;
    Side side = Side::none;
    int hit_frame = 0;
};

std::map<std::string, std::vector<Move>> snu_moves() {
    const nlohmann::json moves = nlohmann::json::parse(kumite::test::read_text(kumite::test::source_dir() / "data/evaluation/snu-boxing-moves.json"));
    std::map<std::string, std::vector<Move>> by_source;
    for (const auto& move : moves["moves"]) {
        const std::string side = move["side"];
        by_source[move["source"]].push_back({move["semantics"], side == "left" ? Side::left : side == "right" ? Side::right : Side::none,
                                             move["hit_frame"].get<int>()});
    }
    return by_source;
}

std::optional<std::vector<StrikeSuggestion>> detect(const std::string& relative) {
    const std::filesystem::path path = kumite::test::mocap_root() / relative;
    if (!std::filesystem::exists(path)) return std::nullopt;
    Result<BvhFile> file = bvh_read_file(path);
    REQUIRE(file.has_value());
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    REQUIRE(anatomy.has_value());
    return strikes_detect(file->clip, *anatomy);
}

constexpr int k_tolerance = 8; // frames at 30 fps: the 0.25 s of suggest --compare

} // namespace

TEST_CASE("strike_detection: an unseen boxer's straights, jabs, hooks and uppercuts are found as punches on their side", "[core][corpus]") {
    // Measured: 86 of 94 found (6 short jabs that extend the arm by less than 0.3 missed, and the last left uppercut
    // as the take ends), 4 other strikes proposed; before the swing and the straight-arm rules 26 of 94, the hooks
    // taken for elbow strikes and the uppercuts for rising blocks. Covers proposed in these 180 s of punching: 12
    // (the lead hand lifted between straights, a hand raised after an uppercut's return), none where a punch lands.
    int moves_count = 0, found = 0, proposed = 0, mistaken = 0, covers = 0;
    for (const auto& [source, moves] : snu_moves()) {
        if (source.find("stand_dir") == std::string::npos) continue;
        const std::optional<std::vector<StrikeSuggestion>> strikes = detect(source);
        if (!strikes) {
            WARN("missing " << source);
            return;
        }
        int found_here = 0;
        for (const Move& move : moves) {
            found_here += std::any_of(strikes->begin(), strikes->end(), [&](const StrikeSuggestion& strike) {
                return strike.semantics == StrikeSemantics::punch && strike.side == move.side && std::abs(strike.hit_frame - move.hit_frame) <= k_tolerance;
            });
        }
        INFO(source << ": " << found_here << " of " << moves.size() << " punches found, " << strikes->size() << " strikes proposed");
        CHECK(found_here >= int(moves.size()) * 3 / 4); // the straights' take: 23 of 30, six short jabs missed
        // The swung fist is the strike: an elbow strike where a hook lands, or a block where an uppercut does, is not.
        for (const Move& move : moves) {
            mistaken += std::any_of(strikes->begin(), strikes->end(), [&](const StrikeSuggestion& strike) {
                return strike.semantics != StrikeSemantics::punch && strike.side == move.side && std::abs(strike.hit_frame - move.hit_frame) <= k_tolerance;
            });
        }
        moves_count += int(moves.size());
        found += found_here;
        for (const StrikeSuggestion& strike : *strikes) (strike.semantics == StrikeSemantics::block ? covers : proposed) += 1;
    }
    INFO(found << " of " << moves_count << " found, " << proposed << " strikes and " << covers << " blocks proposed, " << mistaken
               << " taken for other strikes or blocks");
    CHECK(found >= moves_count * 9 / 10);
    CHECK(mistaken <= 1); // the last left uppercut, 0.3 s before the take's end, is proposed as a rising block (was 23)
    CHECK(found >= proposed * 9 / 10);
    CHECK(covers <= 15);
}

TEST_CASE("strike_detection: an unseen boxer's covers, parries, ducks and hit reactions are not taken for strikes", "[core][corpus]") {
    for (const char* source : {"snu-boxing/boxman_blocking_dir.bvh", "snu-boxing/boxman_ducking_dir.bvh", "snu-boxing/boxman_hited_dir.bvh"}) {
        const std::optional<std::vector<StrikeSuggestion>> strikes = detect(source);
        if (!strikes) {
            WARN("missing " << source);
            continue;
        }
        INFO(source);
        CHECK(std::none_of(strikes->begin(), strikes->end(), [](const StrikeSuggestion& strike) {
            return strike.semantics == StrikeSemantics::punch || strike.semantics == StrikeSemantics::kick;
        }));
    }
}

TEST_CASE("strike_detection: an unseen boxer's covers and a karateka's middle blocks are proposed as blocks on their side", "[core][corpus]") {
    // The boxer's covers raise both gloves, or one, to the face and hold them there, slowly (1-2 m/s); the
    // karateka's outward and inward blocks snap an upright forearm up beside the head. Measured: 16 of the 32
    // defensive moves of boxman_blocking_dir (the both-handed and side covers; not the ten small pushes of the
    // lead hand, nor the low catch), 6 of the 7 blocks of 1-pinian_shodan. Before covers were looked for: 0 and 1.
    const std::optional<std::vector<StrikeSuggestion>> covers = detect("snu-boxing/boxman_blocking_dir.bvh");
    if (!covers) {
        WARN("missing snu-boxing/boxman_blocking_dir.bvh");
        return;
    }
    auto found_in = [](const std::vector<StrikeSuggestion>& proposed, const std::vector<Move>& moves, int tolerance) {
        int found = 0;
        for (const Move& move : moves) {
            found += std::any_of(proposed.begin(), proposed.end(), [&](const StrikeSuggestion& strike) {
                return strike.semantics == StrikeSemantics::block && (move.side == Side::none || strike.side == move.side) &&
                       std::abs(strike.hit_frame - move.hit_frame) <= tolerance;
            });
        }
        return found;
    };
    const std::vector<Move>& boxer = snu_moves()["snu-boxing/boxman_blocking_dir.bvh"];
    const int boxer_found = found_in(*covers, boxer, k_tolerance);
    INFO(boxer_found << " of " << boxer.size() << " of the boxer's defensive moves proposed as blocks");
    CHECK(boxer.size() == 32);
    CHECK(boxer_found >= 15);
    CHECK(std::none_of(covers->begin(), covers->end(), [](const StrikeSuggestion& strike) { return strike.semantics != StrikeSemantics::block; }));

    const std::optional<std::vector<StrikeSuggestion>> kata = detect("hachaj-kata/1-pinian_shodan.bvh");
    REQUIRE(kata);
    const nlohmann::json reference = nlohmann::json::parse(kumite::test::read_text(kumite::test::source_dir() / "data/annotations/reference.json"));
    std::vector<Move> blocks;
    for (const auto& clip : reference["clips"]) {
        if (clip.value("source", "") != "hachaj-kata/1-pinian_shodan.bvh" || clip.value("semantics", "") != "block") continue;
        blocks.push_back({"block", clip["side"] == "left" ? Side::left : Side::right, clip["hit_frame"].get<int>()});
    }
    const int kata_found = found_in(*kata, blocks, 25); // 0.25 s at the kata's 100 fps
    INFO(kata_found << " of " << blocks.size() << " of the kata's blocks proposed");
    CHECK(blocks.size() == 7);
    CHECK(kata_found >= 6);
}

TEST_CASE("strike_thresholds: names over the defaults, unknown names and bad numbers refused", "[core]") {
    const Result<StrikeThresholds> parsed = strike_thresholds_parse("punch_reach=0.7,swing_speed=9");
    REQUIRE(parsed.has_value());
    CHECK(parsed->punch_reach == Approx(0.7));
    CHECK(parsed->swing_speed == Approx(9.0));
    CHECK(parsed->punch_rise == Approx(StrikeThresholds{}.punch_rise));
    const Result<StrikeThresholds> unknown = strike_thresholds_parse("punch_reech=0.7");
    REQUIRE_FALSE(unknown.has_value());
    CHECK(unknown.error().message.find("punch_reach") != std::string::npos); // lists the names
    CHECK_FALSE(strike_thresholds_parse("punch_reach=far").has_value());
    CHECK_FALSE(strike_thresholds_parse("punch_reach").has_value());
}
