// kumite play: the fighter against a tracked (or simulated) user, driven by supervisor commands. In the viewer when
// a display is present and --headless is not given (on the wall clock); headless on a simulated clock (as fast as
// possible, deterministic with --seed) unless --realtime or a live tracker.

#include "capture_loading.h"
#include "partial_file.h"
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
#include "player_window.h"

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
        "[DB.kdb] [--character NAME] [--fighters N] [--tracker dtrack:PORT[:HEAD[,LEFT,RIGHT]] | replay:FILE | simulate:KIND|FILE] "
        "[--commands stdin | tcp:PORT | script:FILE] [--headless] [--viewer-config FILE.json] [--duration S] [--realtime] [--seed N] "
        "[--aim latched|predicted] [--variety N] [--no-defence] [--record OUT.bvh|OUT.glb] [--events OUT.jsonl] [--report OUT.json]",
        "Runs the fighter at 60 Hz against the user's head and hands (a DTrack system, a replayed CSV, or a\n"
        "simulated user) and the supervisor's commands, one per line: punch [left|right] [straight|hook|uppercut]\n"
        "[low|middle|high], kick [left|right] [front|roundhouse|side] [low|middle|high], slash [left|right] [low|middle|high],\n"
        "character NAME, aim latched|predicted, defence on|off, quit (in a script file, each line starts with its\n"
        "time in seconds; on stdin or TCP on 127.0.0.1 they apply when they arrive). Headless runs use a simulated\n"
        "clock unless --realtime or the tracker is live. With a display and without --headless the viewer opens\n"
        "(keys listed on screen; it runs until closed, or for --duration when given). Without DB.kdb: $KUMITE_DB, else the reference annotations baked once\n"
        "and cached (baked again when they or their captures change).",
        0, 1,
        {{"character", "NAME", "the starting character (default: the first of data/characters)"},
         {"fighters", "N", "fighters side by side against the same user (default 1)"},
         {"tracker", "SOURCE", "dtrack:PORT[:BODY] (no BODY: the only 6d body, else the 3d markers' centroid), dtrack:PORT:HEAD,LEFT,RIGHT\n"
                              "(the hands too: 6d body or 3d marker ids), replay:FILE.csv (t,x,y,z[,lx,ly,lz,rx,ry,rz]), or\n"
                              "simulate:still|wander|walk[:SPEED]|dodge|punch|counter|FILE (a user script; default simulate:still), or\n"
                              "capture:FILE.bvh[:DISTANCE[:START_S]] (a recorded person: its head and hands, facing the fighter, its mean\n"
                              "head DISTANCE m in front (default 1.2), from START_S s into the capture, looping at its end)"},
         {"tracker-config", "FILE.json", "the room: bind address, room-to-world transform, room bounds (dtrack)"},
         {"commands", "SOURCE", "stdin, tcp:PORT (127.0.0.1) or script:FILE ('<time_s> <command>' per line)"},
         {"headless", "", "no window"},
         {"screenshot", "OUT.png", "viewer: save the window after --duration seconds and close"},
         {"viewer-config", "FILE.json", "the wall screen's corners, the eye separation, stereo and camera mode (see runtime/player/README.md)"},
         {"duration", "S", "seconds to run (default 30)"},
         {"realtime", "", "step on the wall clock"},
         {"seed", "N", "seed of the simulated user (default 1)"},
         {"lead", "S", "the least time from an order's strike start to its contact (default 0.4 s)"},
         {"plans-per-frame", "N", "at most N fighters plan a strike in one frame, the others on the next frames, oldest order first (default 14; 0: no limit)"},
         {"steer-until", "S", "predicted aim: the strike follows the head until S before its contact (default 0.15 s; 0: never steers)"},
         {"variety", "N", "prefer a clip not used in the last N strikes when one scores within 0.15 of the best (default 6, 0: always the best)"},
         {"no-defence", "", "the fighter does not block or slip the user's strikes (also the command 'defence on|off', the viewer's D key)"},
         {"aim", "latched|predicted", "strike the head where it was at the order (default), or where it will be at the contact\n"
                                      "if it keeps its course (also the command 'aim latched|predicted' and the viewer's A key)"},
         {"record", "OUT.bvh|OUT.glb", "the first fighter's motion on the starting character (glTF: with its body)"},
         {"record-user", "OUT.csv", "the user as the tracker gave it, every frame: t,x,y,z[,lx,ly,lz,rx,ry,rz] (replay it with --tracker replay:OUT.csv)"},
         {"events", "OUT.jsonl", "one JSON object per event"},
         {"report", "OUT.json", "frames, frame times, orders, strikes, hits, misses, impacts, overshoot, joint-limit violations, tracker counts"},
         characters_dir_flag(), json_flag()}};
    return spec;
}

namespace {

nlohmann::json summary_of(const ValueHistogram& values) {
    return {{"mean", values.mean()}, {"p99", values.quantile(0.99)}, {"max", values.max()}};
}

// Median, p95 and max (the strike figures of issue 13's reports).
nlohmann::json quantiles_of(const ValueHistogram& values) {
    return {{"median", values.quantile(0.5)}, {"p95", values.quantile(0.95)}, {"max", values.max()}, {"count", values.count()}};
}

const char* side_text(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "any"; }
// An order's kind or height: "any" when it named none.
const char* label_text(const char* name) { return std::string_view(name) == "none" ? "any" : name; }

bool display_present() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

// What the user is when it is a recorded person (else none): which capture, placed where, and how far it got.
std::optional<nlohmann::json> tracker_source_json(const Bout& bout) {
    const CaptureUser* capture = bout.tracker().capture();
    if (!capture) return std::nullopt;
    const Eigen::Vector3d head = capture->mean_head();
    return nlohmann::json{{"source", "capture"},
                          {"capture", capture->path()},
                          {"distance_m", capture->placement().distance_m},
                          {"start_s", capture->placement().start_s},
                          {"duration_s", capture->duration_s()},
                          {"frame_rate_hz", 1.0 / capture->frame_time_s()},
                          {"performer_height_m", capture->performer_height_m()},
                          {"mean_head", {head.x(), head.y(), head.z()}},
                          {"at_end", "loops"},
                          {"loops", capture->loops()}};
}

// One line of the user's recording: t, head, hands (nan when a hand is not tracked); nothing while the tracker has
// no head (a gap, as a replay reads it).
void write_user_line(std::ostream& out, const Bout& bout) {
    if (!bout.head()) return;
    const Eigen::Vector3d& head = *bout.head();
    out << bout.now_s() << "," << head.x() << "," << head.y() << "," << head.z();
    const UserHands& hands = bout.hands();
    for (int side = 0; side < 2; ++side) {
        if (hands.present[side]) out << "," << hands.world[side].x() << "," << hands.world[side].y() << "," << hands.world[side].z();
        else out << ",nan,nan,nan";
    }
    out << "\n";
}

} // namespace

nlohmann::json play_event_json(const Bout& bout, const BoutEvent& bout_event) {
    const FighterEvent& event = bout_event.event;
    nlohmann::json line = {{"t", event.t_s}, {"type", fighter_event_name(event.type)}, {"fighter", bout_event.fighter}};
    const Retriever& retriever = bout.retriever();
    if (const CaptureUser* capture = bout.tracker().capture()) line["capture_s"] = capture->capture_time_s();
    switch (event.type) {
    case FighterEvent::Type::order:
    case FighterEvent::Type::order_queued:
    case FighterEvent::Type::order_performed:
    case FighterEvent::Type::order_expired:
        line["command"] = retriever.semantics_name(event.semantics);
        line["side"] = side_text(event.side);
        line["kind"] = label_text(strike_kind_name(event.kind));
        line["height"] = label_text(strike_height_name(event.height));
        if (event.type == FighterEvent::Type::order_performed || event.type == FighterEvent::Type::order_expired) line["waited_s"] = event.waited_s;
        if (event.type == FighterEvent::Type::order_expired) line["why"] = event.why;
        break;
    case FighterEvent::Type::ignored_order:
        line["why"] = event.why;
        if (event.semantics >= 0) line["command"] = retriever.semantics_name(event.semantics);
        line["side"] = side_text(event.side);
        line["kind"] = label_text(strike_kind_name(event.kind));
        line["height"] = label_text(strike_height_name(event.height));
        break;
    case FighterEvent::Type::state: line["state"] = fighter_state_name(event.state); break;
    case FighterEvent::Type::strike:
        line["result"] = event.hit ? "hit" : "miss";
        line["contact_error_m"] = event.contact_error_m;
        line["head_distance_m"] = event.head_distance_m;
        line["range_m"] = event.range_m;
        line["clip"] = bout.database().string(bout.database().clips[event.clip].name);
        line["kind"] = strike_kind_name(bout.database().clips[event.clip].strike_kind());
        line["height"] = strike_height_name(bout.database().clips[event.clip].strike_height());
        line["clip_side"] = side_text(static_cast<Side>(bout.database().clips[event.clip].side));
        line["ordered"] = {{"side", side_text(event.side)}, {"kind", label_text(strike_kind_name(event.kind))},
                           {"height", label_text(strike_height_name(event.height))}};
        line["varied"] = event.varied;
        line["effector_speed_at_contact_mps"] = event.effector_speed_mps;
        line["outcome"] = event.impact ? "impact" : "follow_through";
        line["aim"] = fighter_aim_name(event.aim);
        line["target"] = {event.target.x(), event.target.y(), event.target.z()};
        line["head_speed_mps"] = event.head_speed_mps;
        line["prediction_error_m"] = event.prediction_error_m;
        line["retrieval_offset_m"] = event.retrieval_offset_m;
        line["steered_m"] = event.steered_m;
        line["target_part"] = target_part_name(event.target_part);
        line["reachable"] = event.reachable;
        break;
    case FighterEvent::Type::strike_end:
        line["clip"] = bout.database().string(bout.database().clips[event.clip].name);
        line["outcome"] = event.impact ? "impact" : "follow_through";
        line["overshoot_m"] = event.overshoot_m;
        line["joint_limit_violations"] = event.joint_limit_violations;
        break;
    case FighterEvent::Type::character: line["character"] = bout.character_name(event.character); break;
    case FighterEvent::Type::user_strike:
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        line["move"] = defence_move_name(event.user_strike.move);
        line["arm"] = event.user_strike.arm == 0 ? "left" : "right";
        line["time_to_impact_s"] = event.user_strike.time_to_impact_s;
        line["detected"] = event.user_strike.detected;
        line["hand_speed_mps"] = event.user_strike.hand_speed_mps;
        break;
    case FighterEvent::Type::user_strike_end:
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        line["move"] = defence_move_name(event.user_strike.move);
        line["outcome"] = user_strike_outcome_name(event.user_strike.outcome);
        if (event.user_strike.forearm_to_path_m >= 0.0) line["forearm_to_path_m"] = event.user_strike.forearm_to_path_m;
        line["detected"] = event.user_strike.detected;
        if (event.user_strike.blocking_arm >= 0) line["blocking_arm"] = event.user_strike.blocking_arm == 0 ? "left" : "right";
        line["joint_limit_violations"] = event.joint_limit_violations;
        line["foot_shift_m"] = event.foot_shift_m;
        break;
    default: break;
    }
    return line;
}

// Orders still under way or queued when the bout ended (every other order ended performed, refused or expired).
static long long waiting_orders(const Bout& bout) {
    long long waiting = 0;
    for (int f = 0; f < bout.fighter_count(); ++f) waiting += bout.fighter(f).has_waiting_order();
    return waiting;
}

nlohmann::json play_report_json(const Bout& bout) {
    const BoutCounters& counters = bout.counters();
    nlohmann::json by_target;
    for (int target = 0; target < 2; ++target) {
        for (UserStrikeOutcome outcome : {UserStrikeOutcome::blocked, UserStrikeOutcome::slipped, UserStrikeOutcome::hit_by_user, UserStrikeOutcome::missed}) {
            by_target[target == 0 ? "head" : "chest"][user_strike_outcome_name(outcome)] =
                counters.user_outcomes_by_target[target][static_cast<int>(outcome)];
        }
    }
    // Strikes and hits by what the clips are (semantics, kind, height, side), and how many clips were used.
    nlohmann::json by_kind = nlohmann::json::object();
    int clips_used = 0;
    const MotionDatabaseView& db = bout.database();
    for (std::size_t c = 0; c < counters.by_clip.size(); ++c) {
        const auto [strikes, hits] = counters.by_clip[c];
        if (strikes == 0) continue;
        ++clips_used;
        const DbClip& clip = db.clips[c];
        const std::string key = std::string(db.string(clip.semantics)) + " " + strike_kind_name(clip.strike_kind()) + " " +
                                strike_height_name(clip.strike_height()) + " " + side_text(static_cast<Side>(clip.side));
        nlohmann::json& entry = by_kind[key];
        if (entry.is_null()) entry = {{"strikes", 0LL}, {"hits", 0LL}};
        entry["strikes"] = entry.value("strikes", 0LL) + strikes;
        entry["hits"] = entry.value("hits", 0LL) + hits;
    }
    const double mean_latency = counters.command_to_strike_frames.mean(), max_latency = counters.command_to_strike_frames.max();
    return {{"frames", counters.frames},
            {"fighters", bout.fighter_count()},
            {"frame_time_us", summary_of(counters.frame_us)},
            {"missed_frames", counters.missed_frames},
            {"orders", counters.orders},
            {"strikes", counters.strikes},
            {"hits", counters.hits},
            {"misses", counters.misses},
            {"ignored_orders", counters.ignored_orders},
            {"order_outcomes",
             {{"performed", counters.orders_performed}, {"queued", counters.orders_queued}, {"expired", counters.orders_expired},
              {"refused", counters.ignored_orders}, {"waiting_at_end", waiting_orders(bout)}}},
            {"tracker_packets", bout.tracker().packets()},
            {"tracker_rejected", bout.tracker().rejected()},
            {"command_to_strike_frames", {{"max", max_latency}, {"mean", mean_latency}}},
            {"impacts", counters.impacts},
            {"follow_throughs", counters.follow_throughs},
            {"overshoot_m", quantiles_of(counters.impact_overshoot_m)},
            {"effector_speed_at_contact_mps", quantiles_of(counters.contact_speed_mps)},
            {"joint_limit_violations", counters.joint_limit_violations},
            {"aim", fighter_aim_name(bout.fighter(0).aim())},
            {"by_kind", by_kind},
            {"clips_used", clips_used},
            {"by_aim",
             {{"latched", {{"strikes", counters.latched_strikes}, {"hits", counters.latched_hits}}},
              {"predicted", {{"strikes", counters.predicted_strikes}, {"hits", counters.predicted_hits}}}}},
            {"prediction_error_m", quantiles_of(counters.prediction_error_m)},
            {"defence", bout.fighter(0).defence_enabled()},
            {"user_strikes",
             {{"seen", counters.user_strikes}, {"blocks", counters.blocks}, {"slips", counters.slips}, {"blocked", counters.blocked},
              {"slipped", counters.slipped}, {"hit_by_user", counters.hit_by_user}, {"missed", counters.user_missed},
              {"forearm_to_path_m", quantiles_of(counters.forearm_to_path_m)},
              {"joint_limit_violations", counters.defence_joint_limit_violations},
              {"foot_shift_m", counters.defence_foot_shift_m},
              {"by_target", by_target}}}};
}

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
    const Result<double> steer_until_s = arguments.number("steer-until", 0.0, 5.0, FighterSettings{}.steer_until_s, "seconds");
    if (!steer_until_s) return usage_error(play_spec(), steer_until_s.error().message);
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
    const bool want_viewer = !arguments.has("headless");
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
    Result<std::unique_ptr<HeadTracker>> tracker =
        HeadTracker::open(arguments.value("tracker").value_or("simulate:still"), dtrack_config, static_cast<std::uint64_t>(*seed));
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
    Result<MotionDatabase> database = MotionDatabase::open(*database_path);
    if (!database) return input_error(database.error().message);
    const std::optional<std::string> folder = arguments.value("characters-dir");
    const std::filesystem::path characters_dir = folder ? std::filesystem::path(*folder) : default_characters_dir();
    std::vector<CharacterEntry> entries = list_characters(characters_dir);
    if (entries.empty()) return input_error(characters_dir.string() + ": no characters");
    std::string wanted = arguments.value("character").value_or(entries[0].name);
    // A path to a character file of one's own joins the shipped ones under its file's stem.
    if (std::none_of(entries.begin(), entries.end(), [&](const CharacterEntry& entry) { return entry.name == wanted; })) {
        const std::filesystem::path path(wanted);
        if (character_file_exists(path)) {
            const bool stem_taken = std::any_of(entries.begin(), entries.end(), [&](const CharacterEntry& entry) { return entry.name == path.stem().string(); });
            entries.push_back({stem_taken ? path.filename().string() : path.stem().string(), path, is_gltf_path(path) ? path : std::filesystem::path()});
            wanted = entries.back().name;
        }
    }
    BoutOptions options;
    options.fighters = static_cast<int>(*fighters_count);
    options.lead_s = *lead_s;
    options.fighter.steer_until_s = *steer_until_s;
    options.plans_per_frame = static_cast<int>(*plans_per_frame);
    options.fighter.aim = aim;
    options.fighter.defence.enabled = !arguments.has("no-defence");
    options.fighter.variety_recent = static_cast<int>(*variety);
    options.record = arguments.value("record").has_value();
    if (std::optional<std::string> problem = options.record ? recording_path_problem(*arguments.value("record")) : std::nullopt) {
        return usage_error(play_spec(), "--record " + *problem);
    }
    options.start_character = -1;
    std::vector<BoutCharacter> characters;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        Result<BvhFile> file = read_character_file(entries[i].file);
        if (!file) return input_error(file.error().message);
        std::shared_ptr<const SkinnedMesh> body;
        if (!entries[i].body.empty()) {
            Result<std::optional<SkinnedMesh>> loaded = load_character_body(characters_dir, entries[i].body.string(), file->clip.skeleton);
            if (!loaded) return input_error(loaded.error().message);
            if (*loaded) body = std::make_shared<const SkinnedMesh>(std::move(**loaded));
        }
        characters.push_back({entries[i].name, std::move(*file), std::move(body)});
        if (entries[i].name == wanted) options.start_character = static_cast<int>(i);
    }
    if (options.start_character < 0) return usage_error(play_spec(), "unknown character '" + wanted + "' (see kumite characters)");
    Result<std::unique_ptr<Bout>> created = Bout::create(database->view(), std::move(characters), std::move(*tracker), options);
    if (!created) return input_error(created.error().message);
    Bout& bout = **created;
    if (script) bout.set_script(std::move(*script));
    if (stream) bout.set_stream(std::move(stream));
    bout.set_message_handler([](std::string_view message) { std::cerr << "kumite play: " << message; });

    PartialFile events_out, user_out;
    if (const std::optional<std::string> path = arguments.value("events")) {
        if (Result<void> opened = events_out.open(*path, "the events file"); !opened) return input_error(opened.error().message);
        if (const std::optional<nlohmann::json> source = tracker_source_json(bout)) {
            nlohmann::json line = {{"t", 0.0}, {"type", "tracker_source"}};
            line.update(*source);
            events_out.stream() << line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        }
    }
    if (const std::optional<std::string> path = arguments.value("record-user")) {
        if (Result<void> opened = user_out.open(*path, "the user's recording"); !opened) return input_error(opened.error().message);
        user_out.stream() << "# t,x,y,z,lx,ly,lz,rx,ry,rz: the user's head and hands (nan: not tracked), world metres\n" << std::fixed;
        user_out.stream().precision(6);
    }
    auto after_step = [&] {
        if (user_out.is_open()) write_user_line(user_out.stream(), bout);
        if (!events_out.is_open()) return;
        for (const BoutEvent& event : bout.events()) {
            events_out.stream() << play_event_json(bout, event).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        }
    };

    const bool realtime = arguments.has("realtime") || bout.live() || viewer;
    view::PlayerRunOutcome viewer_outcome;
    if (viewer) {
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

    for (PartialFile* file : {&events_out, &user_out}) {
        if (Result<void> finished = file->finish(); !finished) return input_error(finished.error().message);
    }
    if (const std::optional<std::string> path = arguments.value("record")) {
        const BvhFile& start = bout.starting_character_file();
        const CharacterEntry& entry = entries[std::size_t(options.start_character)];
        if (Result<void> written = write_recording(*path, bout.recording(), start, characters_dir, entry.body.empty() ? entry.name : entry.body.string()); !written) {
            return input_error(written.error().message);
        }
    }
    nlohmann::json report = play_report_json(bout);
    if (const std::optional<nlohmann::json> source = tracker_source_json(bout)) report["tracker_source"] = *source;
    report["realtime"] = realtime;
    report["viewer"] = viewer;
    if (viewer) report["viewer_drawing"] = {{"renderer", viewer_outcome.renderer}, {"body_meshes_uploaded", viewer_outcome.body_mesh_uploads}};
    if (const std::optional<std::string> path = arguments.value("report")) {
        if (Result<void> written = write_file_atomically(*path, report.dump(2) + "\n"); !written) return input_error(written.error().message);
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
