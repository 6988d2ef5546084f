// What `kumite play` writes about a bout: its events as JSON lines (with the lines that frame the bout and sample
// the room for the session report), its report, and the user's recording.

#include "play_output.h"

#include "kumite/runtime/bout_event_json.h"
#include "kumite/runtime/combinations.h"

#include <algorithm>
#include <cmath>

namespace kumite::cli {

namespace {

nlohmann::json summary_of(const ValueHistogram& values) {
    return {{"mean", values.mean()}, {"p99", values.quantile(0.99)}, {"max", values.max()}};
}

// Median, p95 and max (the strike figures of the reports).
nlohmann::json quantiles_of(const ValueHistogram& values) {
    return {{"median", values.quantile(0.5)}, {"p95", values.quantile(0.95)}, {"max", values.max()}, {"count", values.count()}};
}

// Per kind of strike that was struck: punch, kick, knee, elbow.
nlohmann::json contact_speed_by_kind(const BoutCounters& counters) {
    nlohmann::json by_kind = nlohmann::json::object();
    for (int k = 0; k < 4; ++k) {
        const ValueHistogram& speeds = counters.contact_speed_by_kind_mps[std::size_t(k)];
        if (!speeds.empty()) by_kind[move_kind_name(MoveKind(int(MoveKind::punch) + k))] = quantiles_of(speeds);
    }
    return by_kind;
}

// The user's answers to the fighter's blows, per kind of strike thrown.
nlohmann::json responses_by_kind(const BoutCounters& counters) {
    nlohmann::json by_kind = nlohmann::json::object();
    for (int k = 0; k < 4; ++k) {
        const BoutCounters::Responses& r = counters.responses_by_kind[std::size_t(k)];
        if (r.blows == 0) continue;
        nlohmann::json kinds = nlohmann::json::object(), quality = nlohmann::json::object();
        for (int i = 0; i < k_response_kind_count; ++i) kinds[response_kind_name(ResponseKind(i))] = r.kinds[std::size_t(i)];
        for (int i = 0; i < k_response_quality_count; ++i) quality[response_quality_name(ResponseQuality(i))] = r.quality[std::size_t(i)];
        by_kind[move_kind_name(MoveKind(int(MoveKind::punch) + k))] = {
            {"blows", r.blows}, {"moved", r.moved}, {"anticipated", r.anticipated}, {"response_time_s", quantiles_of(r.time_s)},
            {"kinds", kinds}, {"quality", quality}, {"countered", r.countered}, {"counters_landed", r.counters_landed}};
    }
    return by_kind;
}

const char* side_text(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "any"; }

nlohmann::json xyz(const Eigen::Vector3d& point) { return {point.x(), point.y(), point.z()}; }

} // namespace

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

void write_user_line(std::ostream& out, const Bout& bout) {
    if (!bout.head()) return;
    const Eigen::Vector3d& head = *bout.head();
    out << bout.now_s() << "," << head.x() << "," << head.y() << "," << head.z();
    const UserHands& hands = bout.hands();
    for (int side = 0; side < 2; ++side) {
        if (hands.present[side]) out << "," << hands.world[side].x() << "," << hands.world[side].y() << "," << hands.world[side].z();
        else out << ",nan,nan,nan";
    }
    // The elbows the user's guard used (tracked or estimated), when it is on and has the hand.
    const UserGuard& guard = bout.fighter(0).user_guard();
    for (int side = 0; side < 2; ++side) {
        const bool elbow = guard.settings().enabled && hands.present[side] && guard.hand(side);
        if (elbow) out << "," << guard.elbow(side).x() << "," << guard.elbow(side).y() << "," << guard.elbow(side).z();
        else out << ",nan,nan,nan";
    }
    out << "\n";
}

nlohmann::json play_event_json(const Bout& bout, const BoutEvent& bout_event) { return nlohmann::json::parse(bout_event_json(bout, bout_event)); }

// Orders still under way or queued when the bout ended (every other order ended performed, refused or expired).
static long long waiting_orders(const Bout& bout) {
    long long waiting = 0;
    for (int f = 0; f < bout.fighter_count(); ++f) waiting += bout.fighter(f).has_waiting_order();
    return waiting;
}

nlohmann::json play_report_json(const Bout& bout) {
    const BoutCounters& counters = bout.counters();
    // The user's strikes' outcomes, counted by UserStrikeOutcome, as {blocked, slipped, hit_by_user, missed}.
    auto outcomes_json = [](const std::array<long long, 4>& counts) {
        nlohmann::json outcomes;
        for (UserStrikeOutcome outcome : {UserStrikeOutcome::blocked, UserStrikeOutcome::slipped, UserStrikeOutcome::hit_by_user, UserStrikeOutcome::missed}) {
            outcomes[user_strike_outcome_name(outcome)] = counts[std::size_t(outcome)];
        }
        return outcomes;
    };
    const nlohmann::json by_target = {{"head", outcomes_json(counters.user_outcomes_by_target[0])},
                                      {"chest", outcomes_json(counters.user_outcomes_by_target[1])}};
    nlohmann::json by_fighter_state = nlohmann::json::object();
    for (int state = 0; state < k_fighter_state_count; ++state) {
        by_fighter_state[fighter_state_name(static_cast<FighterState>(state))] = outcomes_json(counters.user_outcomes_by_fighter_state[std::size_t(state)]);
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
    // Each combination's blows: thrown and landed, the first (it draws the guard) and the second (where it left).
    nlohmann::json by_combination = nlohmann::json::object();
    for (std::size_t c = 0; c < k_combination_count; ++c) {
        const auto& thrown = counters.combination_strikes[c];
        const auto& landed = counters.combination_hits[c];
        if (thrown[0] + thrown[1] == 0) continue;
        by_combination[combinations()[c].name] = {{"first", {{"strikes", thrown[0]}, {"hits", landed[0]}}},
                                                  {"second", {{"strikes", thrown[1]}, {"hits", landed[1]}}}};
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
            {"blocked_by_user", counters.blocked_by_user},
            {"own_attacks", counters.own_attacks},
            {"combinations", by_combination},
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
            {"held_at_target_s", quantiles_of(counters.impact_held_s)},
            {"effector_speed_at_contact_mps", quantiles_of(counters.contact_speed_mps)},
            {"effector_speed_at_contact_by_kind_mps", contact_speed_by_kind(counters)},
            {"user_responses", responses_by_kind(counters)},
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
             {{"seen", counters.user_strikes}, {"blocks", counters.blocks}, {"block_clips", counters.block_clips},
              {"synthesized", counters.blocks - counters.block_clips}, {"slips", counters.slips}, {"blocked", counters.blocked},
              {"slipped", counters.slipped}, {"slipped_on_course", counters.slipped_on_course}, {"blocked_on_course", counters.blocked_on_course}, {"hit_by_user", counters.hit_by_user},
              {"missed", counters.user_missed},
              {"not_defended", counters.not_defended},
              {"move_after_seen_s", quantiles_of(counters.defence_move_after_seen_s)},
              {"forearm_to_path_m", quantiles_of(counters.forearm_to_path_m)},
              {"arm_from_shoulder_mps",
               {{"block_clip", quantiles_of(counters.block_clip_arm_from_shoulder_mps)}, {"synthesized", quantiles_of(counters.synthesized_arm_from_shoulder_mps)}}},
              {"block_clip_speed_ratio", quantiles_of(counters.block_clip_speed_ratio)},
              {"blocking_wrist_mps", quantiles_of(counters.blocking_wrist_mps)},
              {"blocking_elbow_mps", quantiles_of(counters.blocking_elbow_mps)},
              {"joint_limit_violations", counters.defence_joint_limit_violations},
              {"foot_shift_m", counters.defence_foot_shift_m},
              {"by_target", by_target},
              {"by_fighter_state", by_fighter_state}}},
            {"hit_reactions",
             {{"count", counters.hit_reactions}, {"captured", counters.captured_hit_reactions}, {"blows_answered", counters.hit_reaction_blows},
              {"angle_to_blow_deg", quantiles_of(counters.hit_reaction_angle_deg)}, {"delay_s", quantiles_of(counters.hit_reaction_delay_s)}}}};
}


nlohmann::json bout_start_json(const Bout& bout, const PlaySetup& setup) {
    nlohmann::json characters = nlohmann::json::array();
    for (int c = 0; c < bout.character_count(); ++c) characters.push_back(bout.character_name(c));
    nlohmann::json line = {{"t", 0.0},
                           {"type", "bout_start"},
                           {"fighters", bout.fighter_count()},
                           {"characters", characters},
                           {"character", bout.character_name(bout.fighter(0).character())},
                           {"aim", fighter_aim_name(bout.fighter(0).aim())},
                           {"defence", bout.fighter(0).defence_enabled()},
                           {"rate_hz", bout.rate_hz()},
                           {"tracker", setup.tracker},
                           {"database", setup.database},
                           {"seed", setup.seed},
                           {"sample_period_s", k_track_period_s}};
    // Which blocks answer the user's punches: captured ones (and their speed limit, when one is set) or synthesized.
    const DefenceSettings& defence = bout.fighter(0).defence().settings();
    line["blocks"] = defence.captured_blocks ? "captured" : "synthesized";
    if (defence.captured_blocks && defence.block_clip_max_speed_ratio > 0.0) line["block_speed_limit"] = defence.block_clip_max_speed_ratio;
    return line;
}

// Nothing measured on the wall clock: the events of a seeded headless bout are the same every run (frame times are
// in the report).
nlohmann::json bout_end_json(const Bout& bout) {
    const BoutCounters& counters = bout.counters();
    return {{"t", bout.now_s()},
            {"type", "bout_end"},
            {"frames", counters.frames},
            {"duration_s", double(counters.frames) / bout.rate_hz()},
            {"orders_waiting_at_end", waiting_orders(bout)},
            {"tracker_packets", bout.tracker().packets()},
            {"tracker_rejected", bout.tracker().rejected()}};
}

void RoomSampler::sample(const Bout& bout, std::vector<nlohmann::json>& lines) {
    const double t = bout.now_s();
    if (t + 1e-9 >= m_next_track_s) {
        m_next_track_s = t + k_track_period_s;
        if (bout.head()) lines.push_back({{"t", t}, {"type", "track"}, {"head", xyz(*bout.head())}});
    }
    m_last_position.resize(std::size_t(bout.fighter_count()), Eigen::Vector3d::Constant(std::nan("")));
    for (int f = 0; f < bout.fighter_count(); ++f) {
        // Where the fighter stands (its heading frame on the floor, set between clips), not the pelvis swaying in a
        // strike: the top view shows the steps.
        const HeadingFrame heading = bout.fighter(f).heading();
        Eigen::Vector3d& last = m_last_position[std::size_t(f)];
        if (!last.allFinite() || (heading.origin - last).norm() > k_position_step_m) {
            last = heading.origin;
            lines.push_back({{"t", t}, {"type", "fighter_position"}, {"fighter", f}, {"position", xyz(heading.origin)}, {"yaw_rad", heading.yaw_rad}});
        }
    }
}

std::optional<nlohmann::json> DrillPartWatch::changed(const Bout& bout) {
    const DrillRun* drill = bout.drill();
    if (!drill) return std::nullopt;
    const int part = drill->status(bout.now_s()).part;
    if (part < 0 || part == m_part) return std::nullopt;
    m_part = part;
    const DrillPart& info = drill->drill().parts[std::size_t(part)];
    const DrillRun::Part& span = drill->parts()[std::size_t(part)];
    return nlohmann::json{{"t", bout.now_s()}, {"type", "drill_part"}, {"part", part}, {"name", info.name}, {"difficulty", bout.difficulty()},
                          {"free_sparring", info.free_sparring}, {"attacks", span.attacks}, {"end_s", span.end_s}};
}

nlohmann::json drill_report_json(const Bout& bout) {
    const DrillRun& drill = *bout.drill();
    nlohmann::json parts = nlohmann::json::array();
    for (std::size_t p = 0; p < drill.parts().size(); ++p) {
        const DrillPart& info = drill.drill().parts[p];
        parts.push_back({{"name", info.name}, {"difficulty", info.difficulty.text.empty() ? nlohmann::json(nullptr) : nlohmann::json(info.difficulty.text)},
                         {"free_sparring", info.free_sparring}, {"attacks", drill.parts()[p].attacks}, {"start_s", drill.parts()[p].start_s},
                         {"end_s", drill.parts()[p].end_s}});
    }
    return {{"name", drill.drill().name}, {"duration_s", drill.duration_s()}, {"parts", parts}};
}

} // namespace kumite::cli
