#pragma once
// Edits of a MIR frame that the adaptation makes before decoding: moving it on the floor (the retrieval's
// alignment), blending two frames, and turning the body above a trunk joint (the CCD of unreachable targets).
// World quantities (hip centre, part and chain frames) change; limb extremities stay in their parents' frames.

#include "kumite/core/mir.h"
#include "kumite/core/pose_distance.h"

namespace kumite {

// A floor motion in metres applied to a frame decoded on a character whose leg length is `leg_length`.
void mir_frame_move_on_floor(MirFrame& frame, const FloorAlignment& motion, double leg_length);

// out = a blended towards b by weight w in [0, 1]: trunk frames slerped; limb part frames by swing (the bone along
// the great circle) and twist (about the bone) apart, as skeletons differ in how their limb frames turn about the
// bone; limb extremities interpolated as world directions (then expressed in the blended parent frame); positions
// and swivels interpolated; the chains take b's joint fractions (a's chains are sampled there). `out` must not
// alias a or b.
void mir_frame_blend(MirFrame& out, const MirFrame& a, const MirFrame& b, double w);

// Inertialization (Bollo 2016) in MIR space: the offset that takes frame `to` onto frame `from` (hip centre,
// extremity and swivel differences; part and chain frames as rotations from `to`'s to `from`'s, chains at
// `to`'s fractions), stored in a MirFrame; then `frame` plus `weight` times that offset.
void mir_frame_offset(MirFrame& offset, const MirFrame& from, const MirFrame& to);
void mir_frame_add_offset(MirFrame& frame, const MirFrame& offset, double weight);

// The arms of `from` carried onto `frame`'s chest: the clavicles', upper arms', forearms' and hands' frames turned
// by the turn from `from`'s chest to `frame`'s, the extremities (in their parents' frames) and swivels as `from`
// has them. A step that keeps the guard's arms (steps blended into from a tight guard swung the elbows at
// 20+ rad/s towards the loose arms of the walk they were captured in).
void mir_frame_take_arms(MirFrame& frame, const MirFrame& from);

// The trunk joints the CCD may turn, and what each carries.
enum class TrunkPivot {
    spine_base, // the first spine joint above the pelvis: spine chain, chest, neck, head, both arms
    chest,      // the chest: neck, head, both arms
    clavicle_l, // a clavicle: its arm
    clavicle_r,
    pelvis,     // the whole body, about a given point (the support hip), hip centre included
};

// Turns the parts carried by `pivot` by `rotation` (world) about `pivot_point` (world metres; used by pelvis
// only: the other pivots turn about their own joint, where the decoder puts it).
void mir_frame_turn(MirFrame& frame, TrunkPivot pivot, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& pivot_point,
                    double leg_length, double ankle_height);

} // namespace kumite
