#pragma once
// The strike for the pending order (fighter.h): the clip retrieved for the fighter's pose and the target (the head
// latched at the order, or predicted at the contact), tried at the head and then lower on the body until one
// reaches; an order no strike reaches waits while stepping in can help, then strikes at the head anyway. A clip
// struck lately gives way to another that scores within a margin (variety). Owns: the retrieval workspace, the
// pose feature, the ring of recent clips, the planning budget's grant. Touches: the order (how far its look got),
// the strike (it plans it and starts it). Reads: the body, the user, the footwork's band and step.

#include "fighter/footwork.h"
#include "fighter/order_queue.h"
#include "fighter/strike.h"

#include <array>

namespace kumite {

class StrikePlanner {
public:
    StrikePlanner(const MotionDatabaseView& db, const Retriever& retriever, const FighterSettings& settings);

    // The planning budget (planning_budget.h): whether this step may plan, and how many target parts the first look
    // at an order may try in it.
    void set_budget(bool may_plan, int parts) { m_may_plan = may_plan, m_plan_parts = parts; }
    bool may_plan() const { return m_may_plan; }

    // Looks for the pending order's strike: the strike planned and started (begun), the order refused (no strike of
    // that kind can start from here), or not yet (it waits: for reach, or for a head that changes course to settle).
    enum class Outcome { waiting, refused, begun };
    Outcome plan(double t_s, FighterAim aim, bool approaching, OrderQueue& orders, CharacterBody& body, const TrackedUser& user,
                 const Footwork& footwork, Strike& strike);

private:
    // The strike for the pending order at the point `drop_m` under the head, where `aim` asks for (as it is, or as it
    // will be at the contact); the target used in `target`.
    RetrievalResult retrieve(RetrievalQuery& query, const Eigen::Vector3d& offset, FighterAim aim, const PendingOrder& pending, const TrackedUser& user,
                             Eigen::Vector3d& target);
    // A retrieval that prefers a clip not struck lately; m_varied tells if it did.
    RetrievalResult query_with_variety(RetrievalQuery& query);
    void remember(int clip);

    const MotionDatabaseView& m_db;
    const Retriever& m_retriever;
    double m_wait_for_reach_s, m_reach_tolerance_m, m_variety_margin;
    int m_variety_recent;
    bool m_reach_fallback;
    double m_surface_depth_m;
    bool m_may_plan = true; // the planning budget lets this step plan a strike
    int m_plan_parts = 4;   // ... looking at this many target parts at most
    bool m_varied = false;  // the last retrieval took a varied clip
    std::array<int, k_max_variety_recent> m_recent_clips{}; // the clips of the last strikes, newest at m_recent_next - 1
    int m_recent_count = 0;
    int m_recent_next = 0;
    std::array<float, k_feature_dimensions> m_feature{};
    RetrievalWorkspace m_workspace;
};

} // namespace kumite
