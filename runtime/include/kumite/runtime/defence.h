#pragma once
// Defence against the user's own strikes (the paper's future work: "react to kicks and punches of the user").
// Every frame the user's tracked hands are followed (a smoothed velocity); a hand whose straight course passes
// within `threat_radius_m` of the fighter's head or chest within `horizon_s` starts a user strike. A fighter at
// rest or approaching then defends:
//   block — the forearm on the side the hand comes from is moved onto the hand's predicted path, a third of a metre
//           before the target, when the wrist can get there in time at a plausible speed: a captured block
//           (`block_clip`: the fighter retrieves and plays one, block_clips.h) when one fits, else `synthesized`
//           (the arm's extremity driven by a world offset, as a strike drives its hit point: two-bone IK with the
//           guard's swivel);
//   slip  — otherwise the trunk leans the head (and chest) off the hand's line, turning above the spine's base.
// Each user strike ends as `blocked` (the hand's path this frame met a forearm of the fighter: the blocking one, or
// the other held in the guard), `hit_by_user` (it met the head or chest), `slipped` (it went back without either
// while the fighter slipped) or `missed` (without either, and no slip). A hand that meets the head or chest (or a
// forearm on the way) without having been seen coming is a user strike too, `detected` false: it is counted, not
// defended. Nothing here allocates.

#include "kumite/core/heading_frame.h"
#include "kumite/runtime/simulated_hands.h"

#include <algorithm>
#include <array>
#include <span>

namespace kumite {

enum class DefenceMove { none, synthesized, block_clip, slip };
inline bool is_block(DefenceMove move) { return move == DefenceMove::synthesized || move == DefenceMove::block_clip; }
enum class UserStrikeOutcome { blocked, slipped, hit_by_user, missed };
const char* defence_move_name(DefenceMove move);
const char* user_strike_outcome_name(UserStrikeOutcome outcome);

struct DefenceSettings {
    bool enabled = true;
    double horizon_s = 0.5;          // a hand arriving within this long is a threat
    double min_speed_mps = 2.5;       // slower hands are not strikes
    double threat_radius_m = 0.3;    // how close its course must pass to the head or chest
    double head_radius_m = 0.12;      // a hand this close to the head (its path this frame) hits it
    double chest_radius_m = 0.16;
    double block_contact_m = 0.05;    // a hand path this close to the blocking forearm is blocked
    double block_before_m = 0.3;      // where the forearm meets the path: this far before the target
    double max_block_speed_mps = 8.0; // faster wrist moves are not plausible: slip instead
    // A synthesized block's ramp is never so short that its wrist would move faster than this at its fastest (the
    // smoothstep's: 1.5 times its mean), on top of what the body does (no wrist over 12 m/s; the ramp
    // of 0.6 of the time left, started again shorter when the fist turned out faster, moved it at up to 24 m/s).
    // It takes what is left before the fist gets there instead; what cannot arrive in time arrives late.
    double max_block_wrist_mps = 12.0;
    double slip_m = 0.3;              // how far the head leans off the line
    double max_hand_speed_mps = 15.0; // a hand that moves faster between samples jumped (a glitch): a new track
    double contact_speed_mps = 2.0;   // a hand meeting the head or chest at least this fast is a strike that arrived
    double hold_s = 0.2;              // the move held after the hand's expected arrival
    double release_s = 0.3;           // back to the guard
    // A block whose strike is over (blocked, or past) gives way to the next threat instead of being held and released
    // first: a combination's next blow, 0.2-0.5 s later, gets a move too (the arm goes on from where it is shown, at
    // the speeds the fighter's limbs are held to). Off: one move at a time, each held and released (0.5 s) before the
    // next (21 of 45 blows that landed at 1.2 m against the recorded opponents came unanswered while a
    // move for an earlier one was still on). A slip is not handed over: the trunk would snap back.
    bool hand_over_blocks = true;
    // Rocked by a blow, the fighter may still slip the next one: the lean goes on top of the hit reaction's (never
    // past the trunk's limit: a slip leans no further than the trunk may still turn). Off: in a hit reaction only the
    // arms may cover (37 of 94 blows that would land during reactions landed against the recorded opponents).
    bool slip_in_hit_reaction = true;
    // A block's meeting point follows the fist's course, known better each frame, while the fist still travels at
    // least this fast (a kata's punch closes at 2.5-3 m/s and slows before it arrives: followed only while over the
    // 2.5 m/s that makes it a strike, the forearm stayed where its first course pointed).
    double reaim_min_speed_mps = 1.0;
    // Blocks from the database's block clips when one fits (else all synthesized). Off by default: blended in over
    // the little time a fist leaves, the arm moves about twice as fast as in the captured clip (docs/design.md, "Blocks").
    bool captured_blocks = false;
    double block_clip_span_m = 0.15;  // a captured block meets the course between just outside the hit radius (the
                                      // radius and block_contact_m) and this much further out, where its forearm passes
    double block_clip_max_speed_ratio = 0.0; // > 0: a captured block never moves the arm (wrist or elbow, relative to the
                                             // shoulder) faster than this times its clip does; where the fist leaves too
                                             // little time the forearm arrives late (the punch lands, or meets the guard)
    double block_clip_reach = 0.5;    // a captured block whose forearm would have to be moved further (arm lengths) to
                                      // meet the course is another movement: the synthesized block instead
    // While the fighter strikes, the arms the strike leaves free stay where the guard had them from the head (issue
    // 44: "a guard whose forearms are already near the paths punches take"; a kata's punch pulls its other hand to
    // the hip and 35 of 72 blows that landed came during the fighter's own strikes, seen 0-0.1 s before). A blow
    // whose path meets that forearm is blocked. Off: the strike's clip moves them as captured.
    bool keep_guard = true;
    // A person's defence is not instant: the move begins this long after the blow is seen (0: at once, faster than
    // a person, who needs 0.15-0.25 s from a visible cue), when the blow is still coming; the time it then has left
    // is what the move gets.
    double reaction_delay_s = 0.0;
    // The share of the blows seen that the fighter defends at all (1: every one), spread evenly over the bout.
    double defend_share = 1.0;
};

// The fighter's body as the defence sees it (world metres, last frame): arms [left, right].
struct DefenderBody {
    Eigen::Vector3d head = Eigen::Vector3d::Zero(), chest = Eigen::Vector3d::Zero();
    std::array<Eigen::Vector3d, 2> elbow{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> wrist{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> shoulder{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<double, 2> arm_length{0.6, 0.6}; // shoulder to wrist, stretched
    HeadingFrame heading;
};

struct UserStrikeEvent {
    bool ended = false;              // false: the strike was seen (move chosen); true: its outcome
    double t_s = 0.0;
    int hand = 0;                    // the user's 0 left, 1 right
    bool at_head = true;             // what its course was aimed at
    DefenceMove move = DefenceMove::none;
    int arm = 0;                     // blocking arm of the fighter: 0 left, 1 right
    double time_to_impact_s = 0.0;
    double hand_speed_mps = 0.0;
    UserStrikeOutcome outcome = UserStrikeOutcome::missed;
    double forearm_to_path_m = -1.0; // ended blocks: the closest the hand's path came to the blocking forearm
    bool detected = true;            // false: it arrived without having been seen coming (counted, not defended)
    int blocking_arm = -1;           // blocked: the forearm that met it (0 left, 1 right)
    int block_clip = -1;             // block_clip: the database clip played
    // Ended blocks: the fastest the blocking wrist or elbow moved relative to its shoulder (what a captured block's
    // speed limit compares with the clip's own, clip_arm_from_shoulder_mps), and the fastest the wrist and the elbow
    // moved in the world (what the motion meter measures: wrist_mps, elbow_mps).
    double arm_from_shoulder_mps = -1.0;
    double clip_arm_from_shoulder_mps = -1.0; // block_clip: the captured clip's own, on this arm
    double wrist_mps = -1.0, elbow_mps = -1.0;
    Eigen::Vector3d hand_velocity = Eigen::Vector3d::Zero(); // ended: the hand's velocity then (world, m/s): how a blow that landed pushes
    // Slipped: how far outside the hit radius the hand's path passed where the part it was aimed at would have been
    // without the lean (the head by the slip's offset as shown, the chest by half of it); <= 0: the slip is what kept
    // it off, > 0: it would have missed anyway (a slip is started for any course within threat_radius_m).
    double unslipped_clearance_m = 1e9;
    // Blocked: how far outside the hit radius of the head or chest the hand passed after the forearm met it (nothing
    // stops a tracked hand at a virtual forearm: its path goes on, and is followed until it draws back, for 0.3 s at
    // most), or its straight course would have, for half a metre: <= 0: the block kept it off, > 0: it would have
    // missed anyway (a forearm held in the guard also stops hands that pass wide). Told by an event of its own once
    // the path has been followed (`course_followed`: not `ended`, the outcome `blocked`, the time then).
    double unblocked_clearance_m = 1e9;
    bool course_followed = false;
    double moved_s = -1.0;           // when the fighter's move for it began (-1: none; reaction_delay_s after it was seen)
    double move_after_seen_s = -1.0; // ... how long after it was seen (-1: none)
    bool defended = true;            // chosen to be defended (defend_share)
    // Ended: the fastest the hand moved from being seen to its end (unseen: at its arrival), m/s.
    double peak_speed_mps = 0.0;
    // Ended, blocked or hit_by_user: how long the hand had been closing on what it met (the head or the chest, at
    // >= 0.5 m/s) before it met it: the warning its motion gave (a person needs about 0.2 s from there to
    // begin a move). The defence sees it later, once it is fast and on course (`user_strike`'s time).
    double approach_s = -1.0;
};

// The distance between segments [a0, a1] and [b0, b1].
double segment_distance(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& b0, const Eigen::Vector3d& b1);

class Defence {
public:
    explicit Defence(DefenceSettings settings = {}) : m_settings(settings) {}
    DefenceSettings& settings() { return m_settings; }
    const DefenceSettings& settings() const { return m_settings; }
    bool enabled() const { return m_settings.enabled; }

    // One frame: the user's hands, the fighter's body, which moves may start: blocks with which arms ([left,
    // right]; an arm that strikes cannot block), and the slip (not while a strike drives the trunk).
    struct Allowed {
        std::array<bool, 2> block_arms{true, true};
        bool slip = true;
        bool any() const { return block_arms[0] || block_arms[1] || slip; }
    };
    void update(double t_s, const UserHands& hands, const DefenderBody& body, const Allowed& allowed);
    void update(double t_s, const UserHands& hands, const DefenderBody& body, bool can_start) {
        update(t_s, hands, body, can_start ? Allowed{} : Allowed{{false, false}, false});
    }
    void reset(); // tracking lost, a character switch: forget hands and moves
    void cancel_move(); // a blow landed: the move stops (the hands are still followed)

    bool active() const { return m_move != DefenceMove::none; } // a move is on (orders wait)
    // This frame's edits: the block's arm, weight and wrist target; the slip's weight and head offset.
    DefenceMove move() const { return m_move; }
    int block_arm() const { return m_arm; }
    double block_weight() const { return is_block(m_move) ? m_weight : 0.0; }
    // A block started this frame (synthesized until use_block_clip says otherwise), the strike it answers, when it
    // started and how long until the forearm meets the fist's course.
    bool block_started() const { return m_block_started; }
    const UserStrikeEvent& move_strike() const { return m_hands[std::max(0, m_move_hand)].strike; }
    double move_start_s() const { return m_move_start_s; }
    double intercept_s() const { return m_intercept_s; }
    // The block that started is a captured one: its clip, the clip's own arm speed, the blend in and where it meets
    // the course (this far before the target).
    void use_block_clip(int clip, double clip_arm_from_shoulder_mps, double ramp_s, double before_m);
    // Where the course of the strike the move answers is `before_m` short of its target, and when (from now).
    bool course_point(double before_m, Eigen::Vector3d& point, double& time_s) const;
    // How long the fist still needs to the block's meeting point (block_wrist_target), along its course now; 0 once past.
    double time_to_block_point() const;
    // The strike the move answers is over (blocked, landed, gone back): what is left is the hold and the release.
    bool move_strike_over() const { return m_move_hand < 0 || !m_hands[m_move_hand].striking; }
    // The blocking arm's speed this frame (relative to its shoulder), for the block's event.
    void note_arm_speed(double from_shoulder_mps, double wrist_mps, double elbow_mps);
    const Eigen::Vector3d& block_wrist_target() const { return m_wrist_target; }
    double slip_weight() const { return m_move == DefenceMove::slip ? m_weight : 0.0; }
    const Eigen::Vector3d& slip_offset() const { return m_slip_offset; } // full lean, world, horizontal

    std::span<const UserStrikeEvent> events() const { return {m_events.data(), std::size_t(m_event_count)}; }
    void clear_events() { m_event_count = 0; }

private:
    struct Hand {
        bool seen = false;
        Eigen::Vector3d position = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
        double last_s = 0.0;
        bool striking = false;       // a user strike of this hand is under way
        bool armed = true;           // a new strike may start (after one ends: once the hand has slowed down)
        UserStrikeEvent strike;
        double closest_forearm_m = 1e9;
        int receding_frames = 0;
        bool touching = false;       // met the fighter unseen, and has not left it since
        // Since when the hand has been closing on the head [0] and the chest [1] (UserStrikeEvent::approach_s); < 0: not.
        std::array<double, 2> closing_since_s{-1.0, -1.0};
        double peak_speed_mps = 0.0; // of the strike under way
        double move_due_s = -1.0;    // reaction_delay_s: when the move for this strike begins (-1: none waiting)
        // A blocked strike whose path is followed on (unblocked_clearance_m) before its end is told.
        bool watching = false;
        UserStrikeEvent watched;
        int watch_receding_frames = 0;
    };
    // Whether the next blow seen is defended (defend_share, spread evenly: a golden-ratio sequence).
    bool defends_next();
    // A move waiting for the reaction delay, begun when it is due and the blow still comes.
    void start_due_move(double t_s, Hand& hand, const DefenderBody& body, const Allowed& allowed);
    // The forearm (0 left, 1 right) the hand's path from `before` to `now` meets, or -1.
    int forearm_met(const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body) const;
    // How far outside the head's [0] and the chest's [1] hit radius the segment passes; <= 0: it meets that part.
    std::array<double, 2> part_clearances(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const;
    // How far outside the head's or chest's hit radius (the nearer) the segment passes; <= 0: it meets one.
    double body_clearance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const;
    // Which the segment passes nearer, outside its hit radius: the head (0) or the chest (1).
    int met_part(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const DefenderBody& body) const;
    // Whether the path meets the head or the chest.
    bool body_met(const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body) const;
    // How far outside the head's or chest's hit radius a course from `from` along `velocity` passes (UserStrikeEvent::
    // unblocked_clearance_m).
    double course_clearance(const Eigen::Vector3d& from, const Eigen::Vector3d& velocity, const DefenderBody& body) const;
    // A block whose strike has ended, which a new threat may take over (DefenceSettings::hand_over_blocks).
    bool block_is_over() const;
    // A blocked strike's path after the forearm: followed, then its end told.
    void watch_blocked(double t_s, Hand& hand, const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body);
    void end_watch(Hand& hand);
    void push(const UserStrikeEvent& event);
    void start_move(double t_s, Hand& hand, const DefenderBody& body, double time_to_impact, const Allowed& allowed);
    // Where the blocking wrist should go to meet the hand's course in time, and with which arm (the one on the side
    // it comes from first, else the other, among `arms`); false when none can get there at a plausible speed. The
    // meeting is block_before_m short of the target, or (`nearer`) half that when the first is out of reach or
    // too soon; `meeting_s`: how long until the fist gets there.
    bool block_plan(const Hand& hand, const DefenderBody& body, double time_to_impact, const std::array<bool, 2>& arms,
                    Eigen::Vector3d& wrist_target, int& arm, double& meeting_s, bool nearer = true) const;
    void end_strike(double t_s, Hand& hand, UserStrikeOutcome outcome);
    // The hand's closing on the head and the chest over its path this frame (Hand::closing_since_s).
    static void follow_closing(Hand& hand, double before_s, const Eigen::Vector3d& before, const Eigen::Vector3d& now, double dt_s, const DefenderBody& body);
    // How long the hand had been closing on the head (`part` 0) or the chest (1) at t_s (-1: it was not).
    static double approach_time(const Hand& hand, double t_s, int part);
    double ramp_weight(double t_s) const; // the move's weight at t_s while it ramps in
    double shortest_ramp_s(double travel_m) const; // a ramp over `travel_m` at max_block_wrist_mps at its fastest

    DefenceSettings m_settings;
    std::array<Hand, 2> m_hands;
    DefenceMove m_move = DefenceMove::none;
    int m_move_hand = -1;
    int m_arm = 0;
    double m_weight = 0.0;
    double m_move_start_s = 0.0, m_ramp_s = 0.1, m_hold_until_s = 0.0, m_intercept_s = 0.0;
    // The ramp in: from weight m_ramp_from to 1 over m_ramp_s from m_ramp_start_s (started again, shorter, when the
    // fist turns out faster than first seen).
    double m_ramp_start_s = 0.0, m_ramp_from = 0.0;
    bool m_block_started = false;
    double m_block_before_m = 0.3;   // the move's meeting point before the target
    double m_time_to_impact_s = 0.0; // at the move's start
    double m_block_travel_m = 0.0;   // how far the blocking wrist goes, from the guard to the meeting point
    Eigen::Vector3d m_wrist_target = Eigen::Vector3d::Zero(), m_slip_offset = Eigen::Vector3d::Zero();
    std::array<UserStrikeEvent, 8> m_events;
    int m_event_count = 0;
    long long m_threats = 0; // blows seen: which of them are defended (defend_share)
};

} // namespace kumite
