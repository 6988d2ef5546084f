// kumite play: the fighter against a tracked (or simulated) user, driven by supervisor commands. In the viewer when
// a display is present and --headless is not given (on the wall clock); headless on a simulated clock (as fast as
// possible, deterministic with --seed) unless --realtime or a live tracker.

#include "bout_run.h"
#include "capture_loading.h"
#include "partial_file.h"
#include "kumite/runtime/difficulty.h"
#include "play_motion.h"
#include "play_output.h"
#include "play_settings.h"
#include "play_summary.h"
#include "play_xr.h"
#include "session_html.h"
#include "session_log.h"
#include "character_catalog.h"
#include "default_database.h"
#include "commands.h"
#include "kumite/formats/character_body.h"
#include "kumite/formats/gltf_reader.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/atomic_file.h"
#include "kumite/formats/bvh_writer.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/bout_cast.h"
#include "player_window.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace kumite::cli {

// The headset's default fighter (CC0, data/bodies/README.md).
constexpr const char* k_xr_default_body = "data/bodies/quaternius-adventurer/Adventurer.glb";

const CommandSpec& play_spec() {
    static const CommandSpec spec{
        "play",
        "[DB.kdb] [--tracker SOURCE] [--commands SOURCE] [--character NAME] [--headless --duration S] [--xr] [outputs] [settings]",
        "Runs the fighter at 60 Hz against the user's head and hands and the supervisor's orders, one per line: punch|kick|\n"
        "knee|elbow|slash [left|right] [kind] [low|middle|high], character NAME, aim latched|predicted, defence on|off, quit\n"
        "(docs/room.md). Headless runs use a simulated clock unless --realtime or a live tracker. Without DB.kdb: $KUMITE_DB,\n"
        "else the reference annotations baked once and cached. Every fighter setting: --print-settings, docs/settings.md.",
        0, 1,
        {{"tracker", "SOURCE", "dtrack:PORT[:HEAD[,LEFT,RIGHT]], replay:FILE.csv, capture:FILE.bvh[:DISTANCE[:START_S]] (a recorded\n"
                              "person), simulate:still|wander|walk[:SPEED]|dodge|dodge-seen|punch|counter|FILE (default simulate:still)"},
         {"tracker-config", "FILE.json", "the room: bind address, room-to-world transform, room bounds (dtrack)"},
         {"commands", "SOURCE", "stdin, tcp:PORT (127.0.0.1) or script:FILE ('<time_s> <command>' per line)"},
         {"character", "NAME", "the starting character (default: the first shipped; with --xr the human body of data/bodies)"},
         {"fighters", "N", "fighters side by side against the same user (default 1)"},
         {"headless", "", "no window (with --xr: no supervisor's window beside the headset)"},
         {"duration", "S", "seconds to run (default 30; the viewer runs until closed unless it is given)"},
         {"realtime", "", "step on the wall clock"},
         {"seed", "N", "seed of the simulated user and of the fighter's own attacks (default 1)"},
         {"aim", "latched|predicted", "the setting aim: strike where the head was at the order (default) or where it will be"},
         {"no-defence", "", "the setting defence.enabled = false: the fighter neither blocks nor slips"},
         {"difficulty", "LEVEL", "beginner, intermediate, person, expert or faster-than-a-person (default): the fighter's reaction\n"
                                 "time, how often it defends, its tempo and combinations (docs/room.md); applied first"},
         {"spar", "", "the setting attacks.on_its_own = true: the fighter attacks without orders (free sparring)"},
         {"settings", "FILE", "fighter settings, 'name = value' per line (applied before --aim, --no-defence and --set)"},
         {"set", "NAME=VALUE", "one fighter setting, e.g. --set human_speed=true (repeatable; applied last, in order)", true},
         {"print-settings", "", "print every setting with its value and meaning, in the form --settings reads, and exit"},
         {"xr", "", "in an OpenXR headset (the system's runtime; XR_RUNTIME_JSON honoured): its head and grips are the user"},
         {"xr-view-size", "WxH", "with --xr: the size drawn per eye (default: the runtime's recommended size)"},
         {"xr-eye-image", "OUT.png", "with --xr: save the left eye's image near the end of the bout"},
         {"viewer-config", "FILE.json", "the wall screen's corners, eye separation, stereo and camera (runtime/player/README.md)"},
         {"screenshot", "OUT.png", "viewer: save the window after --duration seconds and close"},
         {"record", "OUT.bvh|OUT.glb", "the first fighter's motion on the starting character (glTF: with its body)"},
         {"record-user", "OUT.csv", "the user as tracked, every frame: t, head, hands, elbows (replay:OUT.csv plays it back)"},
         {"events", "OUT.jsonl", "one JSON object per event"},
         {"report", "OUT.json", "the bout report: frames, frame times, orders, strikes, hits, speeds, distance, defence"},
         {"html", "OUT.html", "the session report: summary, timeline, the room from above, distributions"},
         characters_dir_flag(), verify_flag(), json_flag()}};
    return spec;
}

namespace {

// The fighters' settings: the defaults, then --difficulty, then --settings FILE, then --aim and --no-defence, then
// every --set in order.
std::optional<int> read_play_settings(const CommandSpec& spec, const Arguments& arguments, BoutOptions& options) {
    if (const std::optional<std::string> level = arguments.value("difficulty")) {
        if (Result<void> applied = apply_difficulty(options, *level); !applied) return usage_error(spec, applied.error().message);
    }
    if (const std::optional<std::string> file = arguments.value("settings")) {
        if (Result<void> read = play_settings_read(*file, options); !read) return input_error(read.error().message);
    }
    if (const std::optional<std::string> text = arguments.value("aim")) {
        if (Result<void> set = play_setting_assign(options, "aim=" + *text); !set) return usage_error(spec, "--aim: " + set.error().message);
    }
    if (arguments.has("no-defence")) options.fighter.defence.enabled = false;
    if (arguments.has("spar")) options.attacks.on_its_own = true;
    for (const std::string& assignment : arguments.all("set")) {
        if (Result<void> set = play_setting_assign(options, assignment); !set) return usage_error(spec, set.error().message);
    }
    if (options.fighter.defence.block_clip_max_speed_ratio > 0.0 && !options.fighter.defence.captured_blocks) {
        return usage_error(spec, "defence.block_clip_max_speed_ratio limits captured blocks: set defence.captured_blocks = true too");
    }
    return std::nullopt;
}

bool display_present() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

} // namespace

int run_play(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(play_spec(), argc, argv, arguments)) return *status;
    return run_bout(play_spec(), arguments, nullptr);
}

int run_bout(const CommandSpec& spec, const Arguments& arguments, BoutRunExtras* extras) {
    const Result<long long> fighters_count = arguments.integer("fighters", 1, 10000, 1);
    const Result<long long> seed = arguments.integer("seed", 0, 1LL << 62, 1);
    if (!fighters_count) return usage_error(spec, fighters_count.error().message);
    if (!seed) return usage_error(spec, seed.error().message);
    BoutOptions options;
    options.attack_seed = static_cast<std::uint64_t>(*seed);
    if (std::optional<int> status = read_play_settings(spec, arguments, options)) return *status;
    if (arguments.has("print-settings")) {
        std::cout << play_settings_text(options);
        return k_exit_ok;
    }
    double duration_s = 30.0;
    if (const std::optional<std::string> text = arguments.value("duration")) {
        char* end = nullptr;
        duration_s = std::strtod(text->c_str(), &end);
        if (end == text->c_str() || *end != '\0' || !(duration_s > 0.0) || duration_s > 86400.0) {
            return usage_error(spec, "--duration must be seconds, more than 0, not '" + *text + "'");
        }
    }
    const bool want_viewer = !arguments.has("headless") && !arguments.has("xr"); // --xr: the headset is the view
    if (want_viewer && !display_present()) {
        std::cerr << "kumite play: no display (DISPLAY and WAYLAND_DISPLAY are unset): running headless\n";
    }
    const bool viewer = want_viewer && display_present();
    view::ViewerSettings viewer_settings;
    if (const std::optional<std::string> file = arguments.value("viewer-config")) {
        Result<view::ViewerSettings> read = view::viewer_settings_read(*file);
        if (!read) return input_error(read.error().message);
        viewer_settings = *read;
    }

    // The tracker.
    DtrackConfig dtrack_config;
    if (const std::optional<std::string> file = arguments.value("tracker-config")) {
        Result<DtrackConfig> read = dtrack_config_read(*file);
        if (!read) return input_error(read.error().message);
        dtrack_config = *read;
    }
    const bool xr = arguments.has("xr");
    if (xr && arguments.has("tracker")) return usage_error(spec, "--xr: the headset is the tracker, leave out --tracker");
    if ((arguments.has("xr-eye-image") || arguments.has("xr-view-size")) && !xr) return usage_error(spec, "--xr-eye-image and --xr-view-size need --xr");
    Result<std::unique_ptr<HeadTracker>> tracker =
        xr ? Result<std::unique_ptr<HeadTracker>>(HeadTracker::fed())
           : HeadTracker::open(arguments.value("tracker").value_or("simulate:still"), dtrack_config, static_cast<std::uint64_t>(*seed));
    if (!tracker) {
        return tracker.error().code == ErrorCode::invalid ? usage_error(spec, tracker.error().message) : input_error(tracker.error().message);
    }
    std::optional<CommandScript> script;
    std::unique_ptr<CommandStream> stream;
    if (const std::optional<std::string> commands = arguments.value("commands")) {
        if (commands->starts_with("script:")) {
            Result<CommandScript> read = CommandScript::read(commands->substr(7));
            if (!read) return input_error(read.error().message);
            script = std::move(*read);
        } else if (*commands == "stdin" || commands->starts_with("tcp:")) {
            Result<std::unique_ptr<CommandStream>> opened = CommandStream::open(*commands);
            if (!opened) return usage_error(spec, opened.error().message);
            stream = std::move(*opened);
            if (stream->port() > 0) std::cerr << "kumite play: supervisor commands on 127.0.0.1:" << stream->port() << "\n";
        } else {
            return usage_error(spec, "--commands takes stdin, tcp:PORT or script:FILE, not '" + *commands + "'");
        }
    }

    // The database and every character (any of them can be switched to).
    Result<std::filesystem::path> database_path = database_path_from(arguments);
    if (!database_path) return input_error(database_path.error().message);
    Result<MotionDatabase> database = MotionDatabase::open(*database_path, arguments.has("verify"));
    if (!database) return input_error(database.error().message);
    const std::optional<std::string> folder = arguments.value("characters-dir");
    const std::filesystem::path characters_dir = folder ? std::filesystem::path(*folder) : default_characters_dir();
    // In the headset the fighter is a person by default: the CC0 human body shipped in data/bodies (any character
    // can still be named); on the desktop the first shipped mannequin.
    std::string character = arguments.value("character").value_or("");
    if (character.empty() && xr) {
        const std::filesystem::path human = locate_data_folder("KUMITE_XR_BODY", k_xr_default_body);
        if (character_file_exists(human)) character = human.string();
        else std::cerr << "kumite play --xr: the default human body " << human.string() << " is missing: the first shipped character instead\n";
    }
    Result<BoutCast> cast = load_bout_cast(characters_dir, character);
    if (!cast) return cast.error().code == ErrorCode::invalid ? usage_error(spec, cast.error().message) : input_error(cast.error().message);
    options.fighters = static_cast<int>(*fighters_count);
    options.record = arguments.value("record").has_value();
    if (std::optional<std::string> problem = options.record ? recording_path_problem(*arguments.value("record")) : std::nullopt) {
        return usage_error(spec, "--record " + *problem);
    }
    options.start_character = cast->start;
    Result<std::unique_ptr<Bout>> created = Bout::create(database->view(), std::move(cast->characters), std::move(*tracker), options);
    if (!created) return input_error(created.error().message);
    Bout& bout = **created;
    if (extras && extras->drill) {
        if (!arguments.has("duration")) duration_s = extras->drill->duration_s() + 1.0; // its end line ends the bout before
        bout.set_drill(std::move(*extras->drill));
        extras->drill.reset();
    }
    if (script) bout.set_script(std::move(*script));
    if (stream) bout.set_stream(std::move(stream));
    bout.set_message_handler([](std::string_view message) { std::cerr << "kumite play: " << message; });

    PartialFile events_out, user_out;
    const std::optional<std::string> html_path = arguments.value("html");
    if (html_path) {
        const std::filesystem::path folder_of_html = std::filesystem::absolute(*html_path).parent_path();
        if (!std::filesystem::is_directory(folder_of_html)) return input_error(*html_path + ": no folder " + folder_of_html.string() + " to write the session report in");
    }
    // The event lines go to the events file and, for --html, into the session log as they come.
    report::SessionLog session;
    auto write_event = [&](nlohmann::json line) {
        // Against a recorded person every line of the bout says where in the capture it was.
        const CaptureUser* capture = bout.tracker().capture();
        if (capture && bout.counters().frames > 0 && !line.contains("capture_s")) line["capture_s"] = capture->capture_time_s();
        if (events_out.is_open()) events_out.stream() << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        if (html_path) session.add(line);
        if (extras && extras->on_event) extras->on_event(line);
    };
    if (const std::optional<std::string> path = arguments.value("events")) {
        if (Result<void> opened = events_out.open(*path, "the events file"); !opened) return input_error(opened.error().message);
    }
    const PlaySetup setup{xr ? std::string("xr") : arguments.value("tracker").value_or("simulate:still"), database_path->string(), *seed};
    const nlohmann::json settings = play_settings_json(options);
    if (extras && extras->on_start) {
        const std::string start_character = bout.character_name(bout.fighter(0).character());
        if (Result<void> started = extras->on_start({bout, settings, start_character, setup.tracker}); !started) return input_error(started.error().message);
    }
    write_event(bout_start_json(bout, setup));
    if (const std::optional<nlohmann::json> source = tracker_source_json(bout)) {
        nlohmann::json line = {{"t", 0.0}, {"type", "tracker_source"}};
        line.update(*source);
        write_event(line);
    }
    RoomSampler sampler;
    std::vector<nlohmann::json> samples;
    if (const std::optional<std::string> path = arguments.value("record-user")) {
        if (Result<void> opened = user_out.open(*path, "the user's recording"); !opened) return input_error(opened.error().message);
        user_out.stream() << "# t,x,y,z,lx,ly,lz,rx,ry,rz,lex,ley,lez,rex,rey,rez: the user's head, hands and the elbows their guard used (nan: not tracked, or the guard off), world metres\n" << std::fixed;
        user_out.stream().precision(6);
    }
    DrillPartWatch drill_parts;
    // Every event and the room's samples for the files; only what the extras take otherwise (kept off the frame loop's
    // thread: a JSON line for each of a bout's thousand events would be built for nothing).
    const bool every_event = events_out.is_open() || html_path;
    const bool some_events = extras && extras->on_event;
    auto after_step = [&] {
        if (user_out.is_open()) write_user_line(user_out.stream(), bout);
        if (!every_event && !some_events) return;
        if (std::optional<nlohmann::json> line = drill_parts.changed(bout)) write_event(*line);
        for (const BoutEvent& event : bout.events()) {
            if (every_event || !extras->wants_event || extras->wants_event(event.event.type)) write_event(play_event_json(bout, event));
        }
        if (!every_event) return;
        samples.clear();
        sampler.sample(bout, samples);
        for (const nlohmann::json& line : samples) write_event(line);
    };

    const bool realtime = arguments.has("realtime") || bout.live() || viewer || xr;
    view::PlayerRunOutcome viewer_outcome;
    nlohmann::json xr_report;
    if (xr) {
        // Beside the headset, the supervisor's window when there is a display (--headless: none).
        const bool supervisor = !arguments.has("headless") && display_present();
        if (const int status = play_xr(bout, arguments, duration_s, after_step, write_event, supervisor ? &viewer_settings : nullptr, xr_report); status != 0) {
            return status;
        }
    } else if (viewer) {
        view::PlayerRunOptions run;
        run.duration_s = duration_s;
        run.stop_after_duration = arguments.has("duration") || arguments.has("screenshot");
        run.screenshot_path = arguments.value("screenshot").value_or("");
        const int status = view::run_player_window(bout, viewer_settings, run, after_step, &viewer_outcome);
        if (status != 0) return status;
    } else {
        const long long frames = static_cast<long long>(std::llround(duration_s * bout.rate_hz()));
        const auto wall_start = std::chrono::steady_clock::now();
        for (long long frame = 0; frame < frames && !bout.quit_requested(); ++frame) {
            const double t = double(frame) / bout.rate_hz();
            if (realtime) std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t));
            bout.step(t);
            after_step();
        }
    }

    const nlohmann::json motion = play_motion_json(bout);
    nlohmann::json end = bout_end_json(bout);
    end["motion"] = motion;
    write_event(end);
    for (PartialFile* file : {&events_out, &user_out}) {
        if (Result<void> finished = file->finish(); !finished) return input_error(finished.error().message);
    }
    if (const std::optional<std::string> path = arguments.value("record")) {
        const BvhFile& start = bout.starting_character_file();
        const CharacterEntry& entry = cast->entries[std::size_t(options.start_character)];
        if (Result<void> written = write_recording(*path, bout.recording(), start, characters_dir, entry.body.empty() ? entry.name : entry.body.string()); !written) {
            return input_error(written.error().message);
        }
    }
    nlohmann::json report = play_report_json(bout);
    if (const std::optional<nlohmann::json> source = tracker_source_json(bout)) report["tracker_source"] = *source;
    report["motion"] = motion;
    report["settings"] = settings;
    if (bout.drill()) report["drill"] = drill_report_json(bout);
    report["difficulty"] = difficulty_of(options);
    report["realtime"] = realtime;
    report["viewer"] = viewer;
    if (xr) report["xr"] = xr_report;
    if (viewer) report["viewer_drawing"] = {{"renderer", viewer_outcome.renderer}, {"body_meshes_uploaded", viewer_outcome.body_mesh_uploads}};
    if (const std::optional<std::string> path = arguments.value("report")) {
        if (Result<void> written = write_file_atomically(*path, report.dump(2) + "\n"); !written) return input_error(written.error().message);
    }
    if (extras && extras->on_end) {
        if (Result<void> ended = extras->on_end(report); !ended) return input_error(ended.error().message);
    }
    if (html_path) {
        if (Result<void> written = write_file_atomically(*html_path, report::session_html(session, &report, arguments.value("events").value_or("kumite play"))); !written) {
            return input_error(written.error().message);
        }
    }
    if (arguments.has("json")) {
        print_json(report);
    } else {
        std::vector<std::pair<std::string, std::string>> files;
        for (const auto& [flag, what] : {std::pair{"events", "events"}, std::pair{"record", "recording"}, std::pair{"record-user", "user's track"},
                                         std::pair{"report", "report"}, std::pair{"html", "session page"}}) {
            if (const std::optional<std::string> path = arguments.value(flag)) files.emplace_back(what, *path);
        }
        std::cout << play_summary_text(report, files);
    }
    return k_exit_ok;
}

} // namespace kumite::cli
