#pragma once
// The fighter's defence on its body (fighter.h, defence.h): each frame its body as shown handed to the Defence with
// the moves its state allows (no slip while a strike drives the trunk, no block with the striking arm, nothing in
// hold or without a head); the user's strikes told as events; the move's edits (a blocking arm driven onto the
// hand's course or playing a captured block, a slip's lean) decoded over the pose shown, measured (joint limits,
// feet). Owns: the Defence, the captured block's arm, the edited frame and what it shows, the edits' measures since
// the last user strike, the blow that landed this frame. Touches: the body (the pose shown), the event log
// (user_strike, user_strike_end). While the fighter strikes, the arms the strike leaves free are kept where the
// guard had them from the head (a kata's pulled-back hand, a swinging arm: the face is covered as a boxer's is).

#include "fighter/captured_block_arm.h"
#include "fighter/character_body.h"
#include "fighter/event_log.h"
#include "fighter/speed_limit.h"

#include "kumite/runtime/defence.h"
#include "kumite/runtime/user_guard.h"

namespace kumite {

class FighterDefence final : public HeldPoseBounds {
public:
    FighterDefence(const MotionDatabaseView& db, const DefenceSettings& settings) : m_defence(settings), m_block_arm(db) {}

    Defence& defence() { return m_defence; }
    const Defence& defence() const { return m_defence; }
    bool active() const { return m_defence.active(); } // a move is on (orders wait)
    void reset();                                      // the tracker lost the user, another character: no move
    void cancel_move() { m_defence.cancel_move(); }    // a blow landed: the move gives way to the hit reaction

    // One frame, before the body moves: the user's `hands` against the body shown last frame (at `shown_s`), the
    // moves `state` allows (`striking_segment`: the strike's body part, while striking), the events of the user's
    // strikes.
    void defend(double t_s, double shown_s, const UserHands& hands, bool tracking, FighterState state, int striking_segment, const CharacterBody& body,
                EventLog& log);
    // A user strike landed on the head or chest in this frame's defend() (the last one, when both hands did).
    bool landed() const { return m_landed; }
    const UserStrikeEvent& landed_strike() const { return m_landed_strike; }
    // After the body moved (the clip played, with the feet's `pins`, or the strike's adapted frame of the body part
    // `striking_segment`, -1 when not striking): the move's edits and the guard kept decoded over the pose shown, when
    // either is on.
    void apply(double now_s, int striking_segment, const LimbPins& pins, CharacterBody& body);
    // This frame's apply() also keeps the fists out of the user's gloves: a glove pushes a fist it meets (the guard
    // pose against a user in close, a blocked strike's recovery swinging back through the glove that stopped it),
    // every arm but a strike's own (its contact is the strike's) and a captured block's. Cleared by apply().
    void keep_fists_off_gloves(const UserGuard& guard, double fist_radius_m, double knuckles_past_wrist_m) {
        m_fist_off = {&guard, fist_radius_m, knuckles_past_wrist_m};
    }
    // For the speed limit (HeldPoseBounds): an arm held back whose fist would be in one of the user's gloves, of the
    // arms this frame's apply() kept out of them.
    bool blocked(const CharacterBody& body, int limb) const override;
    // After the speed limit: the blocking arm's speed as shown, for the block's event (when apply() edited one).
    void note_shown_arm(double now_s, const CharacterBody& body);

    // The speed limit held the pose shown back from the one the edits asked for: the recording's MIR follows it.
    void shown_held(CharacterBody& body) {
        if (m_shown) body.encode(m_shown_mir);
    }
    // The pose shown with the edits, in the MIR (for a recording), and whether this frame's pose carries them.
    bool shown() const { return m_shown; }
    const MirFrame& shown_mir() const { return m_shown_mir; }
    // Frames kept here that may hold any character's MIR frame (for sizing: CharacterBody).
    std::array<MirFrame*, 2> frames() { return {&m_defended_frame, &m_shown_mir}; }

private:
    Defence m_defence;
    CapturedBlockArm m_block_arm;
    MirFrame m_defended_frame;           // scratch: the shown frame with the defence's edits
    MirFrame m_shown_mir;                // the pose shown with the defence's edits, encoded again
    bool m_shown = false;                // this frame's pose carries the defence's edits
    LimbPins m_pins;                     // the edits' pins (the feet as shown, the blocking arm's offset)
    int m_violations = 0;                // joint-limit violations of the defence's edits, since the last user strike ended
    double m_foot_shift_m = 0.0;         // how far they moved a foot, since then
    int m_arm_to_note = -1;              // the limb apply() moved as a block this frame (its speed is noted as shown)
    bool m_landed = false;               // a user strike landed this frame
    // The guard kept while striking (DefenceSettings::keep_guard): each arm's wrist from the head (heading axes) in
    // the guard as last shown, and each arm's weight towards it (1 while striking and k_cover_hold_s after).
    std::array<Eigen::Vector3d, 2> m_guard_wrist_from_head{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    bool m_guard_known = false;
    std::array<double, 2> m_cover_weight{0.0, 0.0};
    std::array<double, 2> m_cover_end_s{0.0, 0.0};
    double m_last_apply_s = 0.0;
    UserStrikeEvent m_landed_strike;
    struct FistOff {
        const UserGuard* guard = nullptr; // none this frame
        double fist_radius_m = 0.0, knuckles_past_wrist_m = k_fist_centre_past_wrist_m;
    } m_fist_off;
    // The fists of `arms` as decoded now pushed out of the user's gloves (`pins` and the defended frame's swivels
    // edited): whether any was in one.
    bool push_fists_out(const FistOff& fists, const std::array<bool, 2>& arms, const std::array<Eigen::Vector3d, 2>& bends, LimbPins& pins, CharacterBody& body);
    // The fist of an arm whose elbow and wrist are given held out of the user's gloves: the wrist's offset
    // (world), zero when it is in none.
    static Eigen::Vector3d fist_off_offset(const FistOff& fists, const Eigen::Vector3d& elbow, const Eigen::Vector3d& wrist);
    static Eigen::Vector3d fist_centre(const Eigen::Vector3d& elbow, const Eigen::Vector3d& wrist, double knuckles_past_wrist_m) {
        const Eigen::Vector3d along = wrist - elbow;
        return along.norm() > 1e-6 ? Eigen::Vector3d(wrist + knuckles_past_wrist_m * along.normalized()) : wrist;
    }
    FistOff m_fists_kept;            // this frame's apply(): the gloves the fists were kept out of (guard nullptr: none)
    std::array<bool, 2> m_fists_kept_arms{}; // and the arms kept out of them (not a strike's own, nor a captured block's)
};

} // namespace kumite
