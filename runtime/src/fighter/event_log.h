#pragma once
// The fighter's events of one step (fighter_event.h). Owns: a fixed array (64 a step; more are dropped, nothing
// allocates). Every part writes its own events here, in the order they happen; the Bout reads and clears them.

#include "kumite/runtime/fighter_event.h"

#include <array>
#include <span>

namespace kumite {

class EventLog {
public:
    void push(const FighterEvent& event) {
        if (m_count < static_cast<int>(m_events.size())) m_events[m_count++] = event;
    }
    std::span<const FighterEvent> events() const { return {m_events.data(), std::size_t(m_count)}; }
    void clear() { m_count = 0; }

    // An event of `type` at `t_s` with what `order` asked for (semantics, side, kind, height).
    static FighterEvent of_order(FighterEvent::Type type, double t_s, const StrikeOrder& order) {
        FighterEvent event;
        event.type = type;
        event.t_s = t_s;
        event.semantics = order.semantics;
        event.side = order.side;
        event.kind = order.kind;
        event.height = order.height;
        event.combination = order.combination;
        event.blow = order.blow;
        event.own = order.own;
        return event;
    }
    // An event of `type` at `t_s` with nothing else (tracker lost or back, ...).
    static FighterEvent at(FighterEvent::Type type, double t_s) {
        FighterEvent event;
        event.type = type;
        event.t_s = t_s;
        return event;
    }

private:
    std::array<FighterEvent, 64> m_events;
    int m_count = 0;
};

} // namespace kumite
