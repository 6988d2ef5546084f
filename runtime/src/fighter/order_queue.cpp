#include "fighter/order_queue.h"

#include "fighter/strike_aim.h"

namespace kumite {

bool OrderQueue::offer(const StrikeOrder& order, double now_s, bool busy, bool defending, const Eigen::Vector3d& head, EventLog& log) {
    const char* why = "";
    if (!fits(order, why)) { // the pending and waiting orders, if any, stay as they were
        emit(FighterEvent::Type::ignored_order, order, now_s, now_s, log, why);
        return false;
    }
    if (order.blow > 0) { // a combination's later blow: after the one just offered, whatever the fighter is doing
        if (m_has_follow_up) emit(FighterEvent::Type::order_expired, m_follow_up, now_s, m_follow_up_since_s, log, "a later order took its place");
        m_has_follow_up = true;
        m_follow_up_of_queued = m_has_queued;
        m_follow_up = order;
        m_follow_up_since_s = now_s;
        emit(FighterEvent::Type::order_queued, order, now_s, now_s, log);
        return true;
    }
    if (!busy) {
        emit(FighterEvent::Type::order, order, now_s, now_s, log);
        take(order, now_s, head);
        m_pending.ordered_s = now_s;
        return true;
    }
    if (m_wait_s <= 0.0) {
        emit(FighterEvent::Type::ignored_order, order, now_s, now_s, log, defending ? "defending" : "already striking");
        return false;
    }
    // The latest order waits; one already waiting gives way to it.
    if (m_has_queued) {
        emit(FighterEvent::Type::order_expired, m_queued, now_s, m_queued_since_s, log, "a later order took its place");
        end_follow_up(true, now_s, "a later order took the place of the blow before it", log);
    }
    m_has_queued = true;
    m_queued = order;
    m_queued_since_s = now_s;
    emit(FighterEvent::Type::order_queued, order, now_s, now_s, log);
    return true;
}

void OrderQueue::serve(double now_s, bool busy, const Eigen::Vector3d& head, EventLog& log) {
    if (!m_has_queued) return;
    if (now_s - m_queued_since_s > m_wait_s) {
        m_has_queued = false;
        end_follow_up(true, now_s, "the blow before it waited too long", log);
        return emit(FighterEvent::Type::order_expired, m_queued, now_s, m_queued_since_s, log, "waited too long");
    }
    if (busy) return;
    m_has_queued = false;
    m_follow_up_of_queued = false; // its blow before is the pending one now
    take(m_queued, now_s, head);
    m_pending.ordered_s = m_queued_since_s;
}

void OrderQueue::performed(double now_s, EventLog& log) {
    m_has_pending = false;
    emit(FighterEvent::Type::order_performed, m_pending.order, now_s, m_pending.ordered_s, log);
    if (m_has_follow_up && !m_follow_up_of_queued) m_follow_up_since_s = now_s; // it waits from the blow's start
}

void OrderQueue::refuse(double now_s, const char* why, EventLog& log) {
    m_has_pending = false;
    emit(FighterEvent::Type::ignored_order, m_pending.order, now_s, m_pending.ordered_s, log, why);
    end_follow_up(false, now_s, "the blow before it was refused", log);
}

bool OrderQueue::take_follow_up(double now_s, const Eigen::Vector3d& head) {
    if (!m_has_follow_up || m_follow_up_of_queued || m_has_pending) return false;
    m_has_follow_up = false;
    take(m_follow_up, now_s, head);
    m_pending.ordered_s = m_follow_up_since_s;
    return true;
}

void OrderQueue::end_follow_up(bool of_queued, double now_s, const char* why, EventLog& log) {
    if (!m_has_follow_up || m_follow_up_of_queued != of_queued) return;
    m_has_follow_up = false;
    emit(FighterEvent::Type::order_expired, m_follow_up, now_s, m_follow_up_since_s, log, why);
}

bool OrderQueue::fits(const StrikeOrder& order, const char*& why) const {
    if (order.semantics < 0) {
        why = "the database has no such strike";
        return false;
    }
    if (m_retriever.candidate_count(order.semantics, order.side, order.kind, order.height) == 0) {
        why = "the database has no strike of that side, kind and height";
        return false;
    }
    return true;
}

void OrderQueue::take(const StrikeOrder& order, double now_s, const Eigen::Vector3d& head) {
    m_pending.order = order;
    m_has_pending = true;
    m_pending.since_s = now_s;
    m_pending.head = head;
    m_pending.tried = false;
    m_pending.part = first_target_part(order.height);
}

void OrderQueue::emit(FighterEvent::Type type, const StrikeOrder& order, double now_s, double since_s, EventLog& log, const char* why) {
    FighterEvent event = EventLog::of_order(type, now_s, order);
    event.why = why;
    event.waited_s = now_s - since_s;
    log.push(event);
}

} // namespace kumite
