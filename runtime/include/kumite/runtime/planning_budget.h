#pragma once
// Strike planning spread over frames (issue: no hitch when orders arrive). Planning a strike (its retrievals, the
// reach checks of up to four body parts, the adaptation's set-up) costs about half a millisecond; two hundred
// fighters ordered at once would plan in one frame and freeze it. Each frame, before the fighters step, the budget
// lets at most `plans_per_frame` of the fighters that want to plan do so; the others keep their guard and their
// order, and plan on a later frame. Served in order: first attempts before retries (a fighter whose strike waits for
// reach looks again each frame), then the oldest order first, then the lower fighter index. Deterministic: the same
// orders give the same plans on the same frames. Nothing here allocates after construction.

#include "kumite/runtime/fighter.h"

#include <span>
#include <vector>

namespace kumite {

class PlanningBudget {
public:
    // plans_per_frame <= 0: no limit (every fighter plans on the frame it wants to, as without a budget).
    PlanningBudget(int plans_per_frame, std::size_t max_fighters);

    // Grants this frame's plans (Fighter::set_may_plan on every fighter). Call after the frame's orders, before
    // the fighters step. Returns how many fighters wanted to plan.
    int grant(std::span<Fighter* const> fighters);
    int plans_per_frame() const { return m_plans_per_frame; }

private:
    int m_plans_per_frame = 0;
    std::vector<int> m_wanting; // scratch: indices of the fighters that want to plan (capacity max_fighters)
};

} // namespace kumite
