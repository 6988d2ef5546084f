// kumite train: a drill run as a bout against the trainee (desktop, DTrack wall, headset or a simulated or recorded
// user), and stored as one session in the training store (authoring/training) as it goes.

#include "bout_run.h"
#include "commands.h"
#include "train_rows.h"
#include "training_store.h"

#include "kumite/formats/drill_file.h"

#include <fstream>
#include <iostream>
#include <sstream>

namespace kumite::cli {
namespace {

// Play's flags that a drill's bout takes too, with play's help.
std::vector<FlagSpec> play_flags(std::initializer_list<const char*> names) {
    std::vector<FlagSpec> flags;
    for (const char* name : names) {
        for (const FlagSpec& flag : play_spec().flags) {
            if (flag.name == name) flags.push_back(flag);
        }
    }
    return flags;
}

Result<std::string> file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the drill");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::optional<std::string> trainee_name_problem(const std::string& name) {
    if (name.empty() || name.size() > 100) return "--trainee needs a name of 1 to 100 characters";
    for (const char c : name) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "--trainee: the name has a control character";
    }
    return std::nullopt;
}

} // namespace

const CommandSpec& train_spec() {
    static const CommandSpec spec = [] {
        CommandSpec s{"train",
                      "[DB.kdb] --trainee NAME --drill FILE [--store PATH | --no-store] [--tracker SOURCE] [--headless] [--xr] [outputs]",
                      "Runs a drill (data/drills/, docs/training.md) against the trainee: its parts in turn, each with its attacks at\n"
                      "their moments or free sparring, at its difficulty. The session (every attack with the trainee's response, the\n"
                      "trainee's strikes, the summary) goes into the training store as it runs, committed every quarter second: a\n"
                      "session cut short keeps what was committed and is marked incomplete. `kumite progress NAME` shows the weeks.",
                      0,
                      1,
                      {{"trainee", "NAME", "who trains (created in the store the first time)"},
                       {"drill", "FILE", "the drill file (TOML); a mistake in it is refused with its line before anything starts"},
                       {"store", "PATH", "the training store (SQLite; default $KUMITE_STORE, else ~/.local/share/kumite/training.sqlite)"},
                       {"no-store", "", "run the drill without storing it"}}};
        s.flags.push_back({"duration", "S", "stop after S seconds (default: when the drill ends)"});
        for (FlagSpec& flag : play_flags({"tracker", "tracker-config", "character", "headless", "realtime", "seed", "difficulty", "settings", "set",
                                          "xr", "xr-view-size", "xr-eye-image", "viewer-config", "screenshot", "record", "record-user", "events",
                                          "report", "html", "characters-dir", "verify", "json"})) {
            s.flags.push_back(std::move(flag));
        }
        return s;
    }();
    return spec;
}

int run_train(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(train_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> trainee = arguments.value("trainee");
    const std::optional<std::string> drill_path = arguments.value("drill");
    if (!trainee) return usage_error(train_spec(), "--trainee NAME is required");
    if (std::optional<std::string> problem = trainee_name_problem(*trainee)) return usage_error(train_spec(), *problem);
    if (!drill_path) return usage_error(train_spec(), "--drill FILE is required");
    if (arguments.has("no-store") && arguments.has("store")) return usage_error(train_spec(), "--store and --no-store exclude each other");

    // The drill, whole and checked, before anything starts.
    Result<std::string> drill_text = file_text(*drill_path);
    if (!drill_text) return input_error(drill_text.error().message);
    Result<Drill> drill = drill_parse(*drill_text, *drill_path);
    if (!drill) return input_error(drill.error().message);
    const std::string drill_name = drill->name;
    Result<DrillRun> run = DrillRun::compile(std::move(*drill), *drill_path);
    if (!run) return input_error(run.error().message);

    const bool storing = !arguments.has("no-store");
    const std::filesystem::path store_path = arguments.value("store") ? std::filesystem::path(*arguments.value("store")) : training::default_store_path();
    std::unique_ptr<training::SessionWriter> writer;
    TrainRows rows;
    BoutRunExtras extras;
    extras.drill = std::move(*run);
    if (storing) {
        extras.on_start = [&](const BoutRunStart& start) -> Result<void> {
            training::SessionStart session{*trainee, drill_name, *drill_path, *drill_text, start.settings.dump(), start.character, start.tracker, {}};
            Result<std::unique_ptr<training::SessionWriter>> opened = training::SessionWriter::open(store_path, session);
            if (!opened) return opened.error();
            writer = std::move(*opened);
            return {};
        };
        double stored_duration_s = 0.0;
        extras.on_event = [&, stored_duration_s](const nlohmann::json& line) mutable {
            if (line.value("type", "") == "drill_part") rows.take_part(line);
            if (std::optional<training::AttackRow> attack = rows.attack(line)) writer->add(std::move(*attack));
            if (std::optional<training::UserStrikeRow> strike = rows.user_strike(line)) writer->add(std::move(*strike));
            const double t = line.value("t", 0.0);
            if (t >= stored_duration_s + 1.0) writer->set_duration(stored_duration_s = t);
        };
        extras.wants_event = [](FighterEvent::Type type) { return type == FighterEvent::Type::user_response || type == FighterEvent::Type::user_strike_end; };
        extras.on_end = [&](const nlohmann::json& report) -> Result<void> {
            const double duration_s = double(report.value("frames", 0LL)) / 60.0;
            if (Result<void> finished = writer->finish(duration_s, train_summary_json(report).dump()); !finished) return finished.error();
            if (!arguments.has("json")) std::cerr << "kumite train: session " << writer->session_id() << " of " << *trainee << " stored in " << store_path.string() << "\n";
            return {};
        };
    }
    return run_bout(train_spec(), arguments, &extras);
}

} // namespace kumite::cli
