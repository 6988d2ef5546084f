#pragma once
// What the fighter is told: how it aims (latched or predicted, which part of the user), what an order asks for, and
// its settings (rate, distance band, blends, waits, variety, defence). Values only: the fighter (fighter.h) reads them.

#include "kumite/core/body_map.h"
#include "kumite/core/strike_labels.h"
#include "kumite/runtime/defence.h"
#include "kumite/runtime/head_motion_filter.h"
#include "kumite/runtime/user_guard.h"
#include "kumite/runtime/user_response.h"

#include <optional>
#include <string_view>

namespace kumite {

// Where a strike aims: the head as it was at the order (the paper), or where it will be at the strike's contact,
// extrapolated from its filtered velocity (a user who keeps walking is hit; one who stops, turns or ducks is not).
enum class FighterAim { latched, predicted };
const char* fighter_aim_name(FighterAim aim);
std::optional<FighterAim> fighter_aim_from_name(std::string_view name);

// The point of the user a strike aims at. The head first; when no strike reaches it (a short fighter, a tall
// user), the highest of chin, chest and solar plexus one does: points below the head by the user's proportions
// (0.10, 0.30 and 0.45 m under a 1.65 m head, scaled by the head's height), moving with the head.
enum class TargetPart { head, chin, chest, solar_plexus };
const char* target_part_name(TargetPart part);

// What the supervisor asks for: a semantics (Retriever::semantics_id) and, optionally, the side, kind and height
// (none: any). An order the database cannot serve is refused, not replaced by another strike.
struct StrikeOrder {
    int semantics = -1;
    Side side = Side::none;
    StrikeKind kind = StrikeKind::none;
    StrikeHeight height = StrikeHeight::none;
    int combination = -1; // a blow of this combination (combinations()), else -1
    int blow = 0;         // which: 0 the first; a later one begins as the one before it ends, from its recoil
    bool own = false;     // the fighter's own attack (BoutOptions::attacks), not the supervisor's order
};

struct FighterSettings {
    double rate_hz = 60.0;
    double hit_radius_m = 0.12;      // a strike hits when the effector is this close to the head at contact
    double tracker_timeout_s = 0.5;
    double hold_s = 1.0;
    double near_legs = 0.5;          // the distance band to the user (horizontal, from the pelvis) where strikes
    double far_legs = 1.05;          // reach, in leg lengths; the far end comes closer when the arms cannot reach
                                     // the head from there (a short fighter, a tall user): see strike_reach_m().
                                     // Nearer than half a leg the bodies touch (a clinch): the fighter steps back
                                     // before it strikes (it struck from 0.35 until 2026-11-29, and blows landed on it there)
    double close_near_legs = 0.35;   // ... unless no strike reaches from the band (an elbow, a knee) or the arms reach
                                     // the head from nowhere (a chibi, a tall user): then from this near
    double landing_in_band = 0.7;    // steps are shortened (feet locked) to land this far from near to far
    // The fighting distance kept between strikes: just out of reach, from rest_near_legs (at least the
    // strike band's far end) to rest_far_legs leg lengths, pelvis to head on the floor; the fighter steps in to
    // strike and out after. Off: it rests in the strike band, as the paper's fighter does.
    bool keep_distance = true;
    double rest_near_legs = 0.8;
    double rest_far_legs = 1.2;
    // Out after a strike: with no order waiting, a strike that leaves
    // the fighter inside the fighting distance recovers stepping back out to it (the step begun with the recovery,
    // the recovery's speeds while it lasts) instead of guarding where it struck until it has rested. Off: it
    // recovers where it stands and steps out from its guard.
    bool step_out_after_strikes = true;
    // A user who rushes in is evaded: one nearer than this (leg lengths, pelvis to head on the floor)
    // while the fighter steps or recovers from a strike makes it step back at once, not when its step or guard
    // loop ends (resting, it steps out of the fighting distance as soon as it is crowded anyway); with an order
    // waiting, only one nearer than the band its strike starts from. Against the recorded opponents, the blows that
    // landed on it came at a median 0.37 m (those it blocked: 0.58 m). 0: it steps back only where a clip ends.
    double crowd_legs = 0.6;
    // A strike ends this long after its contact as shown (the impact and its recoil, k_pace_back_s of the
    // strike's clock back to the clip's pace and a little more): the fighter recovers to its guard from where its
    // limbs are, at human speed, instead of playing out the capture's own way back (a kata's clip goes on 0.3-0.6 s
    // into the performer's next stance). Only a recovery may slip, block with either arm, step out or evade a user
    // who rushes in: against the recorded opponents 15% fewer blows landed (nine distances, three order timings),
    // most of them in the kata's long follow-throughs. 0: every strike's clip played to its end.
    double strike_follow_s = 0.15;
    double min_step_scale = 0.15;    // the shortest step, as a fraction of the clip's
    // A step is sized for where the user's head will be when it lands: its horizontal velocity along the line to
    // the fighter over the step clip's length, while the head keeps a settled course at a walking pace
    // (`lead_walk_mps`, the slowest walk of a user walking the room at 0.6-1.0 m/s; a user walking away at
    // 0.7 m/s is a step clip's second, 0.7 m, further by then; a boxer bobbing back and forth is not followed ahead).
    // On by default since 2026-11-30: recorded walkers' orders performed 96.4% instead of 89.8% and hit on 86.4% of
    // strikes instead of 78.5%, the recorded fighters unchanged (blows landed 318 against 312, hits 90.5 / 90.6%);
    // simulated walkers, whose random legs turn in one frame, are hit less (1145 strikes hit against 1181 over seeds
    // 1-3: a step sized for a course that then turns lands too far). Led from 0.3 m/s (until then the only setting):
    // the held-out SNU boxer's strikes hit 83.2% (85.3% not led).
    bool steps_lead_user = true;
    double lead_walk_mps = 0.6;
    double blend_s = 0.2;
    double recover_s = 0.3;
    double start_x_m = 0.0;          // where the fighter starts on the floor: x, facing +Z (side by side)
    FighterAim aim = FighterAim::latched;
    HeadMotionSettings head_motion;  // the filter behind predicted aim
    bool reach_fallback = true;      // aim lower on the body when the head is out of reach (else strike at the head)
    double reach_tolerance_m = 0.05; // a strike reaches a point when its adaptation gets the hit point this close
    // A strike meets the user's surface: the point aimed at (the tracked head's centre, or a point under it) is moved
    // this far towards the fighter on the floor plane. 0: at the centre, inside the head.
    double surface_depth_m = 0.08;
    DefenceSettings defence;         // blocks and slips against the user's tracked hands (defence.h)
    UserGuardSettings user_guard;    // the user's gloves and forearms in the way of the fighter's strikes (user_guard.h)
    ResponseSettings response;       // how the user's answers to the fighter's blows are told (user_response.h)
    // With predicted aim, the fighter keeps its eyes on the head during a strike: every frame until this long
    // before the contact it aims again at where the head will be at the contact (the adaptation carries the hit
    // point there); the last `steer_until_s` fly on as they are, as a person's punch does once it is too late to
    // correct it (visual feedback takes ~0.15 s). 0 or less: the target stays as planned (no steering).
    double steer_until_s = 0.15;
    // An order that comes while the fighter strikes, recovers, defends or has an order under way waits this long
    // and is carried out as soon as the fighter can; a later one takes its place (the earlier expires), and one
    // that waits too long expires. 0: refused at once ("already striking"), as the paper's fighter does.
    double order_wait_s = 1.5;
    double wait_for_reach_s = 1.5;   // an order no strike reaches waits this long for the fighter to step in (the
                                     // target stays latched), then strikes at the head anyway
    // Variety: when the best strike for an order is one of the last `variety_recent` clips struck, the best other
    // clip is taken instead if its score is within `variety_margin` of the best (score units: leg lengths of pose
    // and target distance). 0 recent: always the best.
    int variety_recent = 6; // with ~40 clips per order, 6 keeps twenty same orders on at least six clips
    double variety_margin = 0.15;
    // Strikes at a real strike's speed: a punch or kick whose clip arrives at its contact slower than a
    // real one meets its target (punch_speed_mps, kick_speed_mps: the speeds real strikes land at; the kata's
    // punches are captured at 2-4 m/s) is played faster up to the contact, at most `max_speedup` times its captured
    // speed (then as captured: the impact, the recovery). 1: every strike as captured. Its joints stay human with
    // human_speed on (the speed limit holds what goes over the library's fastest).
    double punch_speed_mps = 5.0;
    // Kicks aimed at 7 m/s (the library's front kicks land at 7-9.5): a kick's contact as shown comes slower than its
    // clip's contact frame (the kata's side kick, 40% of the kicks ordered, captured at 6 m/s lands at 5-6), and aimed
    // at 6 the median kick landed at 5.9-6.2 m/s once strikes ended after their recoil (strike_follow_s).
    double kick_speed_mps = 7.0;
    double max_speedup = 1.6;
    // Human speed: no joint shown faster than the library's fastest for its kind of move (speed_limit.h);
    // a part that asks for more is shown lagging. Off until the defence reads punches early enough to block at that
    // speed (runtime/README.md, "Human speed").
    bool human_speed = false;
    // Blocks at human speed with human_speed off: the blocking arm alone held to the library's block
    // speeds (a synthesized block seen late moved its wrist at up to 24 m/s); the rest of the body as asked.
    bool human_speed_blocks = true;
    // No wrist or ankle shown faster than a person's (k_human_extremity_mps, 12 m/s) with human_speed off:
    // a strike captured faster, or sped up towards a real one's speed with its offset added, lags and lands later
    // (its speed at contact at most that); a turn or lunge that carries a hand too fast holds the whole pose.
    bool human_extremities = true;
    // Every move at human speed with human_speed off: every joint held to the library's fastest for its
    // kind of move — steps, the guard, blocks, slips, recoveries, hit reactions, and the limbs a strike leaves free;
    // the striking limb as human_speed_strikes says. Off: only the blocking arm (human_speed_blocks).
    bool human_speed_but_strikes = true;
    // With human_speed_but_strikes, the striking limb too: its elbow or knee held to the library's
    // fastest for the kind of strike, like every other joint. An adapted punch whose target asks for the arm's last
    // centimetres of reach straightened the elbow in the contact's frame (60-80 rad/s; the library's punches reach
    // 26 on the scout): held, the fist trails the pose asked for, and the strike goes on at its own pace while it
    // trails by at most strike_lag_share of hit_radius_m — further behind, the strike waits for it (its clock held
    // back, as with human_speed, where punches land at 4 m/s). Off: the striking limb's elbow or knee free, its
    // wrist or ankle held to a person's (human_extremities).
    bool human_speed_strikes = true;
    double strike_lag_share = 0.5;
    // Hit reactions: a user strike that lands on the head or chest moves the fighter's head and trunk the
    // way it pushes, from the database's captured hit reactions (hit_reactions.h), blended in over
    // `reaction_blend_s`, then back to the guard. A strike under way is played out first. The blend is as long as the
    // others: over 0.1 s the feet slid onto the clip's stance at 6-9 m/s (the library's reactions move them at 2.4).
    bool hit_reactions = true;
    double reaction_blend_s = 0.2;
};
inline constexpr int k_max_variety_recent = 8;

} // namespace kumite
