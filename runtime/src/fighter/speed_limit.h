#pragma once
// The last word on the pose shown (fighter.h): no wrist, ankle, elbow or knee of the fighter moves (an elbow or knee
// bends) faster than the library's fastest for the kind of move the frame is (speed_bar), and no wrist
// or ankle faster than a person's (k_human_extremity_mps). A limb that would is shown only part of the way from the
// last pose shown — its joints' local rotations slerped by the share that keeps its wrist or ankle and its elbow or
// knee at their bars — the trunk and the other limbs as asked; when the trunk itself carries a limb too fast (a
// turn, a lunge), the whole pose is (every joint and the root by one share). The body lags what the other parts
// asked for and catches up as they slow: what cannot be done at human speed is not shown faster. Owns the last pose shown, its measures and the counts of held frames. Touches the
// body's pose (it replaces it with the one shown) and, when it holds one back, its MIR frame (encoded from the pose
// shown: the next blend or strike starts there). Reads the library's speeds on each character.

#include "fighter/character_body.h"

#include "kumite/runtime/joint_speeds.h"

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

namespace kumite {

// What a pose held back may not do to a limb (limb: LimbSample's order): say, carry a fist into one of the user's
// gloves, where the pose asked for went round it.
class HeldPoseBounds {
public:
    virtual bool blocked(const CharacterBody& body, int limb) const = 0;

protected:
    ~HeldPoseBounds() = default;
};

class SpeedLimit {
public:
    // `library`: per character of the body, its library speeds (LibrarySpeeds::per_character).
    explicit SpeedLimit(std::shared_ptr<const LibrarySpeeds> library);
    // Sized for poses of up to `joints` joints: nothing allocates after.
    void reserve(int joints);
    // Which limb each joint of each character belongs to (its arm's or leg's root and everything below): once, at
    // construction.
    void map_limbs(const std::vector<CharacterRig*>& characters);

    // The next pose is shown as it is (the first frame, a new character).
    void reset() { m_has_last = false; }
    // Holds the body's pose to the bar of `kind` since the last frame shown, `t_s` now. `limbs`: the limbs held
    // to it (bit k: LimbSample's order, arm l, arm r, leg l, leg r); with fewer than all, only those limbs are held,
    // on their own (the trunk shown as asked). `extremities`: every other wrist and ankle held to a person's
    // (k_human_extremity_mps; its elbow or knee free), the whole pose when the trunk carries one too fast. 0 and
    // false: nothing held, the pose only noted as the last shown.
    // `bounds`: a limb held back on its own into a place they forbid (from a pose shown last that was clear) is held
    // back further, to the largest share that is clear.
    void apply(double t_s, MoveKind kind, CharacterBody& body, unsigned limbs = k_all_limbs, bool extremities = false,
               const HeldPoseBounds* bounds = nullptr);
    static constexpr unsigned k_all_limbs = 0xFu;

    // Frames held back (the pose shown short of the asked one), per kind, and the furthest a wrist or ankle was
    // left behind the pose asked for (m).
    const std::array<long long, k_move_kind_count>& held_frames() const { return m_held_frames; }
    double largest_lag_m() const { return m_largest_lag_m; }
    // This frame: how far each limb's wrist or ankle was left behind the pose asked for (0: not held).
    double lag_m(int limb) const { return limb >= 0 && limb < 4 ? m_lag_m[std::size_t(limb)] : 0.0; }
    // The share of the way from the last pose to the asked one this frame showed, per limb (arm l, arm r, leg l,
    // leg r; Limb's order; 1: all of it, not held back).
    double shown_share(int limb) const { return limb >= 0 && limb < 4 ? m_shown_share[std::size_t(limb)] : 1.0; }
    bool held() const { return *std::min_element(m_shown_share.begin(), m_shown_share.end()) < 1.0; } // this frame
    // Whether this frame held `limb` back to the library's bar (not only a person's wrist or ankle).
    bool held_to_library(int limb) const { return limb >= 0 && limb < 4 && (m_library_held & (1u << limb)); }

private:
    using LimbBars = std::array<JointSpeeds, 4>; // per limb, LimbSample's order; a measure left 0 is free
    // Each limb's fastest measure against its bar (> 1: over), from the last pose shown to `sample`.
    std::array<double, 4> limb_ratios(const LimbSample& sample, const LimbBars& bars, double dt_s) const;
    // The limbs over their bar held back on their own; false when that leaves one over `whole_pose_bars` (the trunk
    // carries it too fast).
    bool hold_limbs(const LimbBars& bars, const LimbBars& whole_pose_bars, double dt_s, const std::array<double, 4>& asked_ratios,
                    CharacterBody& body);
    void keep_in_bounds(const HeldPoseBounds& bounds, CharacterBody& body); // after hold_limbs
    void hold_pose(const LimbBars& bars, double dt_s, double over, CharacterBody& body); // the whole pose, one share
    // The limbs held by hold_limbs eased back towards the asked pose (itself under `whole_pose_bars`) as far as
    // brings them under those bars.
    void release_limbs(const LimbBars& whole_pose_bars, double dt_s, CharacterBody& body);

    std::shared_ptr<const LibrarySpeeds> m_library;
    bool m_has_last = false;
    int m_character = -1;
    double m_last_s = 0.0;
    Pose m_last;              // the pose shown last frame
    LimbSample m_last_sample; // and its measures
    Pose m_asked;             // scratch: this frame's asked pose
    std::array<long long, k_move_kind_count> m_held_frames{};
    double m_largest_lag_m = 0.0;
    std::array<double, 4> m_shown_share{1.0, 1.0, 1.0, 1.0};
    std::array<double, 4> m_lag_m{};
    unsigned m_library_held = 0u; // this frame: the limbs held back to the library's bar
    std::vector<std::vector<int>> m_limb_of_joint; // [character][joint]: 0-3 (LimbSample's order), -1 the trunk
};

} // namespace kumite
