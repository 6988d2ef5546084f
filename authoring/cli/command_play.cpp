// kumite play: the fighter against a tracked (or simulated) user, driven by supervisor commands. In the viewer when
// a display is present and --headless is not given (on the wall clock); headless on a simulated clock (as fast as
// possible, deterministic with --seed) unless --realtime or a live tracker.

#include "capture_loading.h"
#include "partial_file.h"
#include "play_motion.h"
#include "play_output.h"
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
        "[DB.kdb] [--character NAME] [--fighters N] [--tracker dtrack:PORT[:HEAD[,LEFT,RIGHT]] | replay:FILE | simulate:KIND|FILE] "
        "[--commands stdin | tcp:PORT | script:FILE] [--headless] [--viewer-config FILE.json] [--duration S] [--realtime] [--seed N] "
        "[--aim latched|predicted] [--variety N] [--no-defence] [--captured-blocks [--block-speed-limit RATIO]] [--max-speedup RATIO] [--human-speed] [--superhuman-strikes] [--superhuman-moves] [--superhuman-blocks] [--superhuman-extremities] [--drop-guard] [--no-hit-reactions] [--no-block-handover] [--no-slip-in-reaction] [--rest-in-reach] [--stay-after-strikes] [--play-out-strikes] [--stand-ground] [--no-lead-steps] [--record OUT.bvh|OUT.glb] [--events OUT.jsonl] [--report OUT.json] [--verify]",
        "Runs the fighter at 60 Hz against the user's head and hands (a DTrack system, a replayed CSV, or a\n"
        "simulated user) and the supervisor's commands, one per line: punch [left|right] [straight|hook|uppercut]\n"
        "[low|middle|high], kick [left|right] [front|roundhouse|side] [low|middle|high], slash [left|right] [low|middle|high],\n"
        "character NAME, aim latched|predicted, defence on|off, quit (in a script file, each line starts with its\n"
        "time in seconds; on stdin or TCP on 127.0.0.1 they apply when they arrive). Headless runs use a simulated\n"
        "clock unless --realtime or the tracker is live. With a display and without --headless the viewer opens\n"
        "(keys listed on screen; it runs until closed, or for --duration when given). Without DB.kdb: $KUMITE_DB, else the reference annotations baked once\n"
        "and cached (baked again when they or their captures change).",
        0, 1,
        {{"character", "NAME", "the starting character (default: the first of data/characters; with --xr the human body of data/bodies)"},
         {"fighters", "N", "fighters side by side against the same user (default 1)"},
         {"tracker", "SOURCE", "dtrack:PORT[:BODY] (no BODY: the only 6d body, else the 3d markers' centroid), dtrack:PORT:HEAD,LEFT,RIGHT\n"
                              "(the hands too: 6d body or 3d marker ids), replay:FILE.csv (t,x,y,z[,lx,ly,lz,rx,ry,rz]), or\n"
                              "simulate:still|wander|walk[:SPEED]|dodge|dodge-seen|punch|counter|FILE (a user script; default simulate:still), or\n"
                              "capture:FILE.bvh[:DISTANCE[:START_S]] (a recorded person: its head and hands, facing the fighter, its mean\n"
                              "head DISTANCE m in front (default 1.2), from START_S s into the capture, looping at its end)"},
         {"tracker-config", "FILE.json", "the room: bind address, room-to-world transform, room bounds (dtrack)"},
         {"commands", "SOURCE", "stdin, tcp:PORT (127.0.0.1) or script:FILE ('<time_s> <command>' per line)"},
         {"headless", "", "no window (with --xr: no supervisor's window beside the headset)"},
         {"xr", "", "in an OpenXR headset (the system's runtime; XR_RUNTIME_JSON honoured): its head and grips are the user, both\n"
                    "eyes drawn into the runtime's swapchains; runs --duration S of bout time (README \"In the headset\")"},
         {"xr-view-size", "WxH", "with --xr: the size drawn per eye (default: the runtime's recommended size; beyond its largest image,\n"
                                    "drawn at this size and scaled into it)"},
         {"xr-eye-image", "OUT.png", "with --xr: the left eye's image near the end of the bout (its geometry in the report's xr.eye_image)"},
         {"screenshot", "OUT.png", "viewer: save the window after --duration seconds and close (with --xr: the supervisor's window at the end)"},
         {"viewer-config", "FILE.json", "the wall screen's corners, the eye separation, stereo and camera mode (see runtime/player/README.md)"},
         {"duration", "S", "seconds to run (default 30)"},
         {"realtime", "", "step on the wall clock"},
         {"seed", "N", "seed of the simulated user (default 1)"},
         {"lead", "S", "the least time from an order's strike start to its contact (default 0.4 s)"},
         {"contact-extension", "SHARE", "strikes make contact where the hit point has covered SHARE of its way to the annotated hit, still\n"
                                        "travelling (default 0.9; 1: at the annotated hit, full extension, the paper's contact)"},
         {"contact-speed-share", "SHARE", "... or earlier, before the hit point first slows under SHARE of its top speed on the way (default 0.85;\n"
                                          "0: by extension alone)"},
         {"plans-per-frame", "N", "at most N fighters plan a strike in one frame, the others on the next frames, oldest order first (default 14; 0: no limit)"},
         {"steer-until", "S", "predicted aim: the strike follows the head until S before its contact (default 0.15 s; 0: never steers)"},
         {"variety", "N", "prefer a clip not used in the last N strikes when one scores within 0.15 of the best (default 6, 0: always the best)"},
         {"max-speedup", "RATIO", "a punch or kick captured slower than a real one lands (5 and 7 m/s) is played up to RATIO times as fast until\n"
                                  "its contact, which comes when it would as captured (default 1.6, at most 1.9; 1: every strike at its captured speed)"},
         {"human-speed", "", "no joint of the fighter moves faster than the library's fastest for its kind of move (wrists and ankles\n"
                             "never over 12 m/s): a move that asks for more is shown lagging (the report's motion.by_move held_back_frames)"},
         {"rest-in-reach", "", "between strikes the fighter rests where its strikes reach (as the paper's); default: just out of reach\n"
                               "(0.8-1.2 leg lengths from the user's head), stepping in to strike and out after"},
         {"stay-after-strikes", "", "after a strike the fighter recovers where it stands, then steps out (default: with no order waiting, it\n"
                                   "recovers stepping back out to the fighting distance)"},
         {"play-out-strikes", "", "every strike's captured clip is played to its end (default: 0.15 s after its contact, the impact and\n"
                                 "the recoil shown, the fighter recovers to its guard from there, free to slip, block and step out)"},
         {"stand-ground", "", "a user who rushes in while the fighter steps or recovers is met where it stands, stepping back only\n"
                             "where its clip ends (default: nearer than 0.6 leg lengths, it steps back at once)"},
         {"lead-steps", "", "steps sized for where a walking user will be (the default; kept for scripts that ask for it)"},
         {"no-lead-steps", "", "a step is sized for where the user's head is, not where it will be when the step lands (default: for a\n"
                              "user on a settled course at 0.6 m/s or more, where it will be: one who walks away is caught up with)"},
         {"superhuman-strikes", "", "a strike's own limb has its elbow or knee free (default: held to the library's fastest for the kind of\n"
                                   "strike, as every other joint; the strike waits for a fist or foot more than half the hit radius behind)"},
         {"superhuman-moves", "", "steps, the guard, slips, recoveries, hit reactions and strikes are not held to the library's speeds for\n"
                                 "their kind (default: they are, as with --human-speed); blocks still are"},
         {"superhuman-blocks", "", "a block's arm is not held to the library's block speeds (default: it is, as with --human-speed; a\n"
                                  "block the fist leaves too little time for arrives late; implies --superhuman-moves)"},
         {"superhuman-extremities", "", "wrists and ankles are not held to a person's 12 m/s (default: they are; a strike that asks for more lags\n"
                                       "and lands later, its speed at contact at most that)"},
         {"drop-guard", "", "while striking, the free arm moves as its clip has it (a kata's punch pulls the other hand to the hip;\n"
                           "default: it stays where the guard had it, covering the face)"},
         {"no-hit-reactions", "", "a user strike that lands does not move the fighter (default: a captured hit reaction, the way the blow pushed)"},
         {"no-defence", "", "the fighter does not block or slip the user's strikes (also the command 'defence on|off', the viewer's D key)"},
         {"no-block-handover", "", "one defence move at a time, held and released before the next (default: a block whose blow is over\n"
                                   "gives way to the next blow of a combination)"},
         {"no-slip-in-reaction", "", "while rocked by a blow (a hit reaction) the fighter only covers with its arms (default: it may also slip\n"
                                     "the next blow, leaning on top of the reaction, never past the trunk's limit)"},
         {"captured-blocks", "", "block punches with the database's captured blocks when one fits: rising at the head, rising or downward at\n"
                                 "the chest (events: move block_clip); else the block is synthesized from the guard"},
         {"block-speed-limit", "RATIO", "captured blocks move the arm at most RATIO times as fast as their clip (1: no faster than captured, no pop);\n"
                                        "a fist that leaves less time gets past the late forearm (default 0: no limit, every block in time)"},
         {"aim", "latched|predicted", "strike the head where it was at the order (default), or where it will be at the contact\n"
                                      "if it keeps its course (also the command 'aim latched|predicted' and the viewer's A key)"},
         {"record", "OUT.bvh|OUT.glb", "the first fighter's motion on the starting character (glTF: with its body)"},
         {"record-user", "OUT.csv", "the user as the tracker gave it, every frame: t,x,y,z[,lx,ly,lz,rx,ry,rz] (replay it with --tracker replay:OUT.csv)"},
         {"events", "OUT.jsonl", "one JSON object per event"},
         {"html", "OUT.html", "the session report: one page with the summary, a timeline, the room from above and distributions (also kumite report)"},
         {"report", "OUT.json", "frames, frame times, orders, strikes, hits, misses, impacts, overshoot, joint-limit violations, tracker counts"},
         characters_dir_flag(), verify_flag(), json_flag()}};
    return spec;
}

namespace {

bool display_present() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

} // namespace

int run_play(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(play_spec(), argc, argv, arguments)) return *status;
    const Result<long long> fighters_count = arguments.integer("fighters", 1, 10000, 1);
    const Result<long long> seed = arguments.integer("seed", 0, 1LL << 62, 1);
    if (!fighters_count) return usage_error(play_spec(), fighters_count.error().message);
    if (!seed) return usage_error(play_spec(), seed.error().message);
    const Result<long long> variety = arguments.integer("variety", 0, k_max_variety_recent, 6);
    if (!variety) return usage_error(play_spec(), variety.error().message);
    const Result<double> lead_s = arguments.number("lead", 0.0, 5.0, 0.4, "seconds");
    if (!lead_s) return usage_error(play_spec(), lead_s.error().message);
    const Result<double> contact_extension = arguments.number("contact-extension", 0.5, 1.0, RetrievalSettings{}.contact_extension, "");
    if (!contact_extension) return usage_error(play_spec(), contact_extension.error().message);
    const Result<double> contact_speed_share = arguments.number("contact-speed-share", 0.0, 1.0, RetrievalSettings{}.contact_speed_share, "");
    if (!contact_speed_share) return usage_error(play_spec(), contact_speed_share.error().message);
    const Result<double> steer_until_s = arguments.number("steer-until", 0.0, 5.0, FighterSettings{}.steer_until_s, "seconds");
    if (!steer_until_s) return usage_error(play_spec(), steer_until_s.error().message);
    const Result<double> max_speedup = arguments.number("max-speedup", 1.0, 1.9, FighterSettings{}.max_speedup, "times the captured speed");
    if (!max_speedup) return usage_error(play_spec(), max_speedup.error().message);
    const Result<double> block_speed_limit = arguments.number("block-speed-limit", 0.0, 100.0, 0.0, "times the clip's speed");
    if (!block_speed_limit) return usage_error(play_spec(), block_speed_limit.error().message);
    if (*block_speed_limit > 0.0 && !arguments.has("captured-blocks")) return usage_error(play_spec(), "--block-speed-limit applies to --captured-blocks: add it");
    const Result<long long> plans_per_frame = arguments.integer("plans-per-frame", 0, 100000, BoutOptions{}.plans_per_frame);
    if (!plans_per_frame) return usage_error(play_spec(), plans_per_frame.error().message);
    FighterAim aim = FighterAim::latched;
    if (const std::optional<std::string> text = arguments.value("aim")) {
        const std::optional<FighterAim> parsed = fighter_aim_from_name(*text);
        if (!parsed) return usage_error(play_spec(), "--aim must be latched or predicted, not '" + *text + "'");
        aim = *parsed;
    }
    double duration_s = 30.0;
    if (const std::optional<std::string> text = arguments.value("duration")) {
        char* end = nullptr;
        duration_s = std::strtod(text->c_str(), &end);
        if (end == text->c_str() || *end != '\0' || !(duration_s > 0.0) || duration_s > 86400.0) {
            return usage_error(play_spec(), "--duration must be seconds, more than 0, not '" + *text + "'");
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
    if (xr && arguments.has("tracker")) return usage_error(play_spec(), "--xr: the headset is the tracker, leave out --tracker");
    if ((arguments.has("xr-eye-image") || arguments.has("xr-view-size")) && !xr) return usage_error(play_spec(), "--xr-eye-image and --xr-view-size need --xr");
    Result<std::unique_ptr<HeadTracker>> tracker =
        xr ? Result<std::unique_ptr<HeadTracker>>(HeadTracker::fed())
           : HeadTracker::open(arguments.value("tracker").value_or("simulate:still"), dtrack_config, static_cast<std::uint64_t>(*seed));
    if (!tracker) {
        return tracker.error().code == ErrorCode::invalid ? usage_error(play_spec(), tracker.error().message) : input_error(tracker.error().message);
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
            if (!opened) return usage_error(play_spec(), opened.error().message);
            stream = std::move(*opened);
            if (stream->port() > 0) std::cerr << "kumite play: supervisor commands on 127.0.0.1:" << stream->port() << "\n";
        } else {
            return usage_error(play_spec(), "--commands takes stdin, tcp:PORT or script:FILE, not '" + *commands + "'");
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
    if (!cast) return cast.error().code == ErrorCode::invalid ? usage_error(play_spec(), cast.error().message) : input_error(cast.error().message);
    BoutOptions options;
    options.fighters = static_cast<int>(*fighters_count);
    options.lead_s = *lead_s;
    options.contact_extension = *contact_extension;
    options.contact_speed_share = *contact_speed_share;
    options.fighter.steer_until_s = *steer_until_s;
    options.fighter.max_speedup = *max_speedup;
    options.plans_per_frame = static_cast<int>(*plans_per_frame);
    options.fighter.aim = aim;
    options.fighter.defence.enabled = !arguments.has("no-defence");
    options.fighter.defence.keep_guard = !arguments.has("drop-guard");
    options.fighter.human_speed = arguments.has("human-speed");
    options.fighter.hit_reactions = !arguments.has("no-hit-reactions");
    options.fighter.human_speed_blocks = !arguments.has("superhuman-blocks");
    options.fighter.human_speed_but_strikes = !arguments.has("superhuman-moves") && !arguments.has("superhuman-blocks");
    options.fighter.human_speed_strikes = !arguments.has("superhuman-strikes");
    options.fighter.human_extremities = !arguments.has("superhuman-extremities");
    options.fighter.keep_distance = !arguments.has("rest-in-reach");
    options.fighter.steps_lead_user = !arguments.has("no-lead-steps");
    options.fighter.step_out_after_strikes = !arguments.has("stay-after-strikes");
    if (arguments.has("stand-ground")) options.fighter.crowd_legs = 0.0;
    if (arguments.has("play-out-strikes")) options.fighter.strike_follow_s = 0.0;
    options.fighter.defence.captured_blocks = arguments.has("captured-blocks");
    options.fighter.defence.hand_over_blocks = !arguments.has("no-block-handover");
    options.fighter.defence.slip_in_hit_reaction = !arguments.has("no-slip-in-reaction");
    options.fighter.defence.block_clip_max_speed_ratio = *block_speed_limit;
    options.fighter.variety_recent = static_cast<int>(*variety);
    options.record = arguments.value("record").has_value();
    if (std::optional<std::string> problem = options.record ? recording_path_problem(*arguments.value("record")) : std::nullopt) {
        return usage_error(play_spec(), "--record " + *problem);
    }
    options.start_character = cast->start;
    Result<std::unique_ptr<Bout>> created = Bout::create(database->view(), std::move(cast->characters), std::move(*tracker), options);
    if (!created) return input_error(created.error().message);
    Bout& bout = **created;
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
    };
    if (const std::optional<std::string> path = arguments.value("events")) {
        if (Result<void> opened = events_out.open(*path, "the events file"); !opened) return input_error(opened.error().message);
    }
    const PlaySetup setup{xr ? std::string("xr") : arguments.value("tracker").value_or("simulate:still"), database_path->string(), *seed};
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
        user_out.stream() << "# t,x,y,z,lx,ly,lz,rx,ry,rz: the user's head and hands (nan: not tracked), world metres\n" << std::fixed;
        user_out.stream().precision(6);
    }
    auto after_step = [&] {
        if (user_out.is_open()) write_user_line(user_out.stream(), bout);
        if (!events_out.is_open() && !html_path) return;
        for (const BoutEvent& event : bout.events()) write_event(play_event_json(bout, event));
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
    report["realtime"] = realtime;
    report["viewer"] = viewer;
    if (xr) report["xr"] = xr_report;
    if (viewer) report["viewer_drawing"] = {{"renderer", viewer_outcome.renderer}, {"body_meshes_uploaded", viewer_outcome.body_mesh_uploads}};
    if (const std::optional<std::string> path = arguments.value("report")) {
        if (Result<void> written = write_file_atomically(*path, report.dump(2) + "\n"); !written) return input_error(written.error().message);
    }
    if (html_path) {
        if (Result<void> written = write_file_atomically(*html_path, report::session_html(session, &report, arguments.value("events").value_or("kumite play"))); !written) {
            return input_error(written.error().message);
        }
    }
    if (arguments.has("json")) {
        print_json(report);
    } else {
        const BoutCounters& c = bout.counters();
        std::cout << "played " << c.frames << " frames (" << double(c.frames) / bout.rate_hz() << " s) with " << bout.fighter_count()
                  << " fighter(s): " << c.orders << " orders, " << c.strikes << " strikes, " << c.hits << " hits, " << c.misses
                  << " misses, " << c.ignored_orders << " ignored; frame time mean " << report["frame_time_us"]["mean"].get<double>()
                  << " us, p99 " << report["frame_time_us"]["p99"].get<double>() << " us\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
