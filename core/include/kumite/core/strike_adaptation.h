#pragma once
// Adaptation (ARCHITECTURE.md step 6): a retrieved strike played on a character, frame by frame, so that its hit
// segment meets the latched target at the contact frame, with planted feet.
//
// Per frame i (clip frame start + i, at the database's frame rate):
//  1. the clip's MIR frame, moved by the retrieval's alignment, blended from the MIR frame the character was in
//     when the strike began over `blend_frames`: a ramp (smoothstep weight, C1 at both ends) or an
//     inertialization (the clip plus the starting offset decayed by a quintic; BlendMode);
//  2. the constraint ramp: the hit point is driven to p(t) + d(t), with d(t) = ramp(t) * d(tc), d(tc) the offset
//     between where the hit point would be at the contact frame and the target. Up to the contact the ramp follows
//     the clip's own progress towards its hit (OffsetRamp::progress), so the strike arrives on the target as the
//     clip arrives at its hit; after the contact it falls back to 0 over `recovery_frames` (constraint_ramp);
//  3. the limb alone: the decoder's analytic two-bone solve of that limb, swivel kept;
//  4. when the limb cannot reach — or only at full stretch: beyond limb_reach_share of its length — Cyclic
//     Coordinate Descent over trunk pivots (clavicle, chest, spine base for arm strikes; the pelvis about the
//     support hip for leg strikes), each turned just so far that the limb's root comes within that reach of the
//     target (a knee or elbow strike: onto the point the upper bone's length from it), within its joint limit
//     (settings), until 1 mm or the iteration budget; the limb is then solved again onto the closest point it
//     reaches; a pivot stops where its turn no longer pays (the root nearing the target at less than half the
//     speed it swings). The turns the contact frame needs are found at begin() (and at each retarget) and the
//     trunk leans into the strike by the offset ramp's share of them (extremity strikes; d(tc) measured from the
//     leaned hit point), the CCD topping up what is left. Every frame starts from the clip's own frame and turns
//     no further than needed, so the result is a smooth function of the target: no jitter, no jump where the
//     target leaves the limb's reach.
//  5. the support feet — planted both in the current motion and in the clip's start — stay pinned where they
//     were when the strike began, for the whole strike; a kick's kicking foot is free. When the clip's hips rise
//     beyond what a pinned leg reaches, the hips are lowered towards the foot instead of lifting it.
//  6. impact: after the contact the hit point may not go past the target (out of reach: the closest point it got
//     to at the contact) along any of the strike's approach directions (its path's chords over the last frames) by more than a soft margin (overshoot_softness_m, approached smoothly), so a strike that lands stops at the
//     target and then recovers along the clip's own retraction, offset-corrected. set_impact(false) lets the
//     strike follow through instead (the user dodged: a visible miss). How far past it the hit point went
//     (past_target_m, the events' overshoot) counts within target_radius_m of an approach line: through the target.
//  7. plausible joints (joint_limits.h): a limb whose extremity is moved keeps bending the way the clip bends it
//     (its elbow or knee bend carried over to the new root->extremity line instead of re-measured from a fixed
//     reference, which can flip it); every frame reports the joints that still break the limits.
// Everything is sized by the first begin(); after it, begin() and step() do not allocate.

#include "kumite/core/character_rig.h"
#include "kumite/core/joint_limits.h"
#include "kumite/core/mir_edit.h"

namespace kumite {

// 0 before t0; rises with a smoothstep (C1: zero slope at both ends) to 1 at tc; falls the same way back to 0 over
// `recovery` after tc; 0 after. Times in frames (any unit).
double constraint_ramp(double t, double t0, double tc, double recovery);

// How the strike takes over from the current motion (see adaptation_bench's blend_pop for the measurement).
enum class BlendMode {
    ramp,            // slerp from the current pose towards the clip, smoothstep weight
    inertialization, // the clip plus the initial offset (current - clip), decayed by a quintic to 0
};

// How d(t) grows from the strike's start to the contact.
enum class OffsetRamp {
    // smoothstep of the clip's progress towards its hit: the share of the hit point's path from the start to the
    // contact it has covered, so the offset moves the fist in step with the clip's own motion (no faster than it,
    // scaled by offset over path). A target nearer than the clip's hit then gets a shorter strike; with time, the
    // clip reaches its full extension while the ramp still lags, and the offset pulls the fist back onto the target
    // at the end: a loop that arrives moving towards the body.
    progress,
    time, // the paper's: a smoothstep in time from the start to the contact (constraint_ramp)
};

struct AdaptationSettings {
    int blend_frames = 6;            // blend-in from the current motion (0.2 s at 30 fps)
    BlendMode blend = BlendMode::ramp;
    int recovery_frames = 8;         // d(t) back to 0 after the contact
    double reach_tolerance_m = 0.001;
    int ccd_iterations = 4;          // sweeps over the pivots (measured: 8 gains nothing, costs twice)
    // The limb carries the hit point out to this share of its length (or as far as the clip's own limb reaches
    // that frame, when it is straighter); further out the trunk brings the limb's root nearer. A person's punch
    // meets its target with the elbow still bending out, not snapped straight: at full stretch the last
    // centimetres of reach take the elbow's fastest turn and the fist arrives slow. 1: the limb alone
    // as far as it reaches.
    double limb_reach_share = 0.95;
    // Joint limits of the CCD, as the largest turn away from the clip's own pose (radians): 25 deg for the spine
    // base, 15 deg for the chest, 15 deg for a clavicle, 30 deg for the pelvis (leaning back from a kick); the chest
    // never turns further than limits.trunk_turn_rad from the pelvis.
    double spine_base_limit_rad = 25.0 * 3.14159265358979 / 180.0;
    double chest_limit_rad = 15.0 * 3.14159265358979 / 180.0;
    double clavicle_limit_rad = 15.0 * 3.14159265358979 / 180.0;
    double pelvis_limit_rad = 30.0 * 3.14159265358979 / 180.0;
    // Impact: how far past the target the hit point may drift after the contact; the excess is squashed smoothly
    // (C1) so that the overshoot stays below this margin.
    double overshoot_softness_m = 0.005;
    // How far from the approach line through the stop point the target reaches (a head, a trunk): past the stop
    // point within it is through the target (AdaptedFrame::past_target_m); further aside the hit point has left it.
    double target_radius_m = 0.3;
    bool keep_clip_bends = true; // step 7; off: the decoder's swivels as they are (for comparison)
    OffsetRamp offset_ramp = OffsetRamp::progress;
    JointLimits limits;
};

// The limb (Limb) a hit segment belongs to: an arm for clavicle to hand, a leg for thigh to toe (the right leg
// for anything else).
int limb_of_segment(BodyPart segment);

// Whether a hit segment strikes with its limb's middle joint: the forearm's joint is the elbow (elbow strikes),
// the shin's the knee (knee strikes). Their adaptation places that joint on the target: the limb turns about
// its root as the clip holds it (the lower bone keeps its bend), and the trunk brings the root to the upper
// bone's length from the target when the limb alone cannot.
bool segment_strikes_with_middle(BodyPart segment);

struct StrikePlan {
    int clip = -1;
    int start_frame = 0;
    int contact_frame = 0;
    FloorAlignment clip_to_world; // from the retrieval
    Eigen::Vector3d target_world = Eigen::Vector3d::Zero();
};

enum class Reach { limb, torso, unreachable };

struct AdaptedFrame {
    Eigen::Vector3d effector = Eigen::Vector3d::Zero(); // the hit joint, world
    Eigen::Vector3d wanted = Eigen::Vector3d::Zero();   // p(t) + d(t)
    double ramp = 0.0;
    Reach reach = Reach::limb;
    int ccd_decodes = 0;
    std::array<double, 3> pivot_turn_rad{};             // how far the CCD turned each pivot (within its limit)
    bool contact = false;                               // the contact frame
    double past_target_m = 0.0;   // after the contact: how far the effector is past the target (out of reach: the
                                  // closest point reached at the contact) along the farthest approach direction,
                                  // counted within settings.target_radius_m of that direction's line (through it)
    unsigned joint_violations = 0; // joint_limits.h mask
};

class StrikeAdapter {
public:
    StrikeAdapter(const CharacterRig& rig, const MotionDatabaseView& database, AdaptationSettings settings = {});

    // Starts a strike from the character's current MIR frame and feet ([left, right]: planted or not, and the
    // ankles' world positions). Decodes the contact frame once to find d(tc).
    void begin(const StrikePlan& plan, const MirFrame& current, const std::array<bool, 2>& planted,
               const std::array<Eigen::Vector3d, 2>& ankles_world);
    const StrikePlan& plan() const { return m_plan; }
    AdaptationSettings& settings() { return m_settings; }
    bool arm_strike() const { return m_arm; }
    bool middle_strike() const { return m_middle; } // a knee or elbow strike (segment_strikes_with_middle)
    // Moves the target during the strike (a fighter that keeps its eyes on a moving head until shortly before the
    // contact): d(tc), the trunk's lean at the contact and the stop point are found again for it (a few decodes at
    // the contact frame, no allocation), so the offset ramp carries the hit point to the new target by the contact.
    // The move shows in the next step() by ramp(t) times the target's move.
    void retarget(const Eigen::Vector3d& target_world);
    // Step 6 on (the default at begin()) or off; the fighter turns it off when the user is no longer at the target.
    void set_impact(bool impact) { m_impact = impact; }
    bool impact() const { return m_impact; }
    // Stops the strike before its contact where something met it (a user's glove or forearm in the way): from frame
    // `index` on, step 6 holds the hit point from passing `stop_world` along `direction` (unit: its course as it
    // met it), as it holds a strike that landed at its target, the impact on. Called again (any index) with where
    // the obstacle is now, the stop follows it. begin() clears it.
    void stop_early(double index, const Eigen::Vector3d& stop_world, const Eigen::Vector3d& direction);
    // As stop_early, with a second plane through its own point that the hit point may not pass either (world;
    // `also_direction` unit): a blocked blow held out of the glove as it is now and from advancing past where
    // the block first stopped it.
    void stop_early(double index, const Eigen::Vector3d& stop_world, const Eigen::Vector3d& direction, const Eigen::Vector3d& also_stop_world,
                    const Eigen::Vector3d& also_direction);
    bool stopped_early() const { return m_early_stop_index < k_no_early_stop; }
    // The unit direction in which the hit point arrives at the target over the frame before the contact (world;
    // the impact also holds it along its chords over the 2 to 4 frames before), and where it stops: the target,
    // or out of reach the closest point it gets to at the contact. Found at begin().
    const Eigen::Vector3d& approach_direction() const { return m_approach; }
    const Eigen::Vector3d& stop_point() const { return m_stop_point; }
    // Step 2's ramp at frame `index` (0 = the start frame): how much of d(tc) the hit point is moved by.
    double offset_ramp(double index) const;
    // Where the hit joint is at the contact frame in the clip as decoded on this character, before any offset:
    // the strike's own landing point (the retrieval's contact point predicts it by scaling the actor's).
    Eigen::Vector3d clip_contact_point() const { return m_plan.target_world - m_offset_at_contact; }

    int frame_count() const { return m_frame_count; }   // start .. the clip's last frame
    int contact_index() const { return m_plan.contact_frame - m_plan.start_frame; }
    int effector_joint() const { return m_effector_joint; }
    const std::array<bool, 2>& support_feet() const { return m_support; }
    const std::array<Eigen::Vector3d, 2>& support_pins() const { return m_support_pins; }

    // Frame `index` (0 = the start frame) into `out`; model transforms of it in positions() / rotations(). A
    // fractional index plays between the database's frames (MIR frames interpolated): a 60 Hz frame loop on a
    // 30 fps database steps by 0.5.
    AdaptedFrame step(double index, Pose& out);
    AdaptedFrame step(int index, Pose& out) { return step(static_cast<double>(index), out); }
    std::span<const Eigen::Vector3d> positions() const { return m_decoder.model_positions(); }
    std::span<const Eigen::Quaterniond> rotations() const { return m_decoder.model_rotations(); }

private:
    void frame_mir(double index, MirFrame& out); // step 1: the clip's frame (interpolated), aligned, blended
    void load_clip_frame(int index, MirFrame& out) const;
    // Decodes; when a pinned support foot is out of its leg's reach, moves the hips towards it just enough and
    // decodes again (so the foot stays down rather than being dragged up). Returns the decodes made.
    int decode(Pose& out, const MirFrame& frame, LimbPins& pins);
    // Step 6 on the decoded frame: the offset that keeps the hit point from passing the target. Step 7: the
    // swivels that keep the clip's bends for the limbs whose extremity is moved. Each returns whether it changed
    // anything (then the frame is decoded again).
    bool stop_at_target(LimbPins& pins, double index) const;
    // Step 6's move of a hit point at `point` that keeps it from passing the stop point (zero when it does not).
    Eigen::Vector3d impact_correction(const Eigen::Vector3d& point, double index) const;
    // Knee and elbow strikes: the frame with the limb's middle joint driven to `wanted` (see
    // segment_strikes_with_middle), from the trunk of the last decode of m_frame. Returns the decodes made.
    int place_middle(Pose& out, LimbPins& pins, const Eigen::Vector3d& wanted);
    AdaptedFrame step_middle(double index, Pose& out, AdaptedFrame result, LimbPins& pins);
    // Decodes m_frame with the striking limb placed on result.wanted (knee and elbow strikes) or as pinned.
    int decode_striking(Pose& out, LimbPins& pins, const Eigen::Vector3d& wanted);
    // How far `point` is past the stop point along the farthest of the approach directions (0 when behind all).
    double past_stop(const Eigen::Vector3d& point) const;
    bool keep_clip_bends(const LimbPins& pins);
    // The vector from limb `limb`'s root to its extremity in the clip's own frame m_frame (world, metres).
    Eigen::Vector3d clip_reach(int limb) const;
    // Where limb `limb`'s middle joint bulges in the clip's own frame, from the decoded root (zero if straight).
    Eigen::Vector3d clip_bend(int limb) const;
    unsigned violations() const;
    // Step 4: the trunk's CCD when the limb alone falls short of result.wanted.
    void reach_with_trunk(AdaptedFrame& result, LimbPins& pins, Pose& out);
    AdaptedFrame at_stop(const AdaptedFrame& result); // the contact frame sets where the strike stops
    // Leans the trunk by `share` of the contact's lean (decoded again when it does); returns the decodes made.
    int lean(double share, Pose& out, LimbPins& pins);
    void measure_contact_offset(); // d(tc) from the hit point at the contact frame, leaned
    AdaptedFrame plan_contact();   // d(tc), the lean and the stop point for the current target; the contact frame
    // How far from its root the striking limb carries the hit point this frame (limb_reach_share).
    double limb_reach() const;
    // Whether the striking limb's root is further from `wanted` than the limb carries (only for an extremity strike).
    bool beyond_limb_reach(const Eigen::Vector3d& wanted) const;
    Eigen::Vector3d pivot_point(TrunkPivot pivot) const;
    // The part of a chest or spine-base turn that keeps the trunk within limits.trunk_turn_rad.
    Eigen::Quaterniond within_trunk_limit(const Eigen::Quaterniond& turn) const;
    double pivot_limit(TrunkPivot pivot) const;

    const CharacterRig& m_rig;
    MotionDatabaseView m_db;
    AdaptationSettings m_settings;
    MirDecoder m_decoder;
    StrikePlan m_plan;
    MirFrame m_current;      // where the character was when the strike began
    MirFrame m_initial_offset; // inertialization: current minus the clip's first frame
    MirFrame m_clip_frame;   // scratch
    MirFrame m_next_frame;   // scratch: the following frame, for fractional indices
    MirFrame m_frame;        // scratch: the frame being decoded
    Pose m_scratch_pose;
    int m_frame_count = 0;
    int m_limb = 0;          // the striking limb (Limb)
    int m_effector_joint = -1;
    bool m_arm = true;
    bool m_middle = false;   // knee or elbow strike: the effector is the limb's middle joint
    std::array<bool, 2> m_support{};
    std::array<Eigen::Vector3d, 2> m_support_pins;
    LimbPins m_pins;
    Eigen::Vector3d m_offset_at_contact = Eigen::Vector3d::Zero(); // d(tc)
    std::vector<double> m_progress; // [frame from the start .. contact]: the clip's progress to its hit (sized once)
    static constexpr int k_approach_chords = 4;
    std::array<Eigen::Vector3d, k_approach_chords + 1> m_approaches{}; // unit, world: the chords, then outwards
    int m_approach_count = 0;
    Eigen::Vector3d m_approach = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d m_stop_point = Eigen::Vector3d::Zero(); // the target, or the closest point reached at the contact
    // Per approach direction, how far along it its plane lies from the stop point (0 but for stop_early's second
    // plane, which has its own point).
    std::array<double, k_approach_chords + 1> m_plane_offsets{};
    bool m_impact = true;
    static constexpr double k_no_early_stop = 1e300;
    double m_early_stop_index = k_no_early_stop; // stop_early's frame (the contact's stop holds after the contact)
    std::array<double, k_limb_count> m_clip_swivels{}; // the frame's swivels before step 7 changed them
    std::array<TrunkPivot, 3> m_pivots{};
    int m_pivot_count = 0;
    std::array<Eigen::Quaterniond, 3> m_pivot_turns;
    // The trunk's lean at the contact (the CCD's turns there, found at begin()), and the share of it this frame
    // leans by (the offset ramp's): the trunk leans into the strike as the hit point travels, instead of all at
    // once in the frame the target leaves the limb's reach.
    std::array<Eigen::Quaterniond, 3> m_contact_lean;
    std::array<Eigen::Quaterniond, 3> m_lean_now;
    bool m_leans = false;
};

} // namespace kumite
