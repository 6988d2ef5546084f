#include "kumite/runtime/planning_budget.h"

#include <algorithm>

namespace kumite {

PlanningBudget::PlanningBudget(int plans_per_frame, std::size_t max_fighters) : m_plans_per_frame(plans_per_frame) {
    m_wanting.reserve(max_fighters);
}

int PlanningBudget::grant(std::span<Fighter* const> fighters) {
    m_wanting.clear();
    for (std::size_t i = 0; i < fighters.size(); ++i) {
        const bool wants = fighters[i]->wants_to_plan();
        fighters[i]->set_may_plan(!wants || m_plans_per_frame <= 0);
        if (wants && m_wanting.size() < m_wanting.capacity()) m_wanting.push_back(static_cast<int>(i));
    }
    const int wanting = static_cast<int>(m_wanting.size());
    if (m_plans_per_frame <= 0 || wanting <= m_plans_per_frame) {
        for (int index : m_wanting) fighters[index]->set_may_plan(true);
        return wanting;
    }
    // More fighters than plans: each granted one looks at one target part this frame (its next, if any, later).
    // The first plans_per_frame in serving order (a partial sort: no allocation).
    auto first_served = [&](int a, int b) {
        const Fighter& x = *fighters[a];
        const Fighter& y = *fighters[b];
        if (x.plan_is_retry() != y.plan_is_retry()) return !x.plan_is_retry();
        if (x.order_since_s() != y.order_since_s()) return x.order_since_s() < y.order_since_s();
        return a < b;
    };
    std::partial_sort(m_wanting.begin(), m_wanting.begin() + m_plans_per_frame, m_wanting.end(), first_served);
    for (int k = 0; k < m_plans_per_frame; ++k) fighters[m_wanting[k]]->set_may_plan(true, 1);
    return wanting;
}

} // namespace kumite
