// kumite sessions: the training store's sessions, one line each (or one JSON document), of everyone or one trainee.

#include "capture_loading.h"
#include "commands.h"
#include "store_flags.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>

namespace kumite::cli {

const CommandSpec& sessions_spec() {
    static const CommandSpec spec{
        "sessions",
        "[--store PATH] [--trainee NAME] [--json]",
        "Lists the sessions of the training store (kumite train), oldest first: id, start (UTC), trainee, drill,\n"
        "duration and the fighter's attacks; `running` for the session a `kumite train` writes now, `incomplete` for one\n"
        "that did not end (killed, crashed: its duration and rows are those committed). --json prints one document\n"
        "{store, trainees, sessions}. A store that is missing, damaged, another program's or a newer kumite's exits\n"
        "with status 1 and the reason, and is left as it was.",
        0, 0,
        {store_flag(),
         trainee_flag(),
         json_flag()}};
    return spec;
}

namespace {

// "1:05" or "1:02:05".
std::string duration_text(double seconds) {
    const long total = std::isfinite(seconds) ? std::lround(std::max(0.0, seconds)) : 0;
    char text[32];
    if (total >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

// "2026-12-06T04:00:00Z" as "2026-12-06 04:00".
std::string date_text(const std::string& utc) {
    std::string date = utc.substr(0, 16);
    if (date.size() > 10 && date[10] == 'T') date[10] = ' ';
    return date;
}

nlohmann::json sessions_json(const std::filesystem::path& store, const std::vector<training::TraineeRow>& trainees,
                             const std::vector<training::SessionRow>& sessions, std::int64_t running_id) {
    nlohmann::json document = {{"store", store.string()}, {"trainees", nlohmann::json::array()}, {"sessions", nlohmann::json::array()}};
    for (const training::TraineeRow& t : trainees) {
        document["trainees"].push_back({{"id", t.id}, {"name", t.name}, {"sessions", t.sessions}, {"last_utc", t.last_utc}});
    }
    for (const training::SessionRow& s : sessions) {
        // The summary as the JSON it is; kept as text if it does not parse.
        nlohmann::json summary = s.summary_json.empty() ? nlohmann::json() : nlohmann::json::parse(s.summary_json, nullptr, false);
        if (summary.is_discarded()) summary = s.summary_json;
        document["sessions"].push_back({{"id", s.id},
                                        {"trainee", s.trainee},
                                        {"drill", s.drill},
                                        {"drill_file", s.drill_file},
                                        {"character", s.character},
                                        {"tracker", s.tracker},
                                        {"started_utc", s.started_utc},
                                        {"duration_s", s.duration_s},
                                        {"complete", s.complete},
                                        {"running", s.id == running_id},
                                        {"attacks", s.attacks},
                                        {"user_strikes", s.user_strikes},
                                        {"summary", summary}});
    }
    return document;
}

void print_sessions(const std::filesystem::path& store, const std::vector<training::SessionRow>& sessions, std::size_t trainee_count, std::int64_t running_id) {
    std::cout << store.string() << ": " << sessions.size() << " session(s) of " << trainee_count << " trainee(s)\n";
    if (sessions.empty()) return;
    int trainee_width = 7, drill_width = 5;
    for (const training::SessionRow& s : sessions) {
        trainee_width = std::max(trainee_width, static_cast<int>(s.trainee.size()));
        drill_width = std::max(drill_width, static_cast<int>(s.drill.size()));
    }
    std::printf("%6s  %-16s  %-*s  %-*s  %8s  %7s\n", "id", "started (UTC)", trainee_width, "trainee", drill_width, "drill", "duration", "attacks");
    for (const training::SessionRow& s : sessions) {
        std::printf("%6lld  %-16s  %-*s  %-*s  %8s  %7d%s\n", static_cast<long long>(s.id), date_text(s.started_utc).c_str(), trainee_width,
                    s.trainee.c_str(), drill_width, s.drill.c_str(), duration_text(s.duration_s).c_str(), s.attacks, s.complete ? "" : s.id == running_id ? "  running" : "  incomplete");
    }
}

} // namespace

int run_sessions(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(sessions_spec(), argc, argv, arguments)) return *status;
    const std::filesystem::path store_path = store_path_of(arguments);
    const std::optional<std::string> trainee = arguments.value("trainee");
    const bool being_written = training::store_being_written(store_path); // before the reader opens it
    Result<training::StoreReader> store = open_store_of(arguments);
    if (!store) return input_error(store.error().message);
    Result<std::vector<training::TraineeRow>> trainees = store->trainees();
    if (!trainees) return input_error(trainees.error().message);
    if (trainee) std::erase_if(*trainees, [&](const training::TraineeRow& t) { return t.name != *trainee; });
    const bool json = arguments.has("json"); // the summaries in it; the table has none
    Result<std::vector<training::SessionRow>> sessions = store->sessions(trainee, json);
    if (!sessions) return input_error(sessions.error().message);
    // The session being written is the store's newest (a writer adds its session as it starts, one at a time).
    std::int64_t running_id = -1; // -1: none
    if (being_written) {
        Result<std::vector<training::SessionRow>> all = trainee ? store->sessions(std::nullopt, false) : sessions;
        const std::int64_t newest = all ? std::accumulate(all->begin(), all->end(), std::int64_t(-1), [](std::int64_t id, const training::SessionRow& r) { return std::max(id, r.id); }) : -1;
        for (const training::SessionRow& r : all ? *all : std::vector<training::SessionRow>{}) {
            if (r.id == newest && !r.complete) running_id = newest;
        }
    }
    if (json) print_json(sessions_json(store_path, *trainees, *sessions, running_id));
    else print_sessions(store_path, *sessions, trainees->size(), running_id);
    return k_exit_ok;
}

} // namespace kumite::cli
