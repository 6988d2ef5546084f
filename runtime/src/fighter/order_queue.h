#pragma once
// The supervisor's orders (fighter.h): one pending (taken, the strike not begun yet) and one queued (waiting while
// the fighter is busy); refused when the database cannot serve them, expired when they wait too long or a later one
// takes their place. A combination's later blow waits beside them, for the end of the blow before it (taken then,
// from its recoil), and ends with it when that one is refused or expires. Every order ends once: performed, refused
// or expired. Owns: the pending and the queued order,
// when each came, the head at the pending order (latched aim), how far the look for reach has got. Touches: the
// event log (order events). Reads: the retriever (which strikes exist); the fighter tells it whether it is busy.

#include "fighter/event_log.h"

#include "kumite/core/retrieval.h"

#include <Eigen/Core>

namespace kumite {

// The order the fighter is about to carry out.
struct PendingOrder {
    StrikeOrder order;
    double since_s = 0.0;                              // taken (later than ordered_s if it waited)
    double ordered_s = 0.0;                            // when the supervisor gave it
    Eigen::Vector3d head = Eigen::Vector3d::Zero();    // the head when it was taken (latched aim)
    bool tried = false;                                // every part was looked at once: it waits for reach
    int part = 0;                                      // the target part to look at next
};

class OrderQueue {
public:
    OrderQueue(const Retriever& retriever, double wait_s) : m_retriever(retriever), m_wait_s(wait_s) {}

    // An order at `now_s`: taken when the fighter is not `busy`, else queued (or refused when orders may not wait:
    // `defending` says why). False when refused.
    bool offer(const StrikeOrder& order, double now_s, bool busy, bool defending, const Eigen::Vector3d& head, EventLog& log);
    // The queued order: taken when the fighter is no longer busy, expired when it waited too long.
    void serve(double now_s, bool busy, const Eigen::Vector3d& head, EventLog& log);

    bool has_pending() const { return m_has_pending; }
    bool has_queued() const { return m_has_queued; }
    bool has_follow_up() const { return m_has_follow_up; }
    // The blow before the follow-up has ended: the follow-up becomes the pending order (true), from the recoil.
    bool take_follow_up(double now_s, const Eigen::Vector3d& head);
    const PendingOrder& pending() const { return m_pending; }
    double queued_since_s() const { return m_queued_since_s; }
    // The pending order's strike began (order_performed) or it cannot be carried out (ignored_order, with why).
    void performed(double now_s, EventLog& log);
    void refuse(double now_s, const char* why, EventLog& log);
    void drop() { m_has_pending = false; } // ended elsewhere (the refusal comes from refuse() after)
    // The look for reach: the first round goes on at `part` next step; or every part was looked at, it waits for
    // reach and looks at `part` next.
    void look_next(int part) { m_pending.part = part; }
    void wait_for_reach(int part) { m_pending.tried = true, m_pending.part = part; }

private:
    bool fits(const StrikeOrder& order, const char*& why) const;
    void take(const StrikeOrder& order, double now_s, const Eigen::Vector3d& head);
    // The follow-up of the order that ended (its first blow) ends with it.
    void end_follow_up(bool of_queued, double now_s, const char* why, EventLog& log);
    static void emit(FighterEvent::Type type, const StrikeOrder& order, double now_s, double since_s, EventLog& log, const char* why = "");

    const Retriever& m_retriever;
    double m_wait_s;
    bool m_has_pending = false;
    PendingOrder m_pending;
    bool m_has_queued = false;
    StrikeOrder m_queued;
    double m_queued_since_s = 0.0;
    bool m_has_follow_up = false;
    bool m_follow_up_of_queued = false; // its blow before is the queued order (else the pending one, or under way)
    StrikeOrder m_follow_up;
    double m_follow_up_since_s = 0.0;
};

} // namespace kumite
