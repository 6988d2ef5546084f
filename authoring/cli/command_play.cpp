// kumite play: the fighter against a tracked (or simulated) user, driven by supervisor commands. Headless for now:
// a simulated clock (as fast as possible, deterministic with --seed) unless --realtime or a live tracker.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/atomic_file.h"
#include "kumite/formats/bvh_writer.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/dtrack_receiver.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/replay_track.h"
#include "kumite/runtime/simulated_user.h"
#include "kumite/runtime/supervisor.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace kumite::cli {

const CommandSpec& play_spec() {
    static const CommandSpec spec{
        "play",
        "DB.kdb [--character NAME] [--fighters N] [--tracker dtrack:PORT[:BODY] | replay:FILE | simulate:still|wander|dodge|FILE] "
        "[--commands stdin | tcp:PORT | script:FILE] --headless [--duration S] [--realtime] [--seed N] [--record OUT.bvh] "
        "[--events OUT.jsonl] [--report OUT.json]",
        "Runs the fighter at 60 Hz against the user's head (a DTrack system, a replayed CSV of t,x,y,z, or a\n"
        "simulated user) and the supervisor's commands, one per line: punch [left|right], kick [left|right],\n"
        "character NAME, quit (in a script file, each line starts with its time in seconds; on stdin or TCP on\n"
        "127.0.0.1 they apply when they arrive). Headless runs use a simulated clock unless --realtime or the\n"
        "tracker is live. (The viewer arrives later.)",
        1, 1,
        {{"character", "NAME", "the starting character (default: the first of data/characters)"},
         {"fighters", "N", "fighters side by side against the same user (default 1)"},
         {"tracker", "SOURCE", "dtrack:PORT[:BODY], replay:FILE.csv, or simulate:still|wander|dodge|FILE (a user script; default simulate:still)"},
         {"tracker-config", "FILE.json", "the room: bind address, room-to-world transform, room bounds (dtrack)"},
         {"commands", "SOURCE", "stdin, tcp:PORT (127.0.0.1) or script:FILE ('<time_s> <command>' per line)"},
         {"headless", "", "no window"},
         {"duration", "S", "seconds to run (default 30)"},
         {"realtime", "", "step on the wall clock"},
         {"seed", "N", "seed of the simulated user (default 1)"},
         {"lead", "S", "the least time from an order's strike start to its contact (default 0.4 s)"},
         {"record", "OUT.bvh", "the first fighter's motion on the starting character"},
         {"events", "OUT.jsonl", "one JSON object per event"},
         {"report", "OUT.json", "frames, frame times, orders, strikes, hits, misses, tracker counts"},
         characters_dir_flag(), json_flag()}};
    return spec;
}

namespace {

struct ScriptLine {
    double t_s = 0.0;
    std::string command;
    int line = 0;
};

Result<std::vector<ScriptLine>> read_script(const std::string& path) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the command script");
    std::vector<ScriptLine> lines;
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string::npos || text[first] == '#') continue;
        std::istringstream stream(text);
        ScriptLine line;
        line.line = number;
        if (!(stream >> line.t_s) || !std::isfinite(line.t_s) || line.t_s < 0) {
            return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": expected '<time_s> <command>'");
        }
        std::getline(stream >> std::ws, line.command);
        lines.push_back(line);
    }
    std::stable_sort(lines.begin(), lines.end(), [](const ScriptLine& a, const ScriptLine& b) { return a.t_s < b.t_s; });
    return lines;
}

nlohmann::json summary_of(std::vector<double> values) {
    if (values.empty()) return {{"mean", 0.0}, {"p99", 0.0}, {"max", 0.0}};
    std::sort(values.begin(), values.end());
    double sum = 0.0;
    for (double v : values) sum += v;
    return {{"mean", sum / values.size()}, {"p99", values[std::min(values.size() - 1, values.size() * 99 / 100)]}, {"max", values.back()}};
}

const char* side_text(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "any"; }

} // namespace

int run_play(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(play_spec(), argc, argv, arguments)) return *status;
    if (!arguments.has("headless")) return usage_error(play_spec(), "the viewer is not built yet: run with --headless");
    const Result<long long> fighters_count = arguments.integer("fighters", 1, 10000, 1);
    const Result<long long> seed = arguments.integer("seed", 0, 1LL << 62, 1);
    if (!fighters_count) return usage_error(play_spec(), fighters_count.error().message);
    if (!seed) return usage_error(play_spec(), seed.error().message);
    std::optional<double> lead_s = 0.4;
    if (const std::optional<std::string> text = arguments.value("lead")) {
        char* end = nullptr;
        lead_s = std::strtod(text->c_str(), &end);
        if (end == text->c_str() || *end != '\0' || !(*lead_s >= 0.0) || *lead_s > 5.0) return usage_error(play_spec(), "--lead must be 0 to 5 seconds");
    }
    double duration_s = 30.0;
    if (const std::optional<std::string> text = arguments.value("duration")) {
        char* end = nullptr;
        duration_s = std::strtod(text->c_str(), &end);
        if (end == text->c_str() || *end != '\0' || !(duration_s > 0.0) || duration_s > 86400.0) {
            return usage_error(play_spec(), "--duration must be seconds, more than 0, not '" + *text + "'");
        }
    }
    // The tracker.
    const std::string tracker = arguments.value("tracker").value_or("simulate:still");
    std::optional<SimulatedUser> simulated;
    std::optional<ScriptedUser> scripted;
    std::optional<ReplayTrack> replay;
    std::unique_ptr<DtrackReceiver> receiver;
    if (tracker.starts_with("simulate:")) {
        const std::string name = tracker.substr(9);
        if (const std::optional<SimulatedKind> kind = simulated_kind_from_name(name)) {
            simulated.emplace(*kind, static_cast<std::uint64_t>(*seed));
        } else if (std::filesystem::exists(name)) {
            Result<ScriptedUser> read = ScriptedUser::read(name);
            if (!read) return input_error(read.error().message);
            scripted = std::move(*read);
        } else {
            return usage_error(play_spec(), "--tracker simulate: takes still, wander, dodge or a user script file, not '" + name + "'");
        }
    } else if (tracker.starts_with("dtrack:")) {
        DtrackConfig config;
        if (const std::optional<std::string> file = arguments.value("tracker-config")) {
            Result<DtrackConfig> read = dtrack_config_read(*file);
            if (!read) return input_error(read.error().message);
            config = *read;
        }
        int port = 0, body = config.head_body;
        char extra = 0;
        const int fields = std::sscanf(tracker.c_str() + 7, "%d:%d%c", &port, &body, &extra);
        if (fields < 1 || fields > 2 || port <= 0 || port > 65535) return usage_error(play_spec(), "--tracker dtrack:PORT[:BODY], not '" + tracker + "'");
        config.port = port;
        config.head_body = fields == 2 ? body : config.head_body;
        Result<std::unique_ptr<DtrackReceiver>> opened = DtrackReceiver::open(config);
        if (!opened) return input_error(opened.error().message);
        receiver = std::move(*opened);
    } else if (tracker.starts_with("replay:")) {
        Result<ReplayTrack> read = ReplayTrack::read(tracker.substr(7));
        if (!read) return input_error(read.error().message);
        replay = std::move(*read);
    } else {
        return usage_error(play_spec(), "--tracker must be dtrack:PORT[:BODY], replay:FILE or simulate:still|wander|dodge");
    }
    std::vector<ScriptLine> script;
    std::unique_ptr<CommandStream> stream;
    if (const std::optional<std::string> commands = arguments.value("commands")) {
        if (commands->starts_with("script:")) {
            Result<std::vector<ScriptLine>> read = read_script(commands->substr(7));
            if (!read) return input_error(read.error().message);
            script = std::move(*read);
        } else if (*commands == "stdin" || commands->starts_with("tcp:")) {
            Result<std::unique_ptr<CommandStream>> opened = CommandStream::open(*commands);
            if (!opened) return usage_error(play_spec(), opened.error().message);
            stream = std::move(*opened);
            if (stream->port() > 0) std::cerr << "kumite play: supervisor commands on 127.0.0.1:" << stream->port() << "\n";
        } else {
            return usage_error(play_spec(), "--commands takes stdin, tcp:PORT or script:FILE, not '" + *commands + "'");
        }
    }

    // The database and every character (any of them can be switched to).
    Result<MotionDatabase> database = MotionDatabase::open(arguments.positionals[0]);
    if (!database) return input_error(database.error().message);
    const MotionDatabaseView& db = database->view();
    const std::optional<std::string> folder = arguments.value("characters-dir");
    const std::filesystem::path characters_dir = folder ? std::filesystem::path(*folder) : default_characters_dir();
    std::vector<CharacterEntry> entries = list_characters(characters_dir);
    if (entries.empty()) return input_error(characters_dir.string() + ": no characters");
    std::vector<BvhFile> files;
    std::vector<RestAnatomy> anatomies;
    files.reserve(entries.size());
    anatomies.reserve(entries.size());
    std::vector<std::unique_ptr<CharacterRig>> rigs;
    int start_character = 0;
    const std::string wanted = arguments.value("character").value_or(entries[0].name);
    bool known = false;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        Result<BvhFile> file = load_character(characters_dir, entries[i].name);
        if (!file) return input_error(file.error().message);
        files.push_back(std::move(*file));
        Result<RestAnatomy> anatomy = rest_anatomy_build(files.back().clip, files.back().body_map);
        if (!anatomy) return input_error("character " + entries[i].name + ": " + anatomy.error().message);
        anatomies.push_back(std::move(*anatomy));
        rigs.push_back(std::make_unique<CharacterRig>(files.back().clip.skeleton, anatomies.back()));
        if (entries[i].name == wanted) start_character = static_cast<int>(i), known = true;
    }
    if (!known) return usage_error(play_spec(), "unknown character '" + wanted + "' (see kumite characters)");
    std::vector<CharacterRig*> order_of_rigs;
    for (int i = 0; i < static_cast<int>(rigs.size()); ++i) order_of_rigs.push_back(rigs[(start_character + i) % rigs.size()].get());
    auto rig_index = [&](const std::string& name) {
        for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
            if (entries[(start_character + i) % entries.size()].name == name) return i;
        }
        return -1;
    };

    // A sparring partner telegraphs: strikes start at least --lead seconds before their contact, so a user has
    // time to see them coming (0.4 s: a still user is hit, one who dodges 0.25 s after the order is missed).
    RetrievalSettings retrieval_settings;
    retrieval_settings.min_lead_frames = std::max(1, static_cast<int>(std::lround(*lead_s / db.meta.frame_time_s)));
    const Retriever retriever(db, retrieval_settings);
    std::vector<std::unique_ptr<Fighter>> fighters;
    for (long long i = 0; i < *fighters_count; ++i) {
        FighterSettings settings;
        settings.start_x_m = (static_cast<double>(i) - 0.5 * double(*fighters_count - 1)) * 1.2;
        fighters.push_back(std::make_unique<Fighter>(db, retriever, order_of_rigs, settings));
    }

    std::ofstream events_out;
    const std::optional<std::string> events_path = arguments.value("events");
    const std::string events_temporary = events_path ? *events_path + ".partial" : "";
    if (events_path) {
        events_out.open(events_temporary);
        if (!events_out) return input_error(*events_path + ": cannot write the events file");
    }
    auto write_event = [&](const nlohmann::json& event) {
        if (events_out.is_open()) events_out << event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    };

    // The recording: the first fighter's MIR decoded on the starting character.
    const Skeleton& record_skeleton = files[start_character].clip.skeleton;
    MirDecoder record_decoder(record_skeleton, anatomies[start_character], {});
    Clip record;
    record.skeleton = record_skeleton;
    constexpr double rate_hz = 60.0;
    record.frame_time_s = 1.0 / rate_hz;
    Pose record_pose;

    const bool realtime = arguments.has("realtime") || receiver != nullptr;
    const long long frames = static_cast<long long>(std::llround(duration_s * rate_hz));
    std::vector<double> frame_us;
    long long missed = 0, orders = 0, strikes = 0, hits = 0, misses = 0, ignored = 0;
    std::vector<double> command_to_strike;
    std::vector<long long> order_frame(fighters.size(), -1);
    std::size_t next_command = 0;
    HeadSample head_sample;
    const auto wall_start = std::chrono::steady_clock::now();
    long long frame = 0;
    for (; frame < frames; ++frame) {
        const double t = frame / rate_hz;
        if (realtime) std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t));
        const auto started = std::chrono::steady_clock::now();
        // The head.
        Eigen::Vector3d head;
        const Eigen::Vector3d* head_now = nullptr;
        if (simulated) {
            head = simulated->head(t);
            head_now = &head;
        } else if (scripted) {
            head = scripted->head(t);
            head_now = &head;
        } else if (replay) {
            if (const std::optional<Eigen::Vector3d> replayed = replay->head(t)) {
                head = *replayed;
                head_now = &head;
            }
        } else if (receiver && receiver->poll(head_sample, t)) { // only a fresh head: silence must reach the fighter
            head = head_sample.position_world;
            head_now = &head;
        }
        // Commands due: from the script, or whatever arrived on the stream.
        bool quit = false;
        auto apply = [&](std::string_view line, const std::string& where) {
            Result<SupervisorCommand> command = supervisor_command_parse(line);
            if (command && command->verb == SupervisorCommand::Verb::character && rig_index(command->argument) < 0) {
                command = make_error(ErrorCode::invalid, "unknown character '" + command->argument + "'");
            }
            if (!command) {
                const std::string message = "error: " + where + command.error().message + "; ignored\n";
                if (stream) stream->reply(message);
                else std::cerr << "kumite play: " << message;
                return;
            }
            switch (command->verb) {
            case SupervisorCommand::Verb::punch:
            case SupervisorCommand::Verb::kick: {
                const Side side = command->side == "left" ? Side::left : command->side == "right" ? Side::right : Side::none;
                if (simulated) simulated->on_order(t);
                if (scripted) scripted->on_order(t);
                const char* verb = command->verb == SupervisorCommand::Verb::punch ? "punch" : "kick";
                for (auto& fighter : fighters) fighter->order(retriever.semantics_id(verb), side);
                break;
            }
            case SupervisorCommand::Verb::character:
                for (auto& fighter : fighters) fighter->set_character(rig_index(command->argument));
                break;
            case SupervisorCommand::Verb::quit: quit = true; break;
            }
        };
        for (; next_command < script.size() && script[next_command].t_s <= t; ++next_command) {
            apply(script[next_command].command, "line " + std::to_string(script[next_command].line) + ": ");
        }
        if (stream) stream->poll([&](std::string_view line) { apply(line, ""); });
        for (std::size_t f = 0; f < fighters.size(); ++f) {
            Fighter& fighter = *fighters[f];
            fighter.step(t, head_now);
            for (const FighterEvent& event : fighter.events()) {
                nlohmann::json line = {{"t", event.t_s}, {"type", fighter_event_name(event.type)}, {"fighter", f}};
                switch (event.type) {
                case FighterEvent::Type::order:
                    ++orders;
                    order_frame[f] = frame;
                    line["command"] = retriever.semantics_name(event.semantics);
                    line["side"] = side_text(event.side);
                    break;
                case FighterEvent::Type::ignored_order:
                    ++ignored;
                    line["why"] = event.why;
                    break;
                case FighterEvent::Type::state:
                    line["state"] = fighter_state_name(event.state);
                    if (event.state == FighterState::strike && order_frame[f] >= 0) {
                        command_to_strike.push_back(double(frame - order_frame[f]));
                        order_frame[f] = -1;
                    }
                    break;
                case FighterEvent::Type::strike:
                    ++strikes;
                    (event.hit ? hits : misses) += 1;
                    line["result"] = event.hit ? "hit" : "miss";
                    line["contact_error_m"] = event.contact_error_m;
                    line["head_distance_m"] = event.head_distance_m;
                    line["range_m"] = event.range_m;
                    line["clip"] = db.string(db.clips[event.clip].name);
                    break;
                case FighterEvent::Type::character: line["character"] = entries[(start_character + event.character) % entries.size()].name; break;
                case FighterEvent::Type::tracker_lost:
                case FighterEvent::Type::tracker_back: break;
                default: break;
                }
                write_event(line);
            }
            fighter.clear_events();
        }
        if (arguments.value("record")) {
            record_decoder.decode(record_pose, fighters[0]->mir());
            record.root_translations.push_back(record_pose.root_translation);
            record.local_rotations.insert(record.local_rotations.end(), record_pose.local_rotations.begin(), record_pose.local_rotations.end());
        }
        const double elapsed = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
        frame_us.push_back(elapsed);
        missed += elapsed > 1e6 / rate_hz;
        if (quit) {
            ++frame;
            break;
        }
    }

    if (events_out.is_open()) {
        events_out.close();
        std::error_code error;
        std::filesystem::rename(events_temporary, *events_path, error);
        if (error) return input_error(*events_path + ": cannot finish the events file: " + error.message());
    }
    if (const std::optional<std::string> path = arguments.value("record")) {
        if (Result<void> written = bvh_write_file(*path, record, files[start_character].layout, files[start_character].unit); !written) {
            return input_error(written.error().message);
        }
    }
    const nlohmann::json times = summary_of(frame_us);
    double mean_latency = 0.0, max_latency = 0.0;
    for (double v : command_to_strike) mean_latency += v / command_to_strike.size(), max_latency = std::max(max_latency, v);
    nlohmann::json report = {{"frames", frame},
                             {"fighters", fighters.size()},
                             {"frame_time_us", times},
                             {"missed_frames", missed},
                             {"orders", orders},
                             {"strikes", strikes},
                             {"hits", hits},
                             {"misses", misses},
                             {"ignored_orders", ignored},
                             {"tracker_packets", receiver ? receiver->stats().packets : 0},
                             {"tracker_rejected", receiver ? receiver->stats().rejected() : 0},
                             {"command_to_strike_frames", {{"max", max_latency}, {"mean", mean_latency}}},
                             {"realtime", realtime}};
    if (const std::optional<std::string> path = arguments.value("report")) {
        if (Result<void> written = write_file_atomically(*path, report.dump(2) + "\n"); !written) return input_error(written.error().message);
    }
    if (arguments.has("json")) {
        print_json(report);
    } else {
        std::cout << "played " << frame << " frames (" << frame / rate_hz << " s) with " << fighters.size() << " fighter(s): " << orders
                  << " orders, " << strikes << " strikes, " << hits << " hits, " << misses << " misses, " << ignored
                  << " ignored; frame time mean " << times["mean"].get<double>() << " us, p99 " << times["p99"].get<double>() << " us\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
