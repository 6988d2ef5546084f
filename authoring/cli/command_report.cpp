// kumite report: the supervisor's session report, one self-contained HTML page, from a bout's events (and its
// report, when given).

#include "capture_loading.h"
#include "commands.h"
#include "session_html.h"
#include "session_log.h"

#include "kumite/formats/atomic_file.h"

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

namespace kumite::cli {

const CommandSpec& report_spec() {
    static const CommandSpec spec{
        "report",
        "EVENTS.jsonl [--report REPORT.json] -o OUT.html [--json]",
        "Draws the session report of a bout from the events `kumite play --events` wrote: the summary (orders\n"
        "performed, refused and expired; strikes and hits by semantics, kind and height; the user's strikes by\n"
        "outcome; frame times; tracker losses), then per fighter a timeline, the room from above and the\n"
        "distributions of latency, speed at contact, overshoot and prediction error. One HTML file with inline SVG and\n"
        "CSS that opens offline. A malformed or cut-off events file gives the report of what could be read and\n"
        "says where reading stopped (exit 0, with a warning).",
        1, 1,
        {{"output", "OUT.html", "the page to write (required)"},
         {"report", "REPORT.json", "the bout's report (kumite play --report): frame times when the events lack them"},
         json_flag()}};
    return spec;
}

int run_report(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(report_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> output = arguments.value("output");
    if (!output) return usage_error(report_spec(), "-o OUT.html is required");
    const auto started = std::chrono::steady_clock::now();
    const std::string& events_path = arguments.positionals[0];
    Result<report::SessionLog> log = report::read_session_log(events_path);
    if (!log) return input_error(log.error().message);

    std::optional<nlohmann::json> play_report;
    if (const std::optional<std::string> path = arguments.value("report")) {
        std::ifstream in(*path, std::ios::binary);
        if (!in) return input_error(*path + ": cannot open the report");
        std::ostringstream text;
        text << in.rdbuf();
        nlohmann::json parsed = nlohmann::json::parse(text.str(), nullptr, false);
        if (parsed.is_discarded() || !parsed.is_object()) return input_error(*path + ": not a JSON object (a report of kumite play --report)");
        play_report = std::move(parsed);
    }
    const std::string html = report::session_html(*log, play_report ? &*play_report : nullptr, events_path);
    if (Result<void> written = write_file_atomically(*output, html); !written) return input_error(written.error().message);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (log->stopped) std::cerr << "kumite report: warning: " << *log->stopped << "\n";

    long long strikes = 0, hits = 0;
    for (const auto& [index, fighter] : log->fighters) {
        strikes += static_cast<long long>(fighter.strikes.size());
        for (const report::StrikeRecord& strike : fighter.strikes) hits += strike.hit;
    }
    if (arguments.has("json")) {
        print_json({{"output", *output},
                    {"bytes", html.size()},
                    {"lines", log->lines},
                    {"fighters", log->fighters.size()},
                    {"strikes", strikes},
                    {"hits", hits},
                    {"complete", !log->stopped && log->end.has_value()},
                    {"stopped", log->stopped ? nlohmann::json(*log->stopped) : nlohmann::json()},
                    {"seconds", seconds}});
    } else {
        std::cout << "wrote " << *output << " (" << html.size() / 1024 << " KiB) from " << log->lines << " event lines: " << log->fighters.size()
                  << " fighter(s), " << strikes << " strikes, " << hits << " hits, in " << seconds << " s\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
