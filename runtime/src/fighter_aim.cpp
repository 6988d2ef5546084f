// The fighter's aim (fighter.h): the strike for an order, where it aims (the head latched or predicted, or the
// highest body point in reach), whether it reaches, and the distance band where strikes reach.

#include "kumite/runtime/fighter.h"

#include "fighter_body.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

// The points a strike may aim at, highest first, and how far under a 1.65 m head they are.
constexpr TargetPart k_target_parts[] = {TargetPart::head, TargetPart::chin, TargetPart::chest, TargetPart::solar_plexus};
constexpr double k_target_drops_m[] = {0.0, 0.10, 0.30, 0.45};

// How far under the user's head `part` is: the drop scaled by the user's size (head height / 1.65 m).
double drop_under_head_m(int part, const Eigen::Vector3d& head) { return k_target_drops_m[part] * std::clamp(head.y() / 1.65, 0.5, 1.4); }

} // namespace

double Fighter::band_far_m() const {
    // The far end comes in when the arms cannot reach the head from there, but the band stays a quarter leg wide
    // so a shortened step lands inside it.
    const double leg = leg_length(), near_m = m_settings.near_legs * leg;
    return m_tracking ? std::clamp(strike_reach_m(), near_m + 0.25 * leg, m_settings.far_legs * leg) : m_settings.far_legs * leg;
}

double Fighter::strike_reach_m() const {
    const Body& body = *m_bodies[m_character];
    const RestAnatomy& anatomy = body.rig->anatomy();
    const auto positions = body.decoder.model_positions();
    // At the head's height, else (reach fallback) at the highest body point under it the arms get to.
    for (int part = 0; part < (m_settings.reach_fallback ? 4 : 1); ++part) {
        const double height = m_head.y() - drop_under_head_m(part, m_head);
        double reach = 0.0;
        for (const Limb arm : {Limb::arm_l, Limb::arm_r}) {
            const LimbChain& limb = anatomy.limbs[int(arm)];
            const Eigen::Vector3d shoulder = m_heading.to_heading(positions[limb.root]);
            const double span = 0.9 * limb.length(), rise = height - positions[limb.root].y();
            if (std::abs(rise) < span) reach = std::max(reach, shoulder.z() + std::sqrt(span * span - rise * rise));
        }
        if (reach > 0.0) return reach + 0.1 * anatomy.leg_length;
    }
    return 0.0;
}

void Fighter::start_strike(double t_s) {
    Body& body = *m_bodies[m_character];
    body.rig->measure(m_pose.view());
    body.rig->still_feature(m_feature);
    RetrievalQuery query;
    query.pose_feature = m_feature;
    query.heading = body.rig->heading();
    query.semantics = m_pending_order.semantics;
    query.side = m_pending_order.side;
    query.kind = m_pending_order.kind;
    query.height = m_pending_order.height;
    query.character = body.rig->size();
    // The head, else the highest point of the body a strike reaches.
    const int parts = m_settings.reach_fallback ? 4 : 1;
    // An order may wait a little: for reach (the approach goes on meanwhile), and with predicted aim while the user
    // is changing course (just turned, stopped or started: the extrapolation would be wrong).
    const bool waiting_allowed = t_s - m_pending_since_s < m_settings.wait_for_reach_s;
    if (m_settings.aim == FighterAim::predicted && waiting_allowed && m_head_motion.ready() && !m_head_motion.settled()) return;
    // The first round looks at every part, as many per step as the planning budget lets it (all at once unless many
    // fighters plan in the same frame); while the order waits, one part per frame, in turn from the head down (each
    // look is a retrieval and the adaptation's planning: a hundred fighters waiting at once stay cheap).
    const int first = m_pending_part;
    const int last = m_pending_tried ? first + 1 : std::min(parts, first + std::max(1, m_plan_parts));
    RetrievalResult found;
    Eigen::Vector3d target = m_head;
    int part = first;
    bool reachable = false;
    for (; part < last; ++part) {
        found = retrieve_strike(query, drop_under_head_m(part, m_head), target);
        if (!found.found) break;
        if (plan_strike(found, target) <= m_settings.reach_tolerance_m) {
            reachable = true;
            break;
        }
    }
    if (found.found && !reachable && !m_pending_tried && last < parts) {
        m_pending_part = last; // the first round goes on at the next step
        return;
    }
    if (found.found && !reachable) {
        // Nothing reaches. When stepping in can help (a step is under way, or the user is beyond the band and the
        // database has a step forward), the fighter steps in first and strikes when in reach; otherwise, or when
        // that takes too long, it strikes at the head as the paper's fighter does.
        const bool closer_helps = m_state == FighterState::approach || (m_step_clips[0] >= 0 && distance_to_user() > band_far_m());
        // ... and when steps at the step clip's pace can close the gap in the time left to wait.
        const int step = m_step_clips[0];
        const double step_s = step >= 0 ? (m_db.clips[step].frame_count - 1) * double(m_db.meta.frame_time_s) : 0.0;
        const double step_speed_mps = step_s > 0.0 ? clip_stride_m(step) / step_s : 0.0;
        const double time_left_s = m_settings.wait_for_reach_s - (t_s - m_pending_since_s);
        const bool in_time = distance_to_user() - band_far_m() < step_speed_mps * time_left_s;
        // A walking user may also come within reach by themselves: predicted aim watches for it.
        const bool user_may_come = m_settings.aim == FighterAim::predicted && m_head_motion.velocity().norm() > 0.2;
        if (waiting_allowed && closer_helps && (in_time || user_may_come)) {
            m_pending_tried = true;
            m_pending_part = last % parts;
            return;
        }
        part = 0;
        found = retrieve_strike(query, 0.0, target);
        plan_strike(found, target);
    }
    m_pending = false;
    if (!found.found) return emit_ignored(t_s, "no strike of that kind can start from here");
    m_strike_part = k_target_parts[part];
    m_strike_drop_m = drop_under_head_m(part, m_head);
    m_strike_reachable = reachable;
    m_strike_aim = m_settings.aim;
    m_strike_head_speed_mps = m_head_motion.velocity().norm();
    m_strike_offset_m = found.d_target_m;
    m_strike_start_s = t_s;
    m_contact_done = false;
    m_strike_overshoot_m = 0.0;
    m_strike_violations = 0;
    m_strike_impact = true;
    m_previous_effector_s = -1.0;
    m_strike_order = m_pending_order;
    m_strike_varied = m_pending_varied;
    remember_strike(found.clip);
    m_strike_range_m = distance_to_user();
    m_planned_target = m_plan.target_world;
    emit_order_event(FighterEvent::Type::order_performed, m_strike_order, m_pending_ordered_s);
    enter(FighterState::strike, t_s); // plan_strike began the adaptation
}

RetrievalResult Fighter::retrieve_strike(RetrievalQuery& query, double drop_m, Eigen::Vector3d& target) {
    const Eigen::Vector3d drop(0.0, drop_m, 0.0);
    target = m_pending_head - drop; // latched: where the head was at the order
    query.target_world = target;
    RetrievalResult found = query_with_variety(query, m_pending_varied);
    if (m_settings.aim != FighterAim::predicted || !m_head_motion.ready()) return found;
    // The contact time depends on the strike, and the strike on the target: a few rounds settle both (each moves
    // the target by the head's speed times the change of contact time; they stop within a centimetre).
    for (int round = 0; round < 3 && found.found; ++round) {
        const Eigen::Vector3d predicted = m_head_motion.predict(found.time_to_contact_s) - drop;
        if ((predicted - target).norm() < 0.01) break;
        target = predicted;
        query.target_world = target;
        found = query_with_variety(query, m_pending_varied);
    }
    return found;
}

double Fighter::plan_strike(const RetrievalResult& found, const Eigen::Vector3d& target) {
    if (!found.found) return 1e9;
    m_plan = {found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target};
    m_strike_start = m_mir;
    m_strike_impact = true;
    begin_strike();
    return (m_bodies[m_character]->adapter.stop_point() - target).norm();
}

} // namespace kumite
