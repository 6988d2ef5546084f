// kumite db-info: what a motion database holds, and whether it opens (and, with --verify, hashes) cleanly.

#include "capture_loading.h"
#include "commands.h"

#include "kumite/formats/motion_database_file.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

namespace kumite::cli {

const CommandSpec& db_info_spec() {
    static const CommandSpec spec{
        "db-info",
        "DB.kdb [--verify] [--json]",
        "Maps and validates a motion database (header, sections, every index and value) and summarises it:\n"
        "clips, poses, clusters, actors and strikes by semantics and side. --verify also checks the content\n"
        "hash. A corrupt, truncated or foreign file exits with status 1 and says what is wrong and where.",
        1, 1,
        {{"verify", "", "also recompute the content hash"}, json_flag()}};
    return spec;
}

namespace {

const char* side_name(std::uint32_t side) {
    return side == static_cast<std::uint32_t>(Side::left) ? "left" : side == static_cast<std::uint32_t>(Side::right) ? "right" : "none";
}

nlohmann::json summary_json(const MotionDatabase& database, double open_us, bool verified) {
    const MotionDatabaseView& db = database.view();
    nlohmann::json strikes = {{"punch", {{"left", 0}, {"right", 0}}}, {"kick", {{"left", 0}, {"right", 0}}}};
    nlohmann::json motions = nlohmann::json::object();
    for (const DbClip& clip : db.clips) {
        const std::string semantics(db.string(clip.semantics));
        if (db_clip_is_strike(clip)) {
            nlohmann::json& counts = strikes[semantics];
            if (counts.is_null()) counts = {{"left", 0}, {"right", 0}};
            counts[side_name(clip.side)] = counts.value(side_name(clip.side), 0) + 1;
        } else {
            motions[semantics] = motions.value(semantics, 0) + 1;
        }
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
            {"clips", db.clips.size()},
            {"poses", db.poses.size()},
            {"clusters", db.clusters.size()},
            {"actors", db.actors.size()},
            {"actor_list", actors},
            {"strikes", strikes},
            {"motions", motions},
            {"frame_time_s", db.meta.frame_time_s},
            {"sections", sections},
            {"open_us", open_us}};
}

} // namespace

int run_db_info(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(db_info_spec(), argc, argv, arguments)) return *status;
    const bool verify = arguments.has("verify");
    const auto started = std::chrono::steady_clock::now();
    Result<MotionDatabase> database = MotionDatabase::open(arguments.positionals[0], verify);
    const double open_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
    if (!database) return input_error(database.error().message);
    const nlohmann::json summary = summary_json(*database, open_us, verify);
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
    for (const auto& [semantics, count] : summary["motions"].items()) std::cout << "  " << semantics << ": " << count << "\n";
    std::printf("  opened in %.0f us\n", open_us);
    return k_exit_ok;
}

} // namespace kumite::cli
