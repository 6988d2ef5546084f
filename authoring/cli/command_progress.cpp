// kumite progress: a trainee's progress page (one self-contained HTML file) from the training store, and with --json
// the per-session numbers it shows.

#include "capture_loading.h"
#include "commands.h"
#include "progress_html.h"
#include "store_flags.h"

#include "kumite/formats/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace kumite::cli {

namespace {

// NaN (no value) as JSON's null: nlohmann would write it so too, but say it here rather than rely on it.
nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json spread_json(const training::TimeSpread& spread) {
    return {{"n", spread.n}, {"median", number(spread.median_s)}, {"p25", number(spread.p25_s)}, {"p75", number(spread.p75_s)}};
}

nlohmann::json session_json(const training::SessionProgress& s) {
    using training::share;
    nlohmann::json by_attack = nlohmann::json::object();
    for (const auto& [name, times] : s.response_times_by_attack_s) by_attack[name] = spread_json(training::time_spread(times));
    return {{"session_id", s.session.id},
            {"started_utc", s.session.started_utc},
            {"drill", s.session.drill},
            {"duration_s", number(s.session.duration_s)},
            {"complete", s.session.complete},
            {"attacks", s.attacks},
            {"response_time_s", spread_json(s.response_time)},
            {"response_time_s_by_attack", by_attack},
            {"anticipated", s.anticipated},
            {"in_time", number(share(s.in_time, s.attacks))},
            {"late", number(share(s.late, s.attacks))},
            {"no_answer", number(share(s.no_answer, s.attacks))},
            {"fighter_blows", {{"hit", s.fighter_hit}, {"blocked", s.fighter_blocked}, {"miss", s.fighter_missed}}},
            {"user_strikes", s.user_strikes},
            {"user_landed", number(share(s.user_landed, s.user_strikes))},
            {"user_defended", number(share(s.user_defended, s.user_strikes))}};
}

nlohmann::json comparisons_json(const std::vector<training::SessionProgress>& sessions) {
    nlohmann::json comparisons = nlohmann::json::array();
    for (const training::DrillComparison& c : training::drill_comparisons(sessions)) {
        const training::SessionProgress& first = sessions[c.first];
        const training::SessionProgress& last = sessions[c.last];
        comparisons.push_back({{"drill", c.drill},
                               {"reaction_test", c.reaction_test},
                               {"runs", c.runs},
                               {"first_session_id", first.session.id},
                               {"last_session_id", last.session.id},
                               {"median_change_s", number(last.response_time.median_s - first.response_time.median_s)},
                               {"in_time_change", number(training::share(last.in_time, last.attacks) - training::share(first.in_time, first.attacks))}});
    }
    return comparisons;
}

} // namespace

const CommandSpec& progress_spec() {
    static const CommandSpec spec{
        "progress",
        "NAME [--store PATH] -o OUT.html [--json]",
        "Draws a trainee's progress from the training store (kumite train): the sessions with their response times\n"
        "(median and p25-p75), answers in time, the fighter's blows that landed and the trainee's strikes; the trends\n"
        "session by session, by attack; and the first against the last run of every drill run more than once (the\n"
        "pre- and post-tests of a reaction test). One HTML file with inline SVG and CSS that opens offline. --json\n"
        "prints the per-session numbers (times in seconds, shares 0..1, null when there are none); with --json,\n"
        "-o may be left out. An unknown NAME is refused with the trainees the store has.",
        1, 1,
        {store_flag(),
         {"output", "OUT.html", "the page to write (required without --json)"},
         json_flag()}};
    return spec;
}

int run_progress(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(progress_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> output = arguments.value("output");
    if (!output && !arguments.has("json")) return usage_error(progress_spec(), "-o OUT.html is required (or --json for the numbers alone)");
    const std::string& trainee = arguments.positionals[0];
    const std::filesystem::path store_path = store_path_of(arguments);

    Result<training::StoreReader> store = training::StoreReader::open(store_path);
    if (!store) return input_error(store.error().message);
    Result<std::vector<training::SessionProgress>> sessions = training::session_progress(*store, trainee);
    if (!sessions) return input_error(sessions.error().message);
    std::size_t bytes = 0;
    if (output) {
        const std::string html = training::progress_html(trainee, *sessions);
        if (Result<void> written = write_file_atomically(*output, html); !written) return input_error(written.error().message);
        bytes = html.size();
    }

    if (arguments.has("json")) {
        nlohmann::json listed = nlohmann::json::array();
        for (const training::SessionProgress& s : *sessions) listed.push_back(session_json(s));
        print_json({{"store", store_path.string()},
                    {"trainee", trainee},
                    {"output", output ? nlohmann::json(*output) : nlohmann::json()},
                    {"bytes", bytes},
                    {"sessions", listed},
                    {"comparisons", comparisons_json(*sessions)}});
    } else {
        const long long incomplete = std::count_if(sessions->begin(), sessions->end(), [](const training::SessionProgress& s) { return !s.session.complete; });
        std::cout << "wrote " << *output << " (" << bytes / 1024 << " KiB): " << trainee << ", " << sessions->size() << " session(s)"
                  << (incomplete ? ", " + std::to_string(incomplete) + " incomplete" : std::string()) << "\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
