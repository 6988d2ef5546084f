#pragma once
// Captures whose root never moves. Some inertial suits export the pose alone: hachaj-shorinryu's Hips stay at
// one point for the whole file while the legs swing under them, so the foot a kick stands on slides 20 cm and
// rises 15 cm while the body hangs in the air. Nothing downstream can plant such a foot.
//
// root_is_pinned tells such a clip (its root translation is the same in every frame). root_motion_from_feet gives
// it the motion the suit did not record, on the assumption that the body stands on its lower foot: while the same
// ankle is the lower one, the root moves so that this ankle stays where it is horizontally; vertically the root
// moves so that the lower ankle keeps one height (its lowest in the clip). The lower foot changes only when the
// other ankle is lower by more than `switch_margin_m`, so that two feet on the floor do not trade every frame.

#include "kumite/core/clip.h"

namespace kumite {

bool root_is_pinned(const Clip& clip);

struct RootFromFeetReport {
    double support_slide_before_m = 0.0; // the largest horizontal path of an ankle while it was the lower one
    double root_travel_m = 0.0;          // how far the new root moves from the first frame, at most
};

// left_ankle and right_ankle are joint indices of `clip.skeleton`. The clip keeps its rotations; only its root
// translations change.
RootFromFeetReport root_motion_from_feet(Clip& clip, int left_ankle, int right_ankle, double switch_margin_m = 0.01);

} // namespace kumite
