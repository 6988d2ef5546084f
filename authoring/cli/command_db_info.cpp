// kumite db-info: what a motion database holds, and whether it opens (and, with --verify, verifies) cleanly.

#include "capture_loading.h"
#include "commands.h"

#include "kumite/core/contact_point.h"
#include "kumite/formats/motion_database_file.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <algorithm>
#include <map>
#include <tuple>
#include <vector>

namespace kumite::cli {

const CommandSpec& db_info_spec() {
    static const CommandSpec spec{
        "db-info",
        "DB.kdb [--verify] [--json]",
        "Maps a motion database, checks its structure (header, sections, actors, clips, clusters: what opening checks,\n"
        "in the same time for any number of poses) and summarises it: clips, poses, clusters, actors and strikes (blocks\n"
        "too) by semantics and side, and by semantics x kind x height x side (the strikes' labels). --verify also checks\n"
        "every per-pose value (pose records, MIR frames, features, cluster members) and the content hash. A corrupt,\n"
        "truncated or foreign file exits with status 1 and says what is wrong and where.",
        1, 1,
        {verify_flag(), json_flag()}};
    return spec;
}

namespace {

const char* side_name(std::uint32_t side) {
    return side == static_cast<std::uint32_t>(Side::left) ? "left" : side == static_cast<std::uint32_t>(Side::right) ? "right" : "none";
}

// `verify_us` < 0: not verified.
nlohmann::json summary_json(const MotionDatabase& database, double open_us, double verify_us) {
    const bool verified = verify_us >= 0.0;
    const MotionDatabaseView& db = database.view();
    nlohmann::json strikes = {{"punch", {{"left", 0}, {"right", 0}}},
                              {"kick", {{"left", 0}, {"right", 0}}},
                              {"knee", {{"left", 0}, {"right", 0}}},
                              {"elbow", {{"left", 0}, {"right", 0}}}};
    nlohmann::json motions = nlohmann::json::object();
    nlohmann::json kinds = nlohmann::json::object(), heights = nlohmann::json::object();
    std::map<std::tuple<std::string, int, int, std::uint32_t>, int> labels; // semantics, kind, height, side
    int strikes_captured = 0, blocks_captured = 0; // before mirroring
    std::vector<std::uint32_t> strike_actors;
    for (const DbClip& clip : db.clips) {
        const std::string semantics(db.string(clip.semantics));
        if (db_clip_is_strike(clip)) {
            const auto count_in = [&](nlohmann::json& table, const char* label) {
                nlohmann::json& counts = table[semantics][label];
                if (counts.is_null()) counts = {{"left", 0}, {"right", 0}};
                counts[side_name(clip.side)] = counts.value(side_name(clip.side), 0) + 1;
            };
            count_in(kinds, strike_kind_name(clip.strike_kind()));
            count_in(heights, strike_height_name(clip.strike_height()));
            ++labels[{semantics, clip.kind, clip.height, clip.side}];
            // Blocks (the defence's moves) are listed with the strikes by side, but not counted among the strikes
            // the fighter throws.
            if (semantics_is_block(semantics)) {
                blocks_captured += (clip.flags & db_clip_mirrored) == 0;
            } else {
                strikes_captured += (clip.flags & db_clip_mirrored) == 0;
                if (std::find(strike_actors.begin(), strike_actors.end(), clip.actor) == strike_actors.end()) strike_actors.push_back(clip.actor);
            }
            nlohmann::json& counts = strikes[semantics];
            if (counts.is_null()) counts = {{"left", 0}, {"right", 0}};
            counts[side_name(clip.side)] = counts.value(side_name(clip.side), 0) + 1;
        } else {
            motions[semantics] = motions.value(semantics, 0) + 1;
        }
    }
    nlohmann::json label_list = nlohmann::json::array();
    for (const auto& [key, count] : labels) {
        const auto& [semantics, kind, height, side] = key;
        label_list.push_back({{"semantics", semantics}, {"kind", strike_kind_name(static_cast<StrikeKind>(kind))},
                              {"height", strike_height_name(static_cast<StrikeHeight>(height))}, {"side", side_name(side)}, {"clips", count}});
    }
    nlohmann::json actors = nlohmann::json::array();
    for (const DbActor& actor : db.actors) {
        actors.push_back({{"name", db.string(actor.name)}, {"leg_length_m", actor.leg_length_m}, {"height_m", actor.height_m}});
    }
    nlohmann::json sections = nlohmann::json::array();
    for (const DatabaseSection& section : database.image().sections()) {
        sections.push_back({{"tag", section_tag_name(section.tag)}, {"offset", section.offset}, {"count", section.count},
                            {"bytes", section.bytes.size()}});
    }
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(database.image().content_hash()));
    return {{"format_version", database.image().format_version()},
            {"bytes", database.image().byte_size()},
            {"hash", hash},
            {"hash_verified", verified},
            {"values_verified", verified},
            {"clips", db.clips.size()},
            {"poses", db.poses.size()},
            {"clusters", db.clusters.size()},
            {"actors", db.actors.size()},
            {"actor_list", actors},
            {"strikes", strikes},
            {"strikes_before_mirroring", strikes_captured},
            {"strike_actors", strike_actors.size()},
            {"blocks_before_mirroring", blocks_captured},
            {"kinds", kinds},
            {"heights", heights},
            {"labels", label_list},
            {"motions", motions},
            {"frame_time_s", db.meta.frame_time_s},
            {"sections", sections},
            {"open_us", open_us},
            {"verify_us", verified ? nlohmann::json(verify_us) : nlohmann::json(nullptr)}};
}

} // namespace

int run_db_info(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(db_info_spec(), argc, argv, arguments)) return *status;
    const bool verify = arguments.has("verify");
    const auto microseconds_since = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    };
    const auto started = std::chrono::steady_clock::now();
    Result<MotionDatabase> database = MotionDatabase::open(arguments.positionals[0]);
    const double open_us = microseconds_since(started);
    if (!database) return input_error(database.error().message);
    double verify_us = -1.0;
    if (verify) {
        const auto verify_started = std::chrono::steady_clock::now();
        if (Result<void> verified = database->verify(); !verified) return input_error(verified.error().message);
        verify_us = microseconds_since(verify_started);
    }
    const nlohmann::json summary = summary_json(*database, open_us, verify_us);
    if (arguments.has("json")) {
        print_json(summary);
        return k_exit_ok;
    }
    std::cout << arguments.positionals[0] << ": kumite database version " << summary["format_version"] << ", " << summary["bytes"]
              << " bytes, hash " << summary["hash"].get<std::string>() << (verify ? " (verified)" : "") << "\n"
              << "  " << summary["clips"] << " clips, " << summary["poses"] << " poses, " << summary["clusters"] << " clusters, "
              << summary["actors"] << " actors, " << 1.0 / summary["frame_time_s"].get<double>() << " fps\n";
    for (const auto& [semantics, counts] : summary["strikes"].items()) {
        std::cout << "  " << semantics << ": " << counts["left"] << " left, " << counts["right"] << " right\n";
    }
    std::cout << "  " << summary["strikes_before_mirroring"] << " strikes before mirroring, from " << summary["strike_actors"] << " actors\n";
    std::cout << "  " << summary["blocks_before_mirroring"] << " blocks before mirroring\n";
    for (const auto& [semantics, count] : summary["motions"].items()) std::cout << "  " << semantics << ": " << count << "\n";
    std::cout << "  strikes by kind, height and side:\n";
    std::string last;
    for (const auto& row : summary["labels"]) {
        const std::string what = row["semantics"].get<std::string>() + " " + row["kind"].get<std::string>() + " " + row["height"].get<std::string>();
        if (what == last) continue;
        last = what;
        int left = 0, right = 0;
        for (const auto& other : summary["labels"]) {
            if (other["semantics"] != row["semantics"] || other["kind"] != row["kind"] || other["height"] != row["height"]) continue;
            (other["side"] == "left" ? left : right) += other["clips"].get<int>();
        }
        std::printf("    %-28s %3d left, %3d right\n", what.c_str(), left, right);
    }
    std::printf("  opened in %.0f us", open_us);
    if (verify) std::printf(", every value and the hash verified in %.0f us", verify_us);
    std::printf("\n");
    return k_exit_ok;
}

} // namespace kumite::cli
