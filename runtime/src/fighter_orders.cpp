// The fighter's orders (fighter.h): taken at once, or queued while it is busy and served when it is free, or
// expired; refused when the database cannot serve them; and whether its next step would plan a strike (the
// planning budget asks). Every order ends once: performed, refused or expired.

#include "kumite/runtime/fighter.h"

namespace kumite {

bool Fighter::order(const StrikeOrder& order) {
    const char* why = "";
    if (!order_fits(order, why)) { // the pending and waiting orders, if any, stay as they were
        emit_order_event(FighterEvent::Type::ignored_order, order, m_now_s, why);
        return false;
    }
    if (!busy()) {
        emit_order_event(FighterEvent::Type::order, order, m_now_s);
        take_order(order);
        m_pending_ordered_s = m_now_s;
        return true;
    }
    if (m_settings.order_wait_s <= 0.0) {
        emit_order_event(FighterEvent::Type::ignored_order, order, m_now_s, m_defence.active() ? "defending" : "already striking");
        return false;
    }
    // The latest order waits; one already waiting gives way to it.
    if (m_queued) emit_order_event(FighterEvent::Type::order_expired, m_queued_order, m_queued_since_s, "a later order took its place");
    m_queued = true;
    m_queued_order = order;
    m_queued_since_s = m_now_s;
    emit_order_event(FighterEvent::Type::order_queued, order, m_now_s);
    return true;
}

FighterEvent Fighter::order_event(FighterEvent::Type type, double t_s, const StrikeOrder& order) {
    FighterEvent event;
    event.type = type;
    event.t_s = t_s;
    event.semantics = order.semantics;
    event.side = order.side;
    event.kind = order.kind;
    event.height = order.height;
    return event;
}

void Fighter::emit_order_event(FighterEvent::Type type, const StrikeOrder& order, double since_s, const char* why) {
    FighterEvent event = order_event(type, m_now_s, order);
    event.why = why;
    event.waited_s = m_now_s - since_s;
    push_event(event);
}

bool Fighter::wants_to_plan() const {
    // As step() decides, from the state before it: a queued order becomes pending in the step when the fighter is
    // free, so it wants to plan too.
    const bool free_to_strike = (m_state == FighterState::rest || m_state == FighterState::approach) && !m_defence.active();
    return free_to_strike && m_tracking && (m_pending || m_queued);
}

bool Fighter::busy() const {
    return m_state == FighterState::strike || m_state == FighterState::recover || m_pending || m_defence.active();
}

void Fighter::take_order(const StrikeOrder& order) {
    m_pending_order = order;
    m_pending = true;
    m_pending_since_s = m_now_s;
    m_pending_head = m_head;
    m_pending_tried = false;
    m_pending_part = 0;
}

void Fighter::serve_queue(double t_s) {
    if (!m_queued) return;
    if (t_s - m_queued_since_s > m_settings.order_wait_s) {
        m_queued = false;
        return emit_order_event(FighterEvent::Type::order_expired, m_queued_order, m_queued_since_s, "waited too long");
    }
    if (busy()) return;
    m_queued = false;
    take_order(m_queued_order);
    m_pending_ordered_s = m_queued_since_s;
}

bool Fighter::order_fits(const StrikeOrder& order, const char*& why) const {
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

void Fighter::emit_ignored(double, const char* why) {
    emit_order_event(FighterEvent::Type::ignored_order, m_pending_order, m_pending_ordered_s, why);
}

} // namespace kumite
