#pragma once
// How fast a body moves, by kind of move: the fastest wrist and ankle (m/s, world), the fastest elbow and knee
// (rad/s: how fast the joint bends or straightens, the angle between upper arm and forearm, thigh and shin; the
// forearm's twist is not counted: the decoder's twist follows the hand's frame and is no joint speed a person could
// be measured at), and the fastest elbow's own travel (m/s, world: its swing about the shoulder, which the bend does
// not see). The fighter's are measured every frame (motion_meter.h); the library's are those of the database's clips
// played on a character, the bar a fighter must stay under (the speed limit holds wrists, ankles and the bends to it;
// the elbow's travel is measured and reported against its bar, not held: see docs/design.md).

#include "kumite/core/character_rig.h"
#include "kumite/core/motion_database.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/core/skeleton.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace kumite {

// The kinds of move, as a frame of the fighter is classified (its state, its strike's segment, its defence) and
// as a database clip is (its semantics and segment).
enum class MoveKind { guard, step, punch, kick, knee, elbow, block, slip, recover, hold, hit_reaction };
inline constexpr int k_move_kind_count = 11;
const char* move_kind_name(MoveKind kind);
// The kind of strike a segment strikes with (hand: punch, foot: kick, knee, elbow).
MoveKind strike_move_kind(BodyPart segment);
inline bool is_strike_kind(MoveKind kind) {
    return kind == MoveKind::punch || kind == MoveKind::kick || kind == MoveKind::knee || kind == MoveKind::elbow;
}

struct JointSpeeds {
    double wrist_mps = 0.0, ankle_mps = 0.0, elbow_radps = 0.0, knee_radps = 0.0;
    double elbow_mps = 0.0; // the elbow's own travel (world): its swing about the shoulder, which elbow_radps does not see
    void keep_fastest(const JointSpeeds& other);
};

// One pose's joints that speeds are measured on: both wrists and ankles (world), both elbows' and knees' turns.
struct LimbSample {
    std::array<Eigen::Vector3d, 4> extremity;   // wrist l, wrist r, ankle l, ankle r
    std::array<double, 4> flexion_rad;          // elbow l, elbow r, knee l, knee r: 0 straight
    std::array<Eigen::Vector3d, 2> elbow;       // elbow l, elbow r (world)
    static LimbSample of(const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> positions);
};
// The speeds from `before` to `after`, `dt_s` apart.
JointSpeeds joint_speeds(const LimbSample& before, const LimbSample& after, double dt_s);

// The library's fastest per kind of move, on a character: every clip of the database played on it at the
// database's rate; a clip's speed is its second-fastest frame's (a capture's one-frame glitch is not a person's
// speed), a kind's the fastest of its clips. Kinds without clips stay 0. Decodes every pose once (~0.2 s).
std::array<JointSpeeds, k_move_kind_count> library_joint_speeds(const MotionDatabaseView& db, const Skeleton& skeleton, const RestAnatomy& anatomy);
// No human wrist or ankle moves faster than this (m/s; the fastest punches and kicks measured), whatever the library.
inline constexpr double k_human_extremity_mps = 12.0;

// The bar a frame of `kind` is held to, from the library's fastest per kind: its own kind's; the guard's and a
// hold's (no clips of its own) the fastest of the guard clips' and the steps' (the guard clips stand still: 0.25 m/s
// wrists, 0.05 m/s ankles; the fighter in its guard turns to face the user and shuffles, as a person does by
// stepping), a recovery's (a strike blended back into the guard) the fastest strike's; a kind the
// library has no clips of (a slip) the block's, else the fastest strike's. Wrists and ankles never above
// k_human_extremity_mps. A measure the bar leaves 0 is not held to anything.
JointSpeeds speed_bar(const std::array<JointSpeeds, k_move_kind_count>& library, MoveKind kind);

// The library's fastest per kind, on each of a set of characters (library_joint_speeds), measured once and shared
// by the fighters that play them.
struct LibrarySpeeds {
    std::vector<std::array<JointSpeeds, k_move_kind_count>> per_character;
};

// The library's speeds on each of `characters` (library_joint_speeds on each: ~0.2 s apiece on the reference
// database): what a Bout measures once for all its fighters.
std::shared_ptr<const LibrarySpeeds> measure_library_speeds(const MotionDatabaseView& db, const std::vector<CharacterRig*>& characters);

// A clip's kind, or none (a clip of another kind: a duck, a walk).
bool clip_move_kind(const MotionDatabaseView& db, int clip, MoveKind& kind);

} // namespace kumite
