#pragma once
// The fighter (ARCHITECTURE.md step 7): a character that guards, steps to keep the user in striking range while
// facing them, strikes on order at the head as it was when the order came (latched; or, with predicted aim, where
// the head will be at the contact), tells a hit from a miss by where the head is at the contact frame, and blocks
// or slips the user's own strikes. It owns its workspace and steps at a fixed rate; after construction a step
// allocates nothing. Several fighters can run side by side, one object each.
//
// States: rest (the guard clip, looped, re-aimed at the user at each loop) -> approach (a step clip towards the
// distance band where strikes reach, then rest) -> strike (on order, from rest or approach) -> recover (blend back
// into the guard) -> rest; from any of them, hit_reaction (a user strike landed: a captured reaction played) ->
// recover. Without a head for `tracker_timeout_s` it holds still, after `hold_s` returns to rest, and
// stays there until a head comes back. Every transition blends in MIR space over `blend_s`; all motion goes through
// the MIR, so `set_character` switches skeleton at any time, mid-strike included.
//
// The fighter is made of parts, each with its own state (runtime/README.md, "The fighter's parts"): the tracked
// user, the order queue, the footwork, the motion player, the strike planner, the strike, the defence, the body.
// step() calls them in the order of a frame.

#include "kumite/core/strike_adaptation.h"
#include "kumite/runtime/block_clips.h"
#include "kumite/runtime/defence.h"
#include "kumite/runtime/fighter_event.h"
#include "kumite/runtime/fighter_settings.h"
#include "kumite/runtime/joint_speeds.h"
#include "kumite/runtime/simulated_hands.h"
#include "kumite/runtime/user_guard.h"

#include <memory>
#include <span>
#include <vector>

namespace kumite {

class Fighter {
public:
    // `characters` must outlive the fighter; the first is the starting one. `library_speeds`: the library's speeds
    // on each character (measure_library_speeds; the speed limit's bars), shared by fighters; none: measured here.
    Fighter(const MotionDatabaseView& database, const Retriever& retriever, std::vector<CharacterRig*> characters,
            FighterSettings settings = {}, std::shared_ptr<const LibrarySpeeds> library_speeds = nullptr);
    ~Fighter();
    Fighter(const Fighter&) = delete;
    Fighter& operator=(const Fighter&) = delete;

    // An order, taken at the next step, or queued while the fighter is busy (FighterSettings::order_wait_s).
    // Returns false when it is refused at once (a semantics, side, kind or height the database lacks; busy with no
    // wait allowed); the reason is also an event. An order the fighter cannot carry out when its turn comes (the
    // tracker has no head, nothing fits) is refused then, with an event.
    bool order(const StrikeOrder& order);
    bool order(int semantics, Side side) { return order(StrikeOrder{semantics, side}); }
    void set_character(int index);
    void set_aim(FighterAim aim) { m_settings.aim = aim; } // from the next strike on
    FighterAim aim() const { return m_settings.aim; }
    void set_defence(bool enabled);
    // Its reaction: the delay after its defence sees a blow before it moves, and the share of blows it defends.
    void set_reaction(double reaction_delay_s, double defend_share);
    bool defence_enabled() const;
    const Defence& defence() const;
    const UserGuard& user_guard() const; // the user's guard as this frame's strikes meet it (when user_guard.enabled)

    // One frame at time t (seconds). `head`: the user's head this frame, or null when the tracker has none;
    // `hands`: the user's tracked hands, if any.
    void step(double t_s, const Eigen::Vector3d* head, const UserHands* hands = nullptr);

    FighterState state() const { return m_state; }
    bool has_waiting_order() const; // taken or queued, not yet ended
    // Planning budget (planning_budget.h): whether the next step would plan a strike (an order taken, at rest or
    // approaching, not defending, a head to aim at), whether that plan is a retry (the order waits for reach), when
    // the order came; and whether this step may plan (default: yes). A fighter that may not keeps its guard and its
    // order, and plans on a later step. `parts`: how many target parts (head, chin, chest, solar plexus) the first
    // look at an order may try in the step (a busy frame's budget grants 1: one retrieval and one set-up).
    bool wants_to_plan() const;
    bool plan_is_retry() const;
    double order_since_s() const;
    void set_may_plan(bool may_plan, int parts = 4);
    bool may_plan() const;
    int character() const;
    const Pose& pose() const;                                // on the current character
    // The speed limit (human speed): frames it held back, per MoveKind, and the furthest a wrist or ankle lagged.
    const std::array<long long, k_move_kind_count>& held_back_frames() const;
    double held_back_lag_m() const;
    // The pose shown, in the MIR (to record it on any skeleton): a block's or slip's edits included.
    const MirFrame& mir() const;
    std::span<const Eigen::Vector3d> positions() const;      // model positions of pose()
    std::span<const Eigen::Quaterniond> rotations() const;   // model rotations of pose()
    Eigen::Vector3d part_position(BodyPart part) const;      // of a body part of the current character, world
    HeadingFrame heading() const;
    bool has_latched_target() const { return m_state == FighterState::strike; }
    const Eigen::Vector3d& latched_target() const { return strike_plan().target_world; }
    int strike_clip() const { return strike_plan().clip; }
    const StrikePlan& strike_plan() const; // valid while striking
    double leg_length() const; // of the current character
    // How far from the pelvis (horizontally, metres) the arms reach the user's head from the current pose: the
    // shoulder's lead plus what 90% of the arm spans at the head's height above the shoulder, plus a lean of
    // 0.1 leg lengths. When the head is beyond the arms (a kid against an adult), the same at the highest body
    // point under it that they reach (reach_fallback); zero when none.
    double strike_reach_m() const;

    std::span<const FighterEvent> events() const;
    void clear_events();

private:
    struct Parts;
    void begin(double t_s);                               // the first step: the guard, shown at once
    void track(double t_s, const Eigen::Vector3d* head); // the head: lost (hold) or back (rest); without it no order
    void defend(double t_s);                              // the user's strikes seen, a block or slip started
    void take_blow(double t_s);                           // a user strike that landed: the hit reaction (a strike
                                                          // under way is played out first)
    void serve_orders(double t_s);                        // the queue: a waiting order taken when the fighter is free
    void plan(double t_s);                                // the pending order's strike, when the fighter may plan
    void play_strike(double t_s);                         // the strike's frame; its end starts the recovery
    void move(double t_s);                                // hold, recover, guard and steps
    void watch_responses(double t_s);                     // the user's answers to the blows (user_response events)
    void show(double t_s);                                // the frame's pose held to human speed, its heading
    void keep_fists_off_gloves();                         // this frame's pose: no fist inside a glove of the user's
    void enter(FighterState state, double t_s);
    bool busy() const; // striking, recovering, defending or with an order under way: new orders wait

    FighterSettings m_settings;
    std::unique_ptr<Parts> m_parts;
    FighterState m_state = FighterState::rest;
    double m_state_since_s = 0.0;
    double m_now_s = 0.0;
    double m_previous_step_s = -1.0; // the step before this one (< 0: none yet)
    bool m_started = false;
    bool m_blow_pending = false;     // a user strike landed and its hit reaction has not begun
    UserStrikeEvent m_blow;          // ... the strike (the last, when several landed meanwhile)
    int m_blows = 0;                 // ... how many landed
    double m_blow_s = 0.0;           // ... when it landed
};

} // namespace kumite
