#pragma once
// The fighter's answer to a blow that lands (fighter.h): the database's captured hit reactions (`hit_reaction`
// clips, each starting at its impact), and the choice of one for a landed user strike. Each clip is measured once:
// the way its head goes relative to the hips (back, sideways, down, folding forward) from the impact to its largest
// displacement, in the clip's heading at the impact. A blow to the head is answered by the clip whose head goes
// most nearly the way the fist pushed (its course in the fighter's heading, horizontal); a blow to the body by the
// clip that folds most (head forward and down, towards the blow). Owns: the clips' courses, the last ones chosen
// (not played again soon when another fits nearly as well). Touches: nothing (it answers; the conductor plays
// the clip on the MotionPlayer).

#include "kumite/core/character_rig.h"
#include "kumite/core/motion_database.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace kumite {

class HitReactions {
public:
    // The clips measured on `measured_on` (the courses are directions: any skeleton tells them alike).
    HitReactions(const MotionDatabaseView& db, const CharacterRig& measured_on);

    struct Clip {
        int clip = -1;
        Eigen::Vector3d head_course = Eigen::Vector3d::Zero(); // unit, the clip's heading axes (+Z forward, +X left)
        double head_travel_legs = 0.0;                         // the head's largest displacement, leg lengths
    };
    struct Choice {
        int clip = -1;     // -1: the database holds no hit reaction
        double fit = 0.0;  // cosine between the clip's head course and the one the blow asks for
    };
    // The clip for a blow that pushes along `push_in_heading` (the fist's velocity in the fighter's heading axes),
    // at the head or at the body.
    Choice choose(const Eigen::Vector3d& push_in_heading, bool at_head);
    // The head course a blow asks for (unit): the push's horizontal direction with a little drop at the head, the
    // fold (forward and down) at the body.
    static Eigen::Vector3d wanted_course(const Eigen::Vector3d& push_in_heading, bool at_head);

    const std::vector<Clip>& clips() const { return m_clips; }

private:
    std::vector<Clip> m_clips;
    std::array<int, 3> m_recent{-1, -1, -1}; // the clips chosen last, the latest first
};

} // namespace kumite
