#include "fighter/strike_planner.h"

#include "fighter/strike_aim.h"

#include <algorithm>
#include <limits>

namespace kumite {

StrikePlanner::StrikePlanner(const MotionDatabaseView& db, const Retriever& retriever, const FighterSettings& settings)
    : m_db(db), m_retriever(retriever), m_wait_for_reach_s(settings.wait_for_reach_s), m_reach_tolerance_m(settings.reach_tolerance_m),
      m_variety_margin(settings.variety_margin), m_variety_recent(settings.variety_recent), m_reach_fallback(settings.reach_fallback), m_surface_depth_m(settings.surface_depth_m),
      m_workspace(retriever.make_workspace()) {}

StrikePlanner::Outcome StrikePlanner::plan(double t_s, FighterAim aim, bool approaching, OrderQueue& orders, CharacterBody& body,
                                           const TrackedUser& user, const Footwork& footwork, Strike& strike) {
    CharacterRig& rig = *body.current().rig;
    rig.measure(body.pose().view());
    rig.still_feature(m_feature);
    const PendingOrder& pending = orders.pending();
    RetrievalQuery query;
    query.pose_feature = m_feature;
    query.heading = rig.heading();
    query.semantics = pending.order.semantics;
    query.side = pending.order.side;
    query.kind = pending.order.kind;
    query.height = pending.order.height;
    query.character = rig.size();
    // The head, else the highest point of the body a strike reaches; against a guard, the highest it leaves open.
    const UserGuard& guard = user.guard();
    const bool openings = guard.settings().enabled && guard.settings().aim_at_openings && pending.order.height == StrikeHeight::none &&
                          user.tracking() && (user.hands().present[0] || user.hands().present[1]);
    // From the part its height names (the head, unless it asked for the body) down.
    const int top = first_target_part(pending.order.height);
    const int parts = m_reach_fallback || openings ? k_target_part_count : top + 1;
    // An order may wait a little: for reach (the approach goes on meanwhile), and with predicted aim while the user
    // is changing course (just turned, stopped or started: the extrapolation would be wrong).
    const bool waiting_allowed = t_s - pending.since_s < m_wait_for_reach_s;
    if (aim == FighterAim::predicted && waiting_allowed && user.motion().ready() && !user.motion().settled()) return Outcome::waiting;
    // A user pressed against the fighter (nearer than the strike band, or than its near end for the shortest strikes
    // when none reached from the band: an elbow, a knee) is not struck from there: it steps back first (the footwork's
    // step out of the band), as long as the order may wait.
    if (waiting_allowed && user.tracking() && user.distance_from(body.heading().origin) < footwork.near_m(body, user, pending.tried)) return Outcome::waiting;
    // The first round looks at every part, as many per step as the planning budget lets it (all at once unless many
    // fighters plan in the same frame); while the order waits, one part per frame, in turn from the head down (each
    // look is a retrieval and the adaptation's planning: a hundred fighters waiting at once stay cheap).
    const int first = pending.part;
    const int last = pending.tried ? first + 1 : std::min(parts, first + std::max(1, m_plan_parts));
    RetrievalResult found;
    Eigen::Vector3d target = user.head();
    int part = first;
    bool reachable = false;
    int covered = -1; // the first part reached whose strike the guard would meet first
    for (; part < last; ++part) {
        found = retrieve(query, aim_offset(part, user.head(), body.heading().origin, m_surface_depth_m), aim, pending, user, target);
        if (!found.found) break;
        if (strike.try_plan(found, target, body.mir(), body) <= m_reach_tolerance_m) {
            if (openings && strike.guard_in_the_way(body, guard)) {
                if (covered < 0) covered = part;
                continue;
            }
            reachable = true;
            break;
        }
    }
    if (!reachable && covered >= 0) { // every part it reaches is covered: the first of them, into the guard
        part = covered;
        found = retrieve(query, aim_offset(part, user.head(), body.heading().origin, m_surface_depth_m), aim, pending, user, target);
        reachable = found.found && strike.try_plan(found, target, body.mir(), body) <= m_reach_tolerance_m;
    }
    if (found.found && !reachable && !pending.tried && last < parts) {
        orders.look_next(last); // the first round goes on at the next step
        return Outcome::waiting;
    }
    if (found.found && !reachable) {
        // Nothing reaches. When stepping in can help (a step is under way, or the user is beyond the band and the
        // database has a step forward), the fighter steps in first and strikes when in reach; otherwise, or when
        // that takes too long, it strikes at the part its height names (the head unless asked for the body), as the
        // paper's fighter strikes at the head.
        const int step = footwork.step_forward_clip();
        const double distance = user.distance_from(body.heading().origin);
        // (A short strike — an elbow, a knee — may not reach from inside the band either: closer helps while the
        // fighter is not yet at its near end.)
        const double closer_m = footwork.close_near_m(body.leg_length()) + Footwork::k_min_band_legs * body.leg_length();
        const bool closer_helps = approaching || (step >= 0 && distance > std::min(closer_m, footwork.far_m(body, user)));
        // ... and when steps at the step clip's pace can close the gap in the time left to wait.
        const double step_s = footwork.duration_s(step);
        const double step_speed_mps = step_s > 0.0 ? footwork.stride_m(step, body.leg_length()) / step_s : 0.0;
        const double time_left_s = m_wait_for_reach_s - (t_s - pending.since_s);
        const bool in_time = distance - footwork.far_m(body, user) < step_speed_mps * time_left_s;
        // A walking user may also come within reach by themselves: predicted aim watches for it.
        const bool user_may_come = aim == FighterAim::predicted && user.motion().velocity().norm() > 0.2;
        // A step under way may finish (the fighter now rests out of reach and steps in for an order): up to twice
        // the wait.
        const bool step_may_finish = approaching && t_s - pending.since_s < 2.0 * m_wait_for_reach_s;
        if ((waiting_allowed || step_may_finish) && closer_helps && (in_time || user_may_come || step_may_finish)) {
            orders.wait_for_reach(last < parts ? last : top);
            return Outcome::waiting;
        }
        part = top;
        found = retrieve(query, aim_offset(top, user.head(), body.heading().origin, m_surface_depth_m), aim, pending, user, target);
        strike.try_plan(found, target, body.mir(), body);
    }
    if (!found.found) return Outcome::refused;
    Strike::Purpose purpose;
    purpose.part = k_target_parts[part];
    purpose.aim_offset = aim_offset(part, user.head(), body.heading().origin, m_surface_depth_m);
    purpose.reachable = reachable;
    purpose.aim = aim;
    purpose.head_speed_mps = user.motion().velocity().norm();
    purpose.retrieval_offset_m = found.d_target_m;
    purpose.order = pending.order;
    purpose.varied = m_varied;
    remember(found.clip);
    purpose.range_m = user.distance_from(body.heading().origin);
    strike.start(t_s, purpose);
    return Outcome::begun;
}

RetrievalResult StrikePlanner::retrieve(RetrievalQuery& query, const Eigen::Vector3d& offset, FighterAim aim, const PendingOrder& pending,
                                        const TrackedUser& user, Eigen::Vector3d& target) {
    target = pending.head + offset; // latched: where the head was at the order
    query.target_world = target;
    RetrievalResult found = query_with_variety(query);
    if (aim != FighterAim::predicted || !user.motion().ready()) return found;
    // The contact time depends on the strike, and the strike on the target: a few rounds settle both (each moves
    // the target by the head's speed times the change of contact time; they stop within a centimetre).
    for (int round = 0; round < 3 && found.found; ++round) {
        const Eigen::Vector3d predicted = user.motion().predict(found.time_to_contact_s) + offset;
        if ((predicted - target).norm() < 0.01) break;
        target = predicted;
        query.target_world = target;
        found = query_with_variety(query);
    }
    return found;
}

void StrikePlanner::remember(int clip) {
    m_recent_clips[m_recent_next] = clip;
    m_recent_next = (m_recent_next + 1) % k_max_variety_recent;
    m_recent_count = std::min(m_recent_count + 1, k_max_variety_recent);
}

RetrievalResult StrikePlanner::query_with_variety(RetrievalQuery& query) {
    m_varied = false;
    query.excluded_clips = {};
    query.score_limit = std::numeric_limits<double>::infinity();
    RetrievalResult best = m_retriever.query(query, m_workspace);
    const int recent = std::min({m_variety_recent, m_recent_count, k_max_variety_recent});
    if (!best.found || recent <= 0 || m_variety_margin <= 0.0) return best;
    // The last `recent` clips, newest first: m_recent_clips is a ring.
    std::array<int, k_max_variety_recent> excluded{};
    for (int k = 0; k < recent; ++k) excluded[k] = m_recent_clips[(m_recent_next - 1 - k + k_max_variety_recent) % k_max_variety_recent];
    if (std::find(excluded.begin(), excluded.begin() + recent, best.clip) == excluded.begin() + recent) return best;
    query.excluded_clips = std::span<const int>(excluded.data(), recent);
    query.score_limit = best.score + m_variety_margin;
    RetrievalResult other = m_retriever.query(query, m_workspace);
    query.excluded_clips = {};
    query.score_limit = std::numeric_limits<double>::infinity();
    if (!other.found) return best;
    m_varied = true;
    return other;
}

} // namespace kumite
