// The table of the fighters' settings (play_settings.h): each setting's name is its field's path in BoutOptions
// (without `fighter.`), written once by the macro so that a name cannot point at another field.

#include "play_settings.h"

#include <array>
#include <string_view>

namespace kumite::cli {

namespace {

constexpr const char* setting_name(const char* path) {
    return std::string_view(path).starts_with("fighter.") ? path + 8 : path;
}

#define KUMITE_SETTING(path, group, min, max, unit, help) \
    Setting{setting_name(#path), group, min, max, unit, help, [](BoutOptions& o) -> SettingField { return &o.path; }}

constexpr const char* k_strikes = "strikes";
constexpr const char* k_distance = "distance and steps";
constexpr const char* k_speed = "human speed";
constexpr const char* k_defence = "defence";
constexpr const char* k_reactions = "hit reactions";
constexpr const char* k_orders = "orders, tracking and crowds";
constexpr const char* k_attacks = "its own attacks (free sparring)";
constexpr const char* k_filter = "the head filter behind predicted aim";
constexpr const char* k_guard = "the user's guard";

const auto k_settings = std::to_array<Setting>({
    KUMITE_SETTING(fighter.aim, k_strikes, 0, 0, "",
                   "where a strike aims: latched (the head where it was at the order) or predicted (where it will be at the "
                   "contact if it keeps its course); also --aim, the command 'aim latched|predicted', the viewer's A key"),
    KUMITE_SETTING(lead_s, k_strikes, 0, 5, "s", "a strike starts at least this long before its contact (a sparring partner telegraphs)"),
    KUMITE_SETTING(contact_extension, k_strikes, 0.5, 1, "",
                   "a strike makes contact where its hit point has covered this share of its way to the annotated hit, still "
                   "travelling (1: at the annotated hit, full extension)"),
    KUMITE_SETTING(contact_speed_share, k_strikes, 0, 1, "",
                   "... or earlier, before the hit point first slows under this share of its top speed on the way (0: by extension alone)"),
    KUMITE_SETTING(fighter.punch_speed_mps, k_strikes, 0.5, 20, "m/s",
                   "a punch whose clip arrives slower than this is played faster until its contact, up to max_speedup (real punches land at about 5)"),
    KUMITE_SETTING(fighter.kick_speed_mps, k_strikes, 0.5, 25, "m/s", "the same for kicks (the library's front kicks land at 7-9.5)"),
    KUMITE_SETTING(fighter.max_speedup, k_strikes, 1, 1.9, "times the captured speed",
                   "how much faster than captured a strike may be played until its contact (1: every strike at its captured speed)"),
    KUMITE_SETTING(fighter.hit_radius_m, k_strikes, 0.01, 1, "m", "a strike hits when its hit point is this close to the point aimed at, at its contact"),
    KUMITE_SETTING(fighter.surface_depth_m, k_strikes, 0, 0.3, "m",
                   "the point aimed at is moved this far from the tracked head's centre towards the fighter, to the surface (0: the centre)"),
    KUMITE_SETTING(fighter.reach_fallback, k_strikes, 0, 0, "",
                   "when no strike reaches the head, aim at the highest of chin, chest and solar plexus that one reaches (false: the head anyway)"),
    KUMITE_SETTING(fighter.reach_tolerance_m, k_strikes, 0, 1, "m", "a strike reaches a point when its adaptation brings the hit point this close"),
    KUMITE_SETTING(fighter.steer_until_s, k_strikes, 0, 5, "s", "predicted aim: a strike follows the head until this long before its contact (0: never steers)"),
    KUMITE_SETTING(fighter.strike_follow_s, k_strikes, 0, 5, "s",
                   "a strike ends this long after its contact (the impact and recoil), then the limbs come back to the guard at human speed "
                   "(0: every strike's captured clip is played to its end)"),
    KUMITE_SETTING(fighter.variety_recent, k_strikes, 0, k_max_variety_recent, "strikes",
                   "prefer a clip not used in this many last strikes when one scores within variety_margin of the best (0: always the best)"),
    KUMITE_SETTING(fighter.variety_margin, k_strikes, 0, 10, "", "... within this much (score units: leg lengths of pose and target distance)"),
    KUMITE_SETTING(fighter.blend_s, k_strikes, 0, 2, "s", "a new motion is blended in over this long"),
    KUMITE_SETTING(fighter.recover_s, k_strikes, 0, 5, "s", "after a strike, the fighter recovers this long before it rests"),

    KUMITE_SETTING(fighter.near_legs, k_distance, 0, 3, "leg lengths",
                   "the near end of the band strikes are thrown from (the fighter's pelvis to the user's head, on the floor)"),
    KUMITE_SETTING(fighter.far_legs, k_distance, 0.1, 5, "leg lengths", "its far end (nearer when the arms cannot reach the head from there)"),
    KUMITE_SETTING(fighter.close_near_legs, k_distance, 0, 3, "leg lengths",
                   "the near end instead when no strike reaches from the band (an elbow, a knee) or the arms reach the head from nowhere"),
    KUMITE_SETTING(fighter.landing_in_band, k_distance, 0, 1, "", "steps are shortened to land this far into the band, from its near end (0) to its far end (1)"),
    KUMITE_SETTING(fighter.keep_distance, k_distance, 0, 0, "",
                   "between strikes the fighter rests just out of reach and steps in to strike (false: it rests where its strikes reach, as the paper's)"),
    KUMITE_SETTING(fighter.rest_near_legs, k_distance, 0, 5, "leg lengths", "the fighting distance kept between strikes: from this (at least far_legs) ..."),
    KUMITE_SETTING(fighter.rest_far_legs, k_distance, 0, 5, "leg lengths", "... to this"),
    KUMITE_SETTING(fighter.step_out_after_strikes, k_distance, 0, 0, "",
                   "with no order waiting, a strike that leaves the fighter inside the fighting distance recovers stepping back out "
                   "(false: it recovers where it stands, then steps out)"),
    KUMITE_SETTING(fighter.crowd_legs, k_distance, 0, 3, "leg lengths",
                   "a user who comes nearer than this while the fighter steps or recovers makes it step back at once (0: only where its clip ends)"),
    KUMITE_SETTING(fighter.min_step_scale, k_distance, 0.01, 1, "", "the shortest step, as a share of its clip's"),
    KUMITE_SETTING(fighter.steps_lead_user, k_distance, 0, 0, "",
                   "a step is sized for where a walking user's head will be when it lands (false: where the head is)"),
    KUMITE_SETTING(fighter.lead_walk_mps, k_distance, 0, 5, "m/s", "... for a user on a settled course at this speed or more"),

    KUMITE_SETTING(fighter.human_speed, k_speed, 0, 0, "",
                   "every joint, the striking limb's too, held to the library's fastest for its kind of move; a strike that asks for more waits for it"),
    KUMITE_SETTING(fighter.human_speed_but_strikes, k_speed, 0, 0, "",
                   "steps, the guard, blocks, slips, recoveries, hit reactions and the limbs a strike leaves free held to the library's fastest "
                   "for their kind (the striking limb: human_speed_strikes)"),
    KUMITE_SETTING(fighter.human_speed_strikes, k_speed, 0, 0, "",
                   "with human_speed_but_strikes, the striking limb's elbow or knee held too (false: free, its wrist or ankle held by human_extremities)"),
    KUMITE_SETTING(fighter.strike_lag_share, k_speed, 0, 10, "",
                   "a held strike goes on at its pace while its hit point trails the pose asked for by at most this share of hit_radius_m; further, it waits"),
    KUMITE_SETTING(fighter.human_speed_blocks, k_speed, 0, 0, "",
                   "with human_speed_but_strikes false, the blocking arm alone held to the library's block speeds (false too: blocks as fast as asked)"),
    KUMITE_SETTING(fighter.human_extremities, k_speed, 0, 0, "",
                   "no wrist or ankle faster than a person's 12 m/s (a strike that asks for more lags and lands later)"),

    KUMITE_SETTING(fighter.defence.enabled, k_defence, 0, 0, "",
                   "the fighter blocks and slips the user's strikes (also --no-defence, the command 'defence on|off', the viewer's D key)"),
    KUMITE_SETTING(fighter.defence.reaction_delay_s, k_defence, 0, 2, "s",
                   "the fighter's reaction time: a move begins this long after the blow is seen (0: at once, faster than a person, "
                   "who needs 0.15-0.25 s; --difficulty sets it)"),
    KUMITE_SETTING(fighter.defence.defend_share, k_defence, 0, 1, "", "the share of the blows seen that the fighter defends at all (--difficulty sets it)"),
    KUMITE_SETTING(fighter.defence.horizon_s, k_defence, 0, 5, "s", "a hand arriving within this long is a threat"),
    KUMITE_SETTING(fighter.defence.min_speed_mps, k_defence, 0, 50, "m/s", "slower hands are not strikes"),
    KUMITE_SETTING(fighter.defence.threat_radius_m, k_defence, 0, 2, "m", "a threat's course passes at most this far from the head or chest"),
    KUMITE_SETTING(fighter.defence.head_radius_m, k_defence, 0, 1, "m", "a hand whose path comes this close to the head hits it"),
    KUMITE_SETTING(fighter.defence.chest_radius_m, k_defence, 0, 1, "m", "a hand whose path comes this close to the chest hits it"),
    KUMITE_SETTING(fighter.defence.block_contact_m, k_defence, 0, 1, "m", "a hand whose path comes this close to the blocking forearm is blocked"),
    KUMITE_SETTING(fighter.defence.block_before_m, k_defence, 0, 2, "m", "the forearm meets the hand's path this far before its target"),
    KUMITE_SETTING(fighter.defence.max_block_speed_mps, k_defence, 0, 100, "m/s", "a block that would need a faster wrist move is not tried: a slip instead"),
    KUMITE_SETTING(fighter.defence.max_block_wrist_mps, k_defence, 0, 100, "m/s",
                   "a synthesized block never moves the wrist faster than this (what cannot arrive in time arrives late)"),
    KUMITE_SETTING(fighter.defence.slip_m, k_defence, 0, 1, "m", "a slip leans the head this far off the blow's line"),
    KUMITE_SETTING(fighter.defence.max_hand_speed_mps, k_defence, 0, 100, "m/s", "a tracked hand faster than this between samples jumped (a glitch): a new track"),
    KUMITE_SETTING(fighter.defence.contact_speed_mps, k_defence, 0, 50, "m/s", "a hand meeting the head or chest at least this fast is a strike that arrived"),
    KUMITE_SETTING(fighter.defence.hold_s, k_defence, 0, 5, "s", "a block or slip is held this long after the hand's expected arrival ..."),
    KUMITE_SETTING(fighter.defence.release_s, k_defence, 0, 5, "s", "... then goes back to the guard over this long"),
    KUMITE_SETTING(fighter.defence.hand_over_blocks, k_defence, 0, 0, "",
                   "a block whose blow is over gives way to the next blow of a combination (false: one move at a time, held and released)"),
    KUMITE_SETTING(fighter.defence.slip_in_hit_reaction, k_defence, 0, 0, "",
                   "rocked by a blow, the fighter may still slip the next, never leaning past the trunk's limit (false: only its arms cover)"),
    KUMITE_SETTING(fighter.defence.reaim_min_speed_mps, k_defence, 0, 50, "m/s", "a block's meeting point follows the fist's course while the fist travels at least this fast"),
    KUMITE_SETTING(fighter.defence.keep_guard, k_defence, 0, 0, "",
                   "while striking, the free arm stays where the guard had it (false: as its clip moves it; a kata's punch pulls it to the hip)"),
    KUMITE_SETTING(fighter.defence.captured_blocks, k_defence, 0, 0, "",
                   "block punches with the database's captured blocks where one fits (false: every block synthesized from the guard)"),
    KUMITE_SETTING(fighter.defence.block_clip_span_m, k_defence, 0, 1, "m",
                   "a captured block meets the course from just outside the hit radius to this much further out"),
    KUMITE_SETTING(fighter.defence.block_clip_max_speed_ratio, k_defence, 0, 100, "times the clip's speed",
                   "over 0: a captured block moves the arm at most this many times as fast as its clip (0: no limit)"),
    KUMITE_SETTING(fighter.defence.block_clip_reach, k_defence, 0, 10, "arm lengths",
                   "a captured block whose forearm would have to move further than this to meet the course is not used"),

    KUMITE_SETTING(fighter.hit_reactions, k_reactions, 0, 0, "", "a user strike that lands moves the fighter the way it pushed (a captured hit reaction)"),
    KUMITE_SETTING(fighter.reaction_blend_s, k_reactions, 0, 2, "s", "a hit reaction is blended in over this long"),

    KUMITE_SETTING(attacks.on_its_own, k_attacks, 0, 0, "",
                   "the fighter attacks without orders (free sparring; also --spar): a supervisor's order still comes first"),
    KUMITE_SETTING(attacks.tempo_s, k_attacks, 0.3, 60, "s", "on its own, an attack this often on average (0.6 to 1.4 times it; --difficulty sets it)"),
    KUMITE_SETTING(attacks.combination_share, k_attacks, 0, 1, "",
                   "on its own, this share of its attacks are combinations: one-two, jab-hook, jab-body-head (--difficulty sets it)"),
    KUMITE_SETTING(attacks.kick_share, k_attacks, 0, 1, "", "on its own, this share of its single blows are kicks, the rest punches"),

    KUMITE_SETTING(fighter.order_wait_s, k_orders, 0, 60, "s",
                   "an order that comes while the fighter is busy waits this long, a later one taking its place (0: refused at once)"),
    KUMITE_SETTING(fighter.wait_for_reach_s, k_orders, 0, 60, "s",
                   "an order no strike reaches waits this long for the fighter to step in, then strikes at the head anyway"),
    KUMITE_SETTING(fighter.tracker_timeout_s, k_orders, 0.01, 60, "s", "the user is lost when the tracker has given nothing for this long"),
    KUMITE_SETTING(fighter.hold_s, k_orders, 0, 60, "s", "a fighter that lost the user holds its pose this long, then guards"),
    KUMITE_SETTING(plans_per_frame, k_orders, 0, 100000, "fighters",
                   "at most this many fighters plan a strike in one frame, the others on the next frames (0: no limit)"),

    KUMITE_SETTING(fighter.user_guard.enabled, k_guard, 0, 0, "",
                   "the user's gloves and forearms stop a strike whose path meets them before the head or trunk: it stops there, "
                   "blocked (false: the head alone decides, at the contact)"),
    KUMITE_SETTING(fighter.user_guard.aim_at_openings, k_guard, 0, 0, "",
                   "an order that leaves the height open aims at the highest part (head, chin, chest, solar plexus) whose strike the "
                   "guard as it is would not meet first (with user_guard.enabled; it lands more and is hit more: docs/design.md)"),
    KUMITE_SETTING(fighter.user_guard.glove_radius_m, k_guard, 0, 0.5, "m", "a glove: a sphere this big around the tracked hand point"),
    KUMITE_SETTING(fighter.user_guard.forearm_radius_m, k_guard, 0, 0.5, "m", "a forearm: a capsule this thick from the wrist back to the elbow"),
    KUMITE_SETTING(fighter.user_guard.head_radius_m, k_guard, 0, 0.5, "m", "the user's head: a sphere this big around the tracked head"),
    KUMITE_SETTING(fighter.user_guard.trunk_radius_m, k_guard, 0, 0.5, "m", "the user's trunk: a capsule this thick from the chest to the belly"),
    KUMITE_SETTING(fighter.user_guard.striking_radius_m, k_guard, 0, 0.5, "m", "the fighter's fist, foot, knee or elbow: a sphere this big"),
    KUMITE_SETTING(fighter.user_guard.knuckles_past_wrist_m, k_guard, 0, 0.5, "m",
                   "the fist's (or foot's) centre lies this far past the wrist (ankle) along the forearm (shin)"),

    KUMITE_SETTING(fighter.head_motion.alpha, k_filter, 0, 1, "", "the position gain per sample"),
    KUMITE_SETTING(fighter.head_motion.beta, k_filter, 0, 1, "", "the velocity gain per sample"),
    KUMITE_SETTING(fighter.head_motion.settled_mps, k_filter, 0, 10, "m/s", "the course is settled while the prediction residuals stay under this speed"),
    KUMITE_SETTING(fighter.head_motion.max_speed_mps, k_filter, 0, 20, "m/s", "faster estimates are scaled down to this"),
    KUMITE_SETTING(fighter.head_motion.max_horizon_s, k_filter, 0, 10, "s", "predictions further ahead are cut there"),
    KUMITE_SETTING(fighter.head_motion.gap_reset_s, k_filter, 0, 10, "s", "samples further apart than this restart the filter"),
});

#undef KUMITE_SETTING

} // namespace

std::span<const Setting> play_settings() { return k_settings; }

const Setting* play_setting_named(std::string_view name) {
    for (const Setting& setting : k_settings) {
        if (name == setting.name) return &setting;
    }
    return nullptr;
}

} // namespace kumite::cli
