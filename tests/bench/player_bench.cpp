// Fighters per frame on one core: 1, 10, 100 and 200 fighters (or --fighters LIST) stepping at 60 Hz against a
// wandering simulated user for --seconds of simulated time, every fighter ordered to strike every second (all at
// once: the worst frame). Reports frame time (mean, median, p99, max) per count, the frames over the 16.7 ms
// budget, command -> first strike frame latency, and as a baseline measured in the same run the same fighters
// never ordered (guard and steps only). Orders go through the planning budget (planning_budget.h, kumite play's
// default of 14 plans a frame); the same fighters planning every strike in its order's frame are the baseline
// (`baseline_planning_in_frame`: the slowest frame, the frames over 16.7 ms); `order_to_plan_frames` is how long a
// fighter that wants to plan waits for the budget. Defence's cost: the same fighters, never ordered, against a user whose
// hands punch at the middle fighter (in front of them) every 2 s, with defence on and off. Heap allocations inside the stepping are
// counted (must be 0).
//
// usage: player_bench DB.kdb [--fighters 1,10,100,200] [--seconds S] [--character NAME] [--characters-dir DIR]

#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/planning_budget.h"
#include "kumite/runtime/simulated_user.h"
#include "support/allocation_counter.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>

using namespace kumite;
using Clock = std::chrono::steady_clock;

namespace {

nlohmann::json summary(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    double sum = 0.0;
    for (double v : values) sum += v;
    auto at = [&](double q) { return values.empty() ? 0.0 : values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))]; };
    return {{"mean", values.empty() ? 0.0 : sum / values.size()}, {"median", at(0.5)}, {"p99", at(0.99)}, {"max", values.empty() ? 0.0 : values.back()}};
}

struct Run {
    std::vector<double> frame_us;
    std::vector<double> latency_frames;
    std::vector<double> served_frames; // order -> the frame its first plan was allowed (the planning budget's wait)
    long allocations = 0;
    int strikes = 0;
    int user_strikes_defended = 0;
};

enum class Opponent { wandering, punching_defended, punching_undefended };

Run run(const MotionDatabaseView& db, const Retriever& retriever, CharacterRig& rig, int count, double seconds, bool orders,
        Opponent opponent = Opponent::wandering, int plans_per_frame = BoutOptions{}.plans_per_frame) {
    std::vector<std::unique_ptr<Fighter>> fighters;
    const auto library_speeds = measure_library_speeds(db, {&rig}); // once, as a Bout does
    for (int i = 0; i < count; ++i) {
        FighterSettings settings;
        settings.start_x_m = (i - 0.5 * (count - 1)) * 1.2;
        settings.defence.enabled = opponent != Opponent::punching_undefended;
        fighters.push_back(std::make_unique<Fighter>(db, retriever, std::vector<CharacterRig*>{&rig}, settings, library_speeds));
    }
    SimulatedUser user(opponent == Opponent::wandering ? SimulatedKind::wander : SimulatedKind::punch, 1);
    Run result;
    std::vector<long> ordered_at(count, -1), waiting_since(count, -1);
    std::vector<Fighter*> pointers;
    for (auto& fighter : fighters) pointers.push_back(fighter.get());
    PlanningBudget planning(plans_per_frame, fighters.size());
    const long frames = static_cast<long>(seconds * 60.0);
    result.frame_us.reserve(frames); // the bench's own vectors must not allocate inside the counted window
    result.latency_frames.reserve(std::size_t(frames) * count);
    result.served_frames.reserve(std::size_t(frames) * count);
    for (long frame = 0; frame < frames; ++frame) {
        const double t = frame / 60.0;
        const Fighter& facing = *fighters[count / 2]; // the middle one stands in front of the user
        user.set_opponent(facing.part_position(BodyPart::head), facing.part_position(BodyPart::chest));
        const Eigen::Vector3d head = user.head(t);
        const UserHands hands = user.hands(t);
        kumite::test::allocation_count_reset();
        kumite::test::allocation_counting(frame > 0);
        const auto started = Clock::now();
        const bool order_now = orders && frame >= 60 && frame % 60 == 0; // every second, all at once
        // As kumite play steps a bout: the frame's orders, the planning budget, then every fighter.
        for (int i = 0; i < count && order_now; ++i) {
            if (fighters[i]->order(retriever.semantics_id(frame % 120 ? "punch" : "kick"), Side::none)) ordered_at[i] = frame;
        }
        planning.grant(pointers);
        for (int i = 0; i < count; ++i) {
            // How long a fighter that wants to plan (its order taken or no longer waiting for a strike to end)
            // waits for the budget to let it.
            if (fighters[i]->wants_to_plan() && !fighters[i]->plan_is_retry()) {
                if (waiting_since[i] < 0) waiting_since[i] = frame;
                if (fighters[i]->may_plan()) {
                    result.served_frames.push_back(double(frame - waiting_since[i]));
                    waiting_since[i] = -1;
                }
            }
            fighters[i]->step(t, &head, &hands);
            for (const FighterEvent& event : fighters[i]->events()) {
                if (event.type == FighterEvent::Type::state && event.state == FighterState::strike && ordered_at[i] >= 0) {
                    result.latency_frames.push_back(double(frame - ordered_at[i]));
                    ordered_at[i] = -1;
                }
                result.strikes += event.type == FighterEvent::Type::strike;
                result.user_strikes_defended += event.type == FighterEvent::Type::user_strike_end &&
                                                (event.user_strike.outcome == UserStrikeOutcome::blocked || event.user_strike.outcome == UserStrikeOutcome::slipped);
            }
            fighters[i]->clear_events();
        }
        result.frame_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - started).count());
        kumite::test::allocation_counting(false);
        result.allocations += kumite::test::allocations_counted();
    }
    return result;
}

} // namespace

int main(int argc, char** argv) {
    std::string database_path, character = "brawler";
    std::vector<int> counts = {1, 10, 100, 200};
    double seconds = 20.0;
    std::filesystem::path characters_dir = std::getenv("KUMITE_CHARACTERS_DIR") ? std::getenv("KUMITE_CHARACTERS_DIR") : "data/characters";
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--seconds" && i + 1 < argc) seconds = std::max(1.0, std::atof(argv[++i]));
        else if (argument == "--character" && i + 1 < argc) character = argv[++i];
        else if (argument == "--characters-dir" && i + 1 < argc) characters_dir = argv[++i];
        else if (argument == "--fighters" && i + 1 < argc) {
            counts.clear();
            for (char* text = argv[++i]; *text;) {
                counts.push_back(std::max(1, static_cast<int>(std::strtol(text, &text, 10))));
                if (*text == ',') ++text;
                else if (*text) break;
            }
        } else if (!argument.starts_with("--") && database_path.empty()) database_path = argument;
        else {
            std::cerr << "usage: player_bench DB.kdb [--fighters 1,10,100,200] [--seconds S] [--character NAME] [--characters-dir DIR]\n";
            return 2;
        }
    }
    if (database_path.empty()) {
        std::cerr << "usage: player_bench DB.kdb [--fighters 1,10,100,200] [--seconds S] [--character NAME] [--characters-dir DIR]\n";
        return 2;
    }
    Result<MotionDatabase> database = MotionDatabase::open(database_path);
    Result<BvhFile> file = bvh_read_file(characters_dir / (character + ".bvh"));
    if (!database || !file) {
        std::cerr << "player_bench: " << (!database ? database.error().message : file.error().message) << "\n";
        return 1;
    }
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    if (!anatomy) return 1;
    CharacterRig rig(file->clip.skeleton, *anatomy);
    RetrievalSettings settings;
    settings.min_lead_frames = 12; // as kumite play
    const Retriever retriever(database->view(), settings);
    nlohmann::json report = {{"benchmark", "player"}, {"database", database_path}, {"character", character}, {"rate_hz", 60},
                             {"seconds", seconds}, {"threads", 1}};
    for (int count : counts) {
        const Run fighting = run(database->view(), retriever, rig, count, seconds, true);
        const Run planning_in_frame = run(database->view(), retriever, rig, count, seconds, true, Opponent::wandering, 0);
        const Run guarding = run(database->view(), retriever, rig, count, seconds, false);
        const Run defending = run(database->view(), retriever, rig, count, seconds, false, Opponent::punching_defended);
        const Run undefended = run(database->view(), retriever, rig, count, seconds, false, Opponent::punching_undefended);
        auto over_budget = [](const Run& r) {
            return std::count_if(r.frame_us.begin(), r.frame_us.end(), [](double us) { return us > 1e6 / 60.0; });
        };
        report["fighters"][std::to_string(count)] = {
            {"frame_time_us", summary(fighting.frame_us)},
            {"frames_over_16_7_ms", over_budget(fighting)},
            {"slowest_frame_us", summary(fighting.frame_us)["max"]},
            {"strikes", fighting.strikes},
            {"command_to_strike_frames", summary(fighting.latency_frames)},
            {"order_to_plan_frames", summary(fighting.served_frames)},
            {"plans_per_frame", BoutOptions{}.plans_per_frame},
            {"baseline_planning_in_frame",
             {{"frame_time_us", summary(planning_in_frame.frame_us)},
              {"frames_over_16_7_ms", over_budget(planning_in_frame)},
              {"slowest_frame_us", summary(planning_in_frame.frame_us)["max"]},
              {"strikes", planning_in_frame.strikes},
              {"command_to_strike_frames", summary(planning_in_frame.latency_frames)}}},
            {"allocations", fighting.allocations},
            {"baseline_guard_only_frame_time_us", summary(guarding.frame_us)},
            {"against_punches_frame_time_us",
             {{"defence_on", summary(defending.frame_us)},
              {"defence_off", summary(undefended.frame_us)},
              {"defended", defending.user_strikes_defended},
              {"allocations", defending.allocations + undefended.allocations}}}};
    }
    std::cout << report.dump(2) << "\n";
    return 0;
}
