// The user's answers to the fighter's blows (response_watch.h, user_response.h).

#include "fighter/response_watch.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_late_window_s = 0.3;  // an answer begun this long after the contact still counts (late)
constexpr double k_parry_reach_m = 0.25; // a glove that crosses the blow's line, and goes on past it by between
constexpr double k_parry_past_m = 0.08;  // these, went across its path (a parry); one that stops on it, a block
constexpr double k_on_path_m = 0.15;     // a glove this near the blow's line (its 10 cm and a fist's 5 cm) is on its path
constexpr double k_line_from_target_m = 0.15; // the blow's line from where its part was when still this far out
constexpr double k_counter_land_s = 0.6; // a counter begun at the window's end has landed or not by this much later
constexpr double k_longest_blow_s = 4.0; // a strike with no contact by then is let go

Eigen::Vector3d unit_or_zero(const Eigen::Vector3d& v) { return v.norm() > 1e-9 ? Eigen::Vector3d(v.normalized()) : Eigen::Vector3d::Zero(); }

// From the line through `point` along `way` (unit) to `p`, square to it.
Eigen::Vector3d off_line(const Eigen::Vector3d& p, const Eigen::Vector3d& point, const Eigen::Vector3d& way) {
    const Eigen::Vector3d offset = p - point;
    return offset - offset.dot(way) * way;
}

} // namespace

void ResponseWatch::watch(double t_s, const Blow& blow, const TrackedUser& user, EventLog& log) {
    const double dt_s = m_have_previous ? t_s - m_previous_s : 0.0;
    for (const FighterEvent& event : log.events()) {
        if (m_have_previous && event.t_s <= m_previous_s) continue; // read last frame (a log nobody cleared)
        if (event.type == FighterEvent::Type::state && event.state == FighterState::strike) {
            Watched* slot = &m_watched[0];
            for (Watched& candidate : m_watched) { // a free slot, else the oldest blow (finished early)
                if (!candidate.active) { slot = &candidate; break; }
                if (candidate.response.began_s < slot->response.began_s) slot = &candidate;
            }
            if (slot->active) finish(t_s, *slot, log);
            *slot = Watched{};
            slot->active = true;
            slot->response.began_s = event.t_s;
            slot->rising_s.fill(-1.0);
            const Eigen::Vector3d to_user = user.head() - blow.fighter;
            slot->floor_way = unit_or_zero(Eigen::Vector3d(to_user.x(), 0.0, to_user.z()));
            m_newest = int(slot - m_watched.data());
            m_have_previous_point = false;
        } else if (event.type == FighterEvent::Type::strike && m_newest >= 0 && m_watched[m_newest].active && !m_watched[m_newest].have_contact) {
            Watched& watched = m_watched[m_newest];
            watched.have_contact = true;
            watched.strike = event;
            watched.response.contact_s = event.t_s;
        } else if (event.type == FighterEvent::Type::user_strike && !event.user_strike.ended) {
            for (Watched& watched : m_watched) {
                UserResponse& r = watched.response;
                if (!watched.active || !watched.have_contact || r.countered || event.t_s < r.contact_s || event.t_s > r.contact_s + m_settings.counter_window_s) continue;
                r.countered = true;
                r.counter_s = event.t_s;
                watched.counter_hand = event.user_strike.hand; // to find how it ended
            }
        } else if (event.type == FighterEvent::Type::user_strike_end && event.user_strike.ended) {
            for (Watched& watched : m_watched) {
                UserResponse& r = watched.response;
                if (watched.active && r.countered && !r.counter_landed && watched.counter_hand == event.user_strike.hand &&
                    event.user_strike.outcome == UserStrikeOutcome::hit_by_user) {
                    r.counter_landed = true;
                }
            }
        }
    }
    for (Watched& watched : m_watched) {
        if (!watched.active) continue;
        if (m_have_previous && dt_s > 0.0) follow(t_s, dt_s, watched, blow, user);
        const UserResponse& r = watched.response;
        const bool over = r.contact_s >= 0.0 ? t_s >= r.contact_s + m_settings.counter_window_s + k_counter_land_s : t_s >= r.began_s + k_longest_blow_s;
        if (over) finish(t_s, watched, log);
    }
    m_have_previous = user.tracking();
    m_previous_s = t_s;
    m_previous_head = user.head();
    m_previous_hands = user.hands();
    if (blow.striking) {
        m_previous_point_from_fighter = blow.point - blow.fighter;
        m_have_previous_point = true;
    }
}

void ResponseWatch::follow(double t_s, double dt_s, Watched& watched, const Blow& blow, const TrackedUser& user) {
    UserResponse& r = watched.response;
    const bool newest = &watched == &m_watched[std::size_t(std::max(0, m_newest))];
    if (newest && blow.striking && !watched.have_contact) {
        // The blow's path as it comes, and the frame it becomes visible: its striking part leaving the guard, moving
        // on the fighter's body (in any direction: a hook's swing and a kick's chamber show before they close in).
        if (m_have_previous_point && r.visible_s < 0.0) {
            const double speed = ((blow.point - blow.fighter - m_previous_point_from_fighter) / dt_s).norm();
            if (speed > m_settings.blow_visible_mps) r.visible_s = t_s;
        }
        if (!watched.have_line || (blow.target - blow.point).norm() > k_line_from_target_m) watched.point = blow.point;
        else watched.line_final = true;
        watched.target = blow.target;
        watched.have_line = true;
    }
    const bool answering = !r.moved && (r.contact_s < 0.0 || t_s <= r.contact_s + k_late_window_s);
    if (!watched.have_line || !user.tracking()) return;
    const Eigen::Vector3d along = unit_or_zero(watched.target - watched.point); // the blow's way
    // Across the line as the blow arrives (within 15 cm of its target, or its contact): where the glove rose on one
    // side, where it is now on the other.
    const bool line_final = watched.line_final || (r.contact_s >= 0.0 && t_s >= r.contact_s);
    if (watched.glove_side >= 0 && r.moved && !watched.crossed && line_final && (r.contact_s < 0.0 || t_s <= r.contact_s)) {
        if (user.hands().present[watched.glove_side]) {
            const Eigen::Vector3d offset = off_line(user.hands().world[watched.glove_side], watched.point, along);
            const Eigen::Vector3d rose = off_line(watched.glove_at_rise, watched.point, along);
            watched.crossed = offset.dot(rose) < 0.0 && offset.norm() >= k_parry_past_m && offset.norm() <= k_parry_reach_m;
        }
    }
    if (!answering) return;
    // The head against the blow's way on the floor (from the fighter to the user): back along it, or off it.
    const Eigen::Vector3d& floor_way = watched.floor_way;
    const Eigen::Vector3d head_velocity = (user.head() - m_previous_head) / dt_s;
    std::array<double, k_channels> speed{};
    speed[head_back] = head_velocity.dot(floor_way);
    speed[head_off_line] = (head_velocity - head_velocity.dot(floor_way) * floor_way).norm();
    for (int side = 0; side < 2; ++side) {
        const bool present = user.hands().present[side] && m_previous_hands.present[side];
        if (!present) continue;
        const Eigen::Vector3d& glove = user.hands().world[side];
        const Eigen::Vector3d own = (glove - m_previous_hands.world[side]) / dt_s - head_velocity; // the arm's own motion
        const Eigen::Vector3d to_path = nearest_on_segment(glove, watched.point, watched.target) - glove;
        speed[glove_left + side] = own.dot(unit_or_zero(to_path));
        // A glove already on the path (the guard) answers by moving along it too: into the face (a cover) or out to
        // meet the blow.
        if (to_path.norm() <= k_on_path_m) speed[glove_left + side] = std::max(speed[glove_left + side], std::abs(own.dot(along)));
    }
    // The first channel over its threshold that was under it since the strike began, held a second frame.
    Channel answered = k_channels;
    for (int c = 0; c < k_channels; ++c) {
        const double threshold = c == head_back || c == head_off_line ? m_settings.head_mps : m_settings.glove_mps;
        if (speed[c] <= threshold) {
            watched.was_below[c] = true;
            watched.rising_s[c] = -1.0;
            continue;
        }
        if (!watched.was_below[c]) continue;
        if (watched.rising_s[c] < 0.0) {
            watched.rising_s[c] = t_s;
            if (c == head_off_line) watched.downwards = -head_velocity.y() > speed[head_off_line] * 0.7071;
            continue;
        }
        if (answered == k_channels || watched.rising_s[c] < watched.rising_s[answered]) answered = Channel(c);
    }
    if (answered != k_channels) answer(watched, answered, watched.rising_s[answered], user);
}

void ResponseWatch::answer(Watched& watched, Channel channel, double rose_s, const TrackedUser& user) {
    UserResponse& r = watched.response;
    r.moved = true;
    r.response_s = rose_s;
    switch (channel) {
    case head_back: r.kind = ResponseKind::step_back; break;
    case head_off_line: r.kind = watched.downwards ? ResponseKind::duck : ResponseKind::slip; break;
    case glove_left:
    case glove_right: {
        r.kind = ResponseKind::block; // a parry once it goes on across the path (follow)
        watched.glove_side = channel == glove_left ? 0 : 1;
        watched.glove_at_rise = user.hands().world[watched.glove_side];
        break;
    }
    case k_channels: break;
    }
}

void ResponseWatch::finish(double t_s, Watched& watched, EventLog& log) {
    UserResponse& r = watched.response;
    watched.active = false;
    if (!watched.have_contact) return; // no contact (cut short): no blow to answer
    if (r.moved && r.kind == ResponseKind::block && watched.crossed) r.kind = ResponseKind::parry;
    const bool blocked_held = !r.moved && watched.strike.user_block != GuardPart::none;
    if (blocked_held) r.kind = ResponseKind::block;
    if (r.moved && r.visible_s >= 0.0) r.response_time_s = r.response_s - r.visible_s;
    const bool landed = watched.strike.hit;
    r.quality = blocked_held ? ResponseQuality::in_time
                : !r.moved   ? ResponseQuality::none
                : landed || r.response_s > r.contact_s ? ResponseQuality::late
                             : ResponseQuality::in_time;
    FighterEvent event = watched.strike;
    event.type = FighterEvent::Type::user_response;
    event.t_s = t_s;
    event.response = r;
    log.push(event);
}

} // namespace kumite
