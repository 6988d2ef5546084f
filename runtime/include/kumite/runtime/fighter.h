#pragma once
// The fighter (ARCHITECTURE.md step 7): a character that guards, steps to keep the user in striking range while
// facing them, strikes on order at the head as it was when the order came (the target is latched; or, with
// predicted aim, where the head will be at the strike's contact if it keeps its course), and tells a
// hit from a miss by where the head is at the contact frame. A strike whose target the head is still at when it
// lands stops there (impact); one the user has dodged follows through, a visible miss. It owns its workspace and steps at a fixed rate; after
// construction a step allocates nothing. Several fighters can run side by side, one object each.
//
// States: rest (the database's guard clip, looped, re-aimed at the user at each loop) -> approach (one step clip
// towards the distance band where strikes reach, then rest) -> strike (on order, from rest or approach; orders
// during a strike or its recovery are ignored and reported) -> recover (blend back into the guard) -> rest. When
// the tracker has given no head for `tracker_timeout_s` the fighter holds still, after `hold_s` returns to rest,
// and stays there until a head comes back. Every transition blends in MIR space over `blend_s`.
//
// All motion goes through the MIR, so `set_character` switches skeleton at any time, mid-strike included: the
// strike carries on, decoded on the new character.

#include "kumite/core/strike_adaptation.h"
#include "kumite/runtime/block_clips.h"
#include "kumite/runtime/defence.h"
#include "kumite/runtime/head_motion_filter.h"
#include "kumite/runtime/simulated_hands.h"

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace kumite {

enum class FighterState { rest, approach, strike, recover, hold };
const char* fighter_state_name(FighterState state);

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
};

struct FighterSettings {
    double rate_hz = 60.0;
    double hit_radius_m = 0.12;      // a strike hits when the effector is this close to the head at contact
    double tracker_timeout_s = 0.5;
    double hold_s = 1.0;
    double near_legs = 0.35;         // the distance band to the user (horizontal, from the pelvis) where strikes
    double far_legs = 1.05;          // reach, in leg lengths; the far end comes closer when the arms cannot reach
                                     // the head from there (a short fighter, a tall user): see strike_reach_m()
    double landing_in_band = 0.7;    // steps are shortened (feet locked) to land this far from near to far
    double min_step_scale = 0.15;    // the shortest step, as a fraction of the clip's
    double blend_s = 0.2;
    double recover_s = 0.3;
    double start_x_m = 0.0;          // where the fighter starts on the floor: x, facing +Z (side by side)
    FighterAim aim = FighterAim::latched;
    HeadMotionSettings head_motion;  // the filter behind predicted aim
    bool reach_fallback = true;      // aim lower on the body when the head is out of reach (else strike at the head)
    double reach_tolerance_m = 0.05; // a strike reaches a point when its adaptation gets the hit point this close
    DefenceSettings defence;         // blocks and slips against the user's tracked hands (defence.h)
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
};
inline constexpr int k_max_variety_recent = 8;

struct FighterEvent {
    // Every order ends once, as order_performed (its strike began), ignored_order (refused, with why) or
    // order_expired (it waited order_wait_s, or a later order took its place); it starts as order (taken at once)
    // or order_queued (waiting).
    enum class Type { order, ignored_order, state, strike, strike_end, tracker_lost, tracker_back, character, user_strike, user_strike_end,
                      order_queued, order_performed, order_expired };
    Type type = Type::state;
    double t_s = 0.0;
    FighterState state = FighterState::rest; // state events: the new state
    int semantics = -1;                      // order and strike events
    Side side = Side::none;
    StrikeKind kind = StrikeKind::none;      // order and strike events: what the order asked for (none: any)
    StrikeHeight height = StrikeHeight::none;
    bool varied = false;                     // strike events: not the best clip, to vary from the last strikes
    int clip = -1;                           // strike events
    bool hit = false;
    double contact_error_m = 0.0;            // effector to the latched target at contact
    double head_distance_m = 0.0;            // effector to the head at contact
    double range_m = 0.0;                    // strike events: pelvis to head on the floor when the strike began
    double effector_speed_mps = 0.0;         // strike events: the hit point's speed arriving at the contact
    bool impact = true;                      // strike and strike_end events: the head was still at the target at
                                             // the contact, so the strike stops there; false: it follows through
    double overshoot_m = 0.0;                // strike_end events: the farthest past the target after the contact
    int joint_limit_violations = 0;          // strike_end events: joints out of limits, summed over the frames
    FighterAim aim = FighterAim::latched;    // strike events: how the target was chosen
    Eigen::Vector3d target = Eigen::Vector3d::Zero(); // strike events: the target aimed at, world
    double head_speed_mps = 0.0;             // strike events: the head's filtered speed when the strike began
    double prediction_error_m = 0.0;         // strike events: the head at the contact to the target aimed at
    std::optional<Eigen::Vector3d> aimed_point_at_contact; // strike events: where the part aimed at was at the contact
                                                           // (world; none without a head then)
    double retrieval_offset_m = 0.0;         // strike events: the chosen clip's natural hit point to the target
    double steered_m = 0.0;                  // strike events: how far steering moved the target since the start
    TargetPart target_part = TargetPart::head; // strike events: the part aimed at
    bool reachable = true;                   // strike events: the adaptation gets the hit point to the target
    UserStrikeEvent user_strike;             // user_strike (seen, the move chosen) and user_strike_end (outcome; its
                                             // joint_limit_violations and foot_shift_m: what the defence did)
    double foot_shift_m = 0.0;
    int character = -1;                      // character events
    const char* why = "";                    // ignored and expired orders
    double waited_s = 0.0;                   // order_performed and order_expired: since the order came
};
const char* fighter_event_name(FighterEvent::Type type);

class Fighter {
public:
    // `characters` must outlive the fighter; the first is the starting one.
    Fighter(const MotionDatabaseView& database, const Retriever& retriever, std::vector<CharacterRig*> characters,
            FighterSettings settings = {});
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
    void set_defence(bool enabled) { m_defence.settings().enabled = enabled; }
    bool defence_enabled() const { return m_defence.enabled(); }
    const Defence& defence() const { return m_defence; }

    // One frame at time t (seconds). `head`: the user's head this frame, or null when the tracker has none;
    // `hands`: the user's tracked hands, if any.
    void step(double t_s, const Eigen::Vector3d* head, const UserHands* hands = nullptr);

    FighterState state() const { return m_state; }
    bool has_waiting_order() const { return m_pending || m_queued; } // taken or queued, not yet ended
    // Planning budget (planning_budget.h): whether the next step would plan a strike (an order taken, at rest or
    // approaching, not defending, a head to aim at), whether that plan is a retry (the order waits for reach), when
    // the order came; and whether this step may plan (default: yes). A fighter that may not keeps its guard and its
    // order, and plans on a later step.
    bool wants_to_plan() const;
    bool plan_is_retry() const { return m_pending && (m_pending_tried || m_pending_part > 0); }
    double order_since_s() const { return m_pending ? m_pending_since_s : m_queued_since_s; }
    // `parts`: how many target parts (head, chin, chest, solar plexus) the first look at an order may try in the
    // step (a busy frame's budget grants 1: each plan is then one retrieval and one set-up).
    void set_may_plan(bool may_plan, int parts = 4) { m_may_plan = may_plan, m_plan_parts = parts; }
    bool may_plan() const { return m_may_plan; }
    int character() const { return m_character; }
    const Pose& pose() const { return m_pose; }              // on the current character
    // The pose shown, in the MIR (to record it on any skeleton): a block's or slip's edits included.
    const MirFrame& mir() const { return m_defence_shown ? m_shown_mir : m_mir; }
    std::span<const Eigen::Vector3d> positions() const;      // model positions of pose()
    std::span<const Eigen::Quaterniond> rotations() const;   // model rotations of pose()
    Eigen::Vector3d part_position(BodyPart part) const;      // of a body part of the current character, world
    HeadingFrame heading() const { return m_heading; }
    bool has_latched_target() const { return m_state == FighterState::strike; }
    const Eigen::Vector3d& latched_target() const { return m_plan.target_world; }
    int strike_clip() const { return m_plan.clip; }
    const StrikePlan& strike_plan() const { return m_plan; } // valid while striking
    double leg_length() const; // of the current character
    // How far from the pelvis (horizontally, metres) the arms reach the user's head from the current pose: the
    // shoulder's lead plus what 90% of the arm spans at the head's height above the shoulder, plus a lean of
    // 0.1 leg lengths. When the head is beyond the arms (a kid against an adult), the same at the highest body
    // point under it that they reach (reach_fallback); zero when none.
    double strike_reach_m() const;

    std::span<const FighterEvent> events() const { return {m_events.data(), std::size_t(m_event_count)}; }
    void clear_events() { m_event_count = 0; }

private:
    struct Body;
    void push_event(const FighterEvent& event);
    void emit_ignored(double t_s, const char* why); // the pending order, ignored
    void emit_order_event(FighterEvent::Type type, const StrikeOrder& order, double since_s, const char* why = "");
    static FighterEvent order_event(FighterEvent::Type type, double t_s, const StrikeOrder& order); // with what it asked for
    bool busy() const; // striking, recovering, defending or with an order under way: new orders wait
    void take_order(const StrikeOrder& order); // becomes the pending order, from now
    void serve_queue(double t_s);              // the waiting order: taken when the fighter can, or expired
    void enter(FighterState state, double t_s);
    void start_clip(int clip, double t_s, bool face_user, double step_scale = 1.0);
    void lock_feet(double t_s, int pose); // foot locking for shortened steps
    double clip_stride_m(int clip) const; // how far a clip moves the hips, on the current character
    void play_clip(double t_s);
    void start_strike(double t_s);
    void begin_strike(); // the current body's adapter on m_plan, from m_strike_start
    void play_strike(double t_s);
    void steer_strike(double to_contact_s); // predicted aim: the target follows the head until steer_until_s before the contact
    FighterEvent strike_event(FighterEvent::Type type, double t_s) const; // a strike or strike_end event of the strike
    void finish_frame();
    void defend(double t_s);        // follows the user's hands, starts and ends moves, emits their events
    void apply_defence();           // decodes the shown pose again with the move's edits (when one is on)
    // A block just started: a captured one instead when one fits (block_clips.h).
    void start_block_clip(const RestAnatomy& anatomy, const DefenderBody& defender);
    bool order_fits(const StrikeOrder& order, const char*& why) const;
    // A retrieval that prefers a clip not struck lately (FighterSettings::variety_recent); `varied` tells if it did.
    RetrievalResult query_with_variety(RetrievalQuery& query, bool& varied);
    void remember_strike(int clip);
    HeadingFrame heading_towards_user() const;
    double distance_to_user() const; // horizontal, pelvis to head
    double band_far_m() const;       // the far end of the distance band where strikes reach
    // The point the strike aims at, where the user has it now (the head, or the body point under it).
    Eigen::Vector3d aimed_point_now() const { return m_head - Eigen::Vector3d(0.0, m_strike_drop_m, 0.0); }
    // The strike for the pending order at the point `drop_m` under the head, where aim asks for (as it is, or as
    // it will be at the contact); the target used in `target`.
    RetrievalResult retrieve_strike(RetrievalQuery& query, double drop_m, Eigen::Vector3d& target);
    // Plans the strike and begins its adaptation: how far from the target the hit point stops at the contact.
    double plan_strike(const RetrievalResult& found, const Eigen::Vector3d& target);

    MotionDatabaseView m_db;
    const Retriever& m_retriever;
    FighterSettings m_settings;
    std::vector<std::unique_ptr<Body>> m_bodies;
    int m_character = 0;
    int m_guard_clip = -1;
    std::array<int, 4> m_step_clips{-1, -1, -1, -1}; // forward, back, left, right

    FighterState m_state = FighterState::rest;
    double m_state_since_s = 0.0;
    double m_now_s = 0.0;
    double m_previous_step_s = -1.0; // the step before this one (< 0: none yet)
    bool m_started = false;
    // the head
    bool m_have_head = false;
    bool m_tracking = false;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero();
    double m_last_head_s = -1e9;
    HeadMotionFilter m_head_motion;
    UserHands m_hands;                   // this frame's
    Defence m_defence;
    BlockClips m_block_clips;            // the database's captured blocks
    BlockClipChoice m_block_choice;      // the one being played (block_clip moves)
    Eigen::Vector3d m_block_last_wrist = Eigen::Vector3d::Zero(), m_block_last_elbow = Eigen::Vector3d::Zero(); // relative to the shoulder
    double m_block_last_s = -1.0;        // when they were measured; < 0: not yet in this block
    bool m_block_measure_from_shown = false; // a block started last frame: measured from the pose shown then
    bool m_block_lagging = false;        // the arm was held back to its clip's speed last frame: not where the blend put it
    double m_block_played = 0.0;         // clip frames of the captured block played since its start frame
    double m_block_played_s = 0.0;       // when
    MirFrame m_defended_frame;           // scratch: the shown frame with the defence's edits
    MirFrame m_shown_mir;                // the pose shown with the defence's edits, encoded again (mir())
    bool m_defence_shown = false;        // this frame's pose carries the defence's edits
    LimbPins m_defence_pins;
    int m_defence_violations = 0;        // joint-limit violations of the defence's edits, since the last user strike ended
    double m_defence_foot_shift_m = 0.0; // how far they moved a foot, since then
    // orders
    bool m_pending = false;
    StrikeOrder m_pending_order;
    double m_pending_since_s = 0.0;
    Eigen::Vector3d m_pending_head = Eigen::Vector3d::Zero(); // the head at the order (latched aim)
    bool m_pending_tried = false; // every part was looked at once: the order waits for reach
    double m_pending_ordered_s = 0.0; // when the supervisor gave it (earlier than m_pending_since_s if it waited)
    bool m_may_plan = true;       // the planning budget lets this step plan a strike
    int m_plan_parts = 4;         // ... looking at this many target parts at most
    bool m_queued = false;        // an order waiting while the fighter is busy
    StrikeOrder m_queued_order;
    double m_queued_since_s = 0.0;
    int m_pending_part = 0;       // the part to look at next while waiting
    // the clip being played (rest, approach, recover)
    int m_clip = -1;
    double m_clip_start_s = 0.0;
    FloorAlignment m_clip_to_world;
    double m_clip_scale = 1.0;                   // horizontal scale of the clip's hip path (shortened steps)
    Eigen::Vector3d m_clip_hip_start = Eigen::Vector3d::Zero();
    std::array<bool, 2> m_foot_pinned{};         // [left, right]
    std::array<Eigen::Vector3d, 2> m_foot_pin{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> m_foot_release_offset{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<double, 2> m_foot_release_s{-1e9, -1e9};
    LimbPins m_pins;
    MirFrame m_blend_from;
    double m_blend_start_s = -1e9;
    // the strike
    StrikePlan m_plan;
    MirFrame m_strike_start;
    double m_strike_start_s = 0.0;
    bool m_contact_done = false;
    StrikeOrder m_strike_order;
    bool m_strike_varied = false;
    bool m_pending_varied = false;               // the planned strike's retrieval took a varied clip
    std::array<int, k_max_variety_recent> m_recent_clips{}; // the clips of the last strikes, newest at m_recent_next - 1
    int m_recent_count = 0;
    int m_recent_next = 0;
    double m_strike_range_m = 0.0;
    double m_strike_overshoot_m = 0.0;
    int m_strike_violations = 0;
    bool m_strike_impact = true;
    FighterAim m_strike_aim = FighterAim::latched;
    double m_strike_head_speed_mps = 0.0;
    double m_strike_offset_m = 0.0;
    double m_strike_drop_m = 0.0;            // the aimed point under the head
    TargetPart m_strike_part = TargetPart::head;
    bool m_strike_reachable = true;
    Eigen::Vector3d m_planned_target = Eigen::Vector3d::Zero(); // the target when the strike began (before steering)
    Eigen::Vector3d m_previous_effector = Eigen::Vector3d::Zero();
    double m_previous_effector_s = 0.0;
    // output
    bool m_shown_by_adapter = false; // this frame's pose is the strike adapter's decode (not the body's decoder's)
    MirFrame m_clip_frame, m_next_frame, m_mir;
    Pose m_pose;
    HeadingFrame m_heading;
    std::array<float, k_feature_dimensions> m_feature{};
    RetrievalWorkspace m_workspace;
    std::array<FighterEvent, 64> m_events;
    int m_event_count = 0;
};

} // namespace kumite
