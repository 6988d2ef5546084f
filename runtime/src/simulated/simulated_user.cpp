#include "kumite/runtime/simulated_user.h"

#include "kumite/core/smoothstep.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace kumite {
namespace {

constexpr double k_dodge_delay_s = 0.25; // from the order (dodge) or the strike's start (dodge-seen) to the dodge

// How far into a dodge `since` seconds after it began: out over 0.15 s, held, back over 0.15 s (1.3 s in all).
double dodge_amount(double since) {
    return since < 0.15 ? smoothstep(since / 0.15) : since < 1.15 ? 1.0 : 1.0 - smoothstep((since - 1.15) / 0.15);
}

} // namespace

std::optional<SimulatedKind> simulated_kind_from_name(std::string_view name) {
    if (name == "still") return SimulatedKind::still;
    if (name == "wander") return SimulatedKind::wander;
    if (name == "walk") return SimulatedKind::walk;
    if (name == "dodge") return SimulatedKind::dodge;
    if (name == "dodge-seen") return SimulatedKind::dodge_seen;
    if (name == "punch") return SimulatedKind::punch;
    if (name == "counter") return SimulatedKind::counter;
    return std::nullopt;
}

SimulatedUser::SimulatedUser(SimulatedKind kind, std::uint64_t seed, double walk_speed_mps)
    : m_kind(kind), m_random{seed}, m_walk_speed_mps(walk_speed_mps) {
    if (kind == SimulatedKind::counter) m_next_punch_s = 1e18; // only in reply
}

void SimulatedUser::on_order(double t_s) {
    if (m_kind != SimulatedKind::dodge) return;
    m_dodge_start_s = t_s + k_dodge_delay_s;
    ++m_dodges;
}

void SimulatedUser::set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding) {
    m_hands.set_opponent(head, chest);
    // The fighter left its guard (a strike began) since it was last seen: a dodge 0.25 s after that.
    if (m_kind == SimulatedKind::dodge_seen && m_opponent_guarding && !guarding) {
        m_dodge_start_s = m_seen_s + k_dodge_delay_s;
        ++m_dodges;
    }
    m_opponent_guarding = guarding;
}

Eigen::Vector3d SimulatedUser::head(double t_s) {
    m_seen_s = t_s;
    const Eigen::Vector3d start = start_position();
    switch (m_kind) {
    case SimulatedKind::still:
    case SimulatedKind::punch:
    case SimulatedKind::counter: return m_last_head = start;
    case SimulatedKind::wander:
    case SimulatedKind::walk: {
        const bool walk = m_kind == SimulatedKind::walk;
        const double speed = walk ? m_walk_speed_mps : 0.4;
        while (t_s >= m_leg_end_s) {
            m_from = m_to;
            for (int attempt = 0; attempt < 20; ++attempt) { // a walk's legs are long enough to be walks, not turns
                m_to = Eigen::Vector3d(m_random.uniform(-1.5, 1.5), k_head_height_m, start.z() + m_random.uniform(-1.0, 1.5));
                if (!walk || (m_to - m_from).norm() >= 1.5) break;
            }
            m_leg_start_s = m_leg_end_s;
            m_leg_end_s = m_leg_start_s + std::max(0.5, (m_to - m_from).norm() / speed);
        }
        const double s = (t_s - m_leg_start_s) / (m_leg_end_s - m_leg_start_s);
        return m_from + (m_to - m_from) * s;
    }
    case SimulatedKind::dodge:
    case SimulatedKind::dodge_seen: {
        const double since = t_s - m_dodge_start_s;
        if (since < 0.0 || since > 1.3) return start;
        const double amount = dodge_amount(since);
        const Eigen::Vector3d away = m_dodges % 2 == 1 ? Eigen::Vector3d(0.0, -0.45, 0.0) : Eigen::Vector3d(0.5, 0.0, 0.0);
        return start + amount * away;
    }
    }
    return start;
}

UserHands SimulatedUser::hands(double t_s) {
    if (m_kind != SimulatedKind::punch && m_kind != SimulatedKind::counter) return {};
    if (m_kind == SimulatedKind::counter) { // a reply when the fighter comes back to its guard, else none
        if (m_opponent_guarding && !m_opponent_was_guarding) m_next_punch_s = t_s + 0.3;
        m_opponent_was_guarding = m_opponent_guarding;
    }
    if (t_s >= m_next_punch_s && m_hands.has_opponent()) {
        const double speed = m_random.uniform(4.0, 8.0);
        m_hands.punch(t_s, m_punches % 2, (m_punches / 2) % 2 == 0, speed, m_random.uniform(0.6, 1.0));
        ++m_punches;
        m_next_punch_s = m_kind == SimulatedKind::counter ? 1e18 : t_s + m_random.uniform(1.6, 2.4);
    }
    return m_hands.hands(t_s, m_last_head);
}

UserHands ScriptedUser::hands(double t_s) {
    if (!m_has_hands) return {};
    return m_hands.hands(t_s, m_last_head);
}

Result<ScriptedUser> ScriptedUser::read(const std::string& path) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the user script");
    ScriptedUser user;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream words(line);
        Action action;
        std::string verb;
        auto fail = [&](const std::string& what) { return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": " + what); };
        if (!(words >> action.t_s >> verb) || !std::isfinite(action.t_s) || action.t_s < 0) return fail("expected '<time_s> <action>'");
        auto numbers = [&](int required, int optional, double* out) {
            int read = 0;
            for (; read < required + optional && (words >> out[read]); ++read) {
                if (!std::isfinite(out[read]) || std::abs(out[read]) > 100.0) return false;
            }
            std::string extra;
            return read >= required && !(words.clear(), words >> extra);
        };
        double values[3] = {0.0, 0.0, 0.8};
        if (verb == "at" || verb == "walk") {
            action.kind = verb == "at" ? Action::Kind::at : Action::Kind::walk;
            if (!numbers(2, verb == "walk" ? 1 : 0, values) || values[2] <= 0.0) return fail(verb + " takes X Z" + (verb == "walk" ? " [SPEED > 0]" : ""));
        } else if (verb == "crouch" || verb == "sidestep") {
            action.kind = verb == "crouch" ? Action::Kind::crouch : Action::Kind::sidestep;
            if (!numbers(1, 0, values)) return fail(verb + " takes one number (metres)");
        } else if (verb == "stand") {
            action.kind = Action::Kind::stand;
            if (!numbers(0, 0, values)) return fail("stand takes nothing");
        } else if (verb == "dodge") {
            action.kind = Action::Kind::dodge;
            std::string mode;
            words >> mode;
            action.dodge_mode = mode == "duck" ? 1 : mode == "side" ? 2 : mode == "off" ? 0 : -1;
            values[0] = k_dodge_delay_s;
            if (action.dodge_mode < 0 || !numbers(0, 1, values) || values[0] < 0.0) return fail("dodge takes duck, side or off, then an optional delay");
        } else if (verb == "punch") {
            action.kind = Action::Kind::punch;
            std::string hand, aim;
            words >> hand >> aim;
            action.side = hand == "left" ? 0 : hand == "right" ? 1 : -1;
            action.at_head = aim == "head";
            values[0] = 6.0;
            if (action.side < 0 || (aim != "head" && aim != "chest") || !numbers(0, 1, values) || !(values[0] >= 0.5 && values[0] <= 20.0)) {
                return fail("punch takes left or right, head or chest, then an optional speed (0.5 to 20 m/s)");
            }
            user.m_has_hands = true;
        } else {
            return fail("unknown action '" + verb + "' (at, walk, crouch, stand, sidestep, dodge, punch)");
        }
        action.a = values[0];
        action.b = values[1];
        action.c = values[2];
        user.m_actions.push_back(action);
    }
    std::stable_sort(user.m_actions.begin(), user.m_actions.end(), [](const Action& x, const Action& y) { return x.t_s < y.t_s; });
    return user;
}

void ScriptedUser::on_order(double t_s) {
    if (m_dodge_mode != 0) m_dodge_start_s = t_s + m_dodge_delay_s;
}

Eigen::Vector3d ScriptedUser::head(double t_s) {
    auto walked = [&](double t) {
        if (m_walk_end_s <= m_walk_start_s) return m_walk_to;
        return Eigen::Vector2d(m_walk_from + (m_walk_to - m_walk_from) * std::clamp((t - m_walk_start_s) / (m_walk_end_s - m_walk_start_s), 0.0, 1.0));
    };
    auto eased = [](double from, double to, double start, double t) { return from + (to - from) * smoothstep((t - start) / 0.2); };
    for (; m_next < m_actions.size() && m_actions[m_next].t_s <= t_s; ++m_next) {
        const Action& action = m_actions[m_next];
        const double now = action.t_s;
        switch (action.kind) {
        case Action::Kind::at:
            m_walk_from = m_walk_to = Eigen::Vector2d(action.a, action.b);
            m_walk_start_s = m_walk_end_s = now;
            break;
        case Action::Kind::walk: {
            m_walk_from = walked(now);
            m_walk_to = Eigen::Vector2d(action.a, action.b);
            m_walk_start_s = now;
            m_walk_end_s = now + (m_walk_to - m_walk_from).norm() / action.c;
            break;
        }
        case Action::Kind::crouch:
        case Action::Kind::stand:
            m_crouch_from = eased(m_crouch_from, m_crouch_to, m_crouch_start_s, now);
            m_crouch_to = action.kind == Action::Kind::crouch ? action.a : 0.0;
            m_crouch_start_s = now;
            break;
        case Action::Kind::sidestep:
            m_side_from = eased(m_side_from, m_side_to, m_side_start_s, now);
            m_side_to = m_side_from + action.a;
            m_side_start_s = now;
            break;
        case Action::Kind::dodge:
            m_dodge_mode = action.dodge_mode;
            m_dodge_delay_s = action.a;
            break;
        case Action::Kind::punch: m_hands.punch(now, action.side, action.at_head, action.a); break;
        }
    }
    const Eigen::Vector2d floor = walked(t_s);
    Eigen::Vector3d head(floor.x() + eased(m_side_from, m_side_to, m_side_start_s, t_s), SimulatedUser::k_head_height_m -
                                                                                               eased(m_crouch_from, m_crouch_to, m_crouch_start_s, t_s),
                         floor.y());
    const double since = t_s - m_dodge_start_s;
    if (since >= 0.0 && since <= 1.3) {
        head += dodge_amount(since) * (m_dodge_mode == 1 ? Eigen::Vector3d(0.0, -0.45, 0.0) : Eigen::Vector3d(0.5, 0.0, 0.0));
    }
    return m_last_head = head;
}

} // namespace kumite
