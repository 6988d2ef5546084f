#pragma once
// The strike being played (fighter.h): planned on a retrieved clip and a target, adapted every frame (the hit point
// carried to the target, steered onto a moving head with predicted aim), its contact judged (a head still at the
// target takes the impact, a dodge is followed through), measured (overshoot, joint-limit violations, speed at the
// contact). Owns: the plan, the MIR frame it began from, its timing, what it was for, its measures. Touches: the
// body (the adapter's pose is shown) and the event log (strike, strike_end). Reads: the user (the head at the
// contact, its course for steering).

#include "fighter/character_body.h"
#include "fighter/event_log.h"
#include "fighter/tracked_user.h"

#include "kumite/core/retrieval.h"

namespace kumite {

// How much faster than captured a strike's hit point arrives at its contact (FighterSettings::max_speedup): the
// speed its clip's hit point has at the contact frame against the real strike's of its kind, at most max_speedup
// (under 2); 1 for other kinds and clips fast enough. The time to the contact stays the clip's (strike_clip_time).
double strike_speedup(const MotionDatabaseView& db, const FighterSettings& settings, int clip, int contact_frame);
// Where in the clip (seconds from its start frame) a strike is `clock_s` into it, for a contact `to_contact_s` into
// the clip played `speedup` times as fast at its contact: up to the contact time runs slower at first and faster at
// the end (clip time T w(t/T), w(u) = (2 - s) u + (s - 1) u^2: w(1) = 1, w'(0) = 2 - s, w'(1) = s), so the
// contact comes when it would as captured and the user has as long to see it coming; after it the clip's clock
// comes back to its own pace over 0.1 s.
double strike_clip_time(double clock_s, double to_contact_s, double speedup);

class Strike {
public:
    Strike(const MotionDatabaseView& db, const FighterSettings& settings);

    // The adaptation of `found` at `target`, begun from `from` on the body (the feet where its pose has them): how
    // far from the target the hit point stops. Planning tries several (target parts); the last one tried is played.
    double try_plan(const RetrievalResult& found, const Eigen::Vector3d& target, const MirFrame& from, CharacterBody& body);
    // What the strike planned last is for, as its events tell.
    struct Purpose {
        StrikeOrder order;
        bool varied = false;         // not the best clip, for variety
        TargetPart part = TargetPart::head;
        Eigen::Vector3d aim_offset = Eigen::Vector3d::Zero(); // the aimed point from the head: under it (the part), and
                                                              // towards the fighter to its surface (strike_aim.h)
        bool reachable = true;
        FighterAim aim = FighterAim::latched;
        double head_speed_mps = 0.0; // when it began
        double retrieval_offset_m = 0.0;
        double range_m = 0.0;        // pelvis to head on the floor when it began
    };
    void start(double t_s, const Purpose& purpose);
    // The strike carried on on another character (set_character): begun again there from the frame it began from.
    void carry_over(CharacterBody& body);

    // One frame: the adapted pose onto the body (its MIR frame encoded again), the contact judged (the impact taken
    // or followed through).
    void play(double t_s, CharacterBody& body, const TrackedUser& user);
    // The speed limit showed only `share` of this frame's step (human speed): the strike's own clock moves on by that
    // share of the frame, so the clip is played no faster than the body can follow it; a contact held back comes
    // again next frame (the strike lands later, at a person's speed, instead of short of its target).
    void held_back(double share);
    // The same frame as shown (after the defence's edits and the speed limit): the contact told from the hit point
    // shown (error, hit, speed), the time held at the target, the body's MIR frame encoded from the pose shown.
    void measure(double t_s, CharacterBody& body, const TrackedUser& user, EventLog& log);
    bool over() const { return m_over; } // the last frame was played: strike_end() and recover
    // When its contact was shown (measure()), or -1 before it.
    double contact_shown_s() const { return m_contact_shown_s; }
    void end(double t_s, EventLog& log);

    const StrikePlan& plan() const { return m_plan; }
    int segment() const; // the body part that strikes (the clip's)
    GuardPart user_block() const { return m_user_block; } // the user's glove or forearm that stopped it, or none
    MirFrame& start_frame() { return m_start_frame; } // (for sizing: CharacterBody)
    // The striking part's centre as shown (world): the fist or foot past the wrist or ankle along the lower bone, or
    // the elbow or knee itself.
    Eigen::Vector3d striking_point(const CharacterBody& body) const;
    // Whether the strike last planned, played to its contact against the user's guard as it is now, meets a glove or
    // forearm before the head or trunk (the adapter's frames into the body's pose: call it while planning).
    bool guard_in_the_way(CharacterBody& body, const UserGuard& guard);

private:
    void begin(CharacterBody& body); // the body's adapter on m_plan, from m_start_frame
    // The user's guard along the striking part's path this frame: a glove or forearm met before the head or trunk
    // stops the strike there (true: step the frame again, held at it); the part then pushes the stop back when it comes forward (follow_block).
    bool meet_guard(double index, CharacterBody& body, const TrackedUser& user);
    void follow_block(double index, CharacterBody& body, const TrackedUser& user);
    // The stop that keeps the striking part (its centre `striking`, the adapter's hit joint at `hit_joint`) out of
    // the part that blocked it.
    // How far the striking part is into the part that blocked it (negative: clear of it).
    double into_block(const CharacterBody& body, const TrackedUser& user) const;
    void hold_off_block(double index, StrikeAdapter& adapter, const Eigen::Vector3d& striking, const Eigen::Vector3d& hit_joint, const UserGuard& guard) const;
    void steer(double to_contact_s, CharacterBody& body, const TrackedUser& user);
    Eigen::Vector3d aimed_point(const TrackedUser& user) const { return user.head() + m_purpose.aim_offset; }
    FighterEvent event(FighterEvent::Type type, double t_s) const;

    const MotionDatabaseView& m_db;
    FighterSettings m_settings;      // a copy: the speedup's speeds
    double m_hit_radius_m, m_steer_until_s;
    double m_speedup = 1.0;          // how much faster than captured the hit point arrives (strike_speedup)
    StrikePlan m_plan;
    Purpose m_purpose;
    MirFrame m_start_frame;
    double m_start_s = 0.0;
    double m_clock_s = 0.0;          // the strike's own time since it began (slower than the bout's when held back);
                                     // the clip's time is strike_clip_time of it
    double m_clock_before_s = 0.0;   // ... at the frame before
    double m_last_play_s = 0.0;      // when play() last ran
    bool m_contact_done = false;
    double m_contact_shown_s = -1.0;
    bool m_contact_now = false;      // this frame is the contact (play() to measure())
    bool m_over = false;
    bool m_impact = true;
    double m_overshoot_m = 0.0;
    double m_held_s = 0.0;           // after the contact, within 1 cm of the target
    bool m_holding = false;          // ... still, this frame
    int m_violations = 0;
    Eigen::Vector3d m_planned_target = Eigen::Vector3d::Zero(); // when it began (before steering)
    Eigen::Vector3d m_previous_effector = Eigen::Vector3d::Zero();
    double m_previous_effector_s = 0.0;
    // The user's guard (FighterSettings::user_guard): the striking part's centre and hit joint last frame, whether
    // its path met the head or trunk (no block after that), and the part that blocked it, where, and where that
    // part was then.
    bool m_have_path = false;
    Eigen::Vector3d m_previous_striking_point = Eigen::Vector3d::Zero(), m_previous_hit_joint = Eigen::Vector3d::Zero();
    bool m_met_body = false;
    GuardPart m_user_block = GuardPart::none;
    Eigen::Vector3d m_block_stop = Eigen::Vector3d::Zero();     // the hit joint where the guard first stopped it
    Eigen::Vector3d m_block_course = Eigen::Vector3d::UnitZ(); // unit: from there towards the strike's target
};

} // namespace kumite
