#pragma once
// The last word on the pose shown (fighter.h; issue 44, "human speed, everywhere"): no wrist, ankle, elbow or knee
// of the fighter moves faster than the library's fastest for the kind of move the frame is (speed_bar), and no wrist
// or ankle faster than a person's (k_human_extremity_mps). A pose that would is shown only part of the way from the
// last one shown — every joint's local rotation and the root slerped by the share that keeps the fastest joint at its
// bar — so the body lags what the other parts asked for and catches up as they slow: what cannot be done at human
// speed is not shown faster. Owns the last pose shown, its measures and the counts of held frames. Touches the
// body's pose (it replaces it with the one shown) and, when it holds one back, its MIR frame (encoded from the pose
// shown: the next blend or strike starts there). Reads the library's speeds on each character.

#include "fighter/character_body.h"

#include "kumite/runtime/joint_speeds.h"

#include <memory>

namespace kumite {

class SpeedLimit {
public:
    // `library`: per character of the body, its library speeds (LibrarySpeeds::per_character).
    explicit SpeedLimit(std::shared_ptr<const LibrarySpeeds> library);
    // Sized for poses of up to `joints` joints: nothing allocates after.
    void reserve(int joints);

    // The next pose is shown as it is (the first frame, a new character).
    void reset() { m_has_last = false; }
    // Holds the body's pose to the bar of `kind` since the last frame shown, `t_s` now.
    void apply(double t_s, MoveKind kind, CharacterBody& body);

    // Frames held back (the pose shown short of the asked one), per kind, and the furthest a wrist or ankle was
    // left behind the pose asked for (m).
    const std::array<long long, k_move_kind_count>& held_frames() const { return m_held_frames; }
    double largest_lag_m() const { return m_largest_lag_m; }

private:
    double over_bar(const LimbSample& sample, const JointSpeeds& bar, double dt_s) const;

    std::shared_ptr<const LibrarySpeeds> m_library;
    bool m_has_last = false;
    int m_character = -1;
    double m_last_s = 0.0;
    Pose m_last;              // the pose shown last frame
    LimbSample m_last_sample; // and its measures
    Pose m_asked;             // scratch: this frame's asked pose
    std::array<long long, k_move_kind_count> m_held_frames{};
    double m_largest_lag_m = 0.0;
};

} // namespace kumite
