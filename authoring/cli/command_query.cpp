// kumite query: the strike the retrieval picks for a character standing at the origin and a target.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"
#include "fighter_setup.h"
#include "strike_reports.h"


#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace kumite::cli {

const CommandSpec& query_spec() {
    static const CommandSpec spec{
        "query",
        "[DB.kdb] --character NAME (--target X,Y,Z | --targets FILE.csv) --command SEMANTICS [--side left|right|any] [--kind KIND] [--height H] [--exhaustive] [--verify] [--json]",
        "Retrieves the strike clip and start pose that suit a character standing at the origin, facing +Z, in\n"
        "the database's guard pose, and a target in world metres (Y up). A k-d tree of pose keys and hit points\n"
        "is searched best bound first with exact bounds; --exhaustive scores every start of every clip instead (the\n"
        "slow reference).",
        0, 1,
        {{"character", "NAME", "a character of data/characters (see kumite characters)"},
         {"target", "X,Y,Z", "the target, world metres"},
         {"targets", "FILE.csv", "one x,y,z per line ('#' comments); prints a list of results"},
         {"command", "SEMANTICS", "punch, kick, or any strike semantics the database holds"},
         {"side", "left|right|any", "which side strikes (default any)"},
         kind_flag(),
         height_flag(),
         {"exhaustive", "", "use the exhaustive reference search"},
         {"scaling", "leg|limb", "bring actors' hit paths to the character by leg length (default) or by the striking limb"},
         characters_dir_flag(), verify_flag(), json_flag()}};
    return spec;
}

namespace {

Result<std::vector<Eigen::Vector3d>> read_targets(const std::string& path) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the targets file");
    std::vector<Eigen::Vector3d> targets;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        Result<Eigen::Vector3d> point = parse_point(line, path + ":" + std::to_string(number));
        if (!point) return point.error();
        targets.push_back(*point);
    }
    if (targets.empty()) return make_error(ErrorCode::invalid, path + ": no targets");
    return targets;
}

} // namespace

int run_query(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(query_spec(), argc, argv, arguments)) return *status;
    if (arguments.value("target").has_value() == arguments.value("targets").has_value()) {
        return usage_error(query_spec(), "give exactly one of --target X,Y,Z and --targets FILE.csv");
    }
    std::vector<Eigen::Vector3d> targets;
    if (const std::optional<std::string> text = arguments.value("target")) {
        Result<Eigen::Vector3d> point = parse_point(*text, "--target");
        if (!point) return usage_error(query_spec(), point.error().message);
        targets.push_back(*point);
    } else {
        Result<std::vector<Eigen::Vector3d>> read = read_targets(*arguments.value("targets"));
        if (!read) return input_error(read.error().message);
        targets = std::move(*read);
    }

    FighterSetup setup;
    if (std::optional<int> status = fighter_setup(setup, query_spec(), arguments)) return *status;
    const Retriever& retriever = *setup.stage->retriever;
    RetrievalQuery query = setup.stage->query;
    RetrievalWorkspace workspace = retriever.make_workspace();
    const bool exhaustive = arguments.has("exhaustive");

    nlohmann::json results = nlohmann::json::array();
    const auto all_started = std::chrono::steady_clock::now();
    for (const Eigen::Vector3d& target : targets) {
        query.target_world = target;
        const auto started = std::chrono::steady_clock::now();
        const RetrievalResult result = exhaustive ? retriever.query_exhaustive(query) : retriever.query(query, workspace);
        const double latency_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
        if (!result.found) {
            return input_error(setup.database_path + ": no " + strike_order_description(*arguments.value("command"), query.side, query.kind, query.height) +
                               " has a start far enough before its hit");
        }
        results.push_back(query_result_json(retriever, result, latency_us));
    }
    const double total_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - all_started).count();

    const bool many = arguments.value("targets").has_value();
    if (arguments.has("json")) {
        print_json(many ? nlohmann::json{{"results", results}, {"total_us", total_us}} : results[0]);
        return k_exit_ok;
    }
    for (std::size_t i = 0; i < results.size(); ++i) {
        const nlohmann::json& r = results[i];
        std::printf("target %.2f,%.2f,%.2f: %s (%s %s %s %s, %s) start %d contact %d in %.2f s; d_pose %.3f d_target %.3f m score %.3f; %.1f us\n",
                    targets[i].x(), targets[i].y(), targets[i].z(), r["clip"].get<std::string>().c_str(),
                    r["semantics"].get<std::string>().c_str(), r["side"].get<std::string>().c_str(), r["kind"].get<std::string>().c_str(),
                    r["height"].get<std::string>().c_str(), r["segment"].get<std::string>().c_str(),
                    r["start_frame"].get<int>(), r["contact_frame"].get<int>(), r["time_to_contact_s"].get<double>(),
                    r["d_pose"].get<double>(), r["d_target"].get<double>(), r["score"].get<double>(), r["latency_us"].get<double>());
    }
    return k_exit_ok;
}

} // namespace kumite::cli
