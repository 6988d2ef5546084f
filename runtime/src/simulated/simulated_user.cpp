#include "kumite/runtime/simulated_user.h"

#include "kumite/core/smoothstep.h"

#include <Eigen/Geometry>

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

// An answer `since` seconds after it began: out over `out_s`, held, back over 0.2 s.
double answer_amount(double since, double out_s) {
    constexpr double k_hold_s = 0.75, k_back_s = 0.2;
    if (since < 0.0 || since > out_s + k_hold_s + k_back_s) return 0.0;
    return since < out_s ? smoothstep(since / out_s) : since < out_s + k_hold_s ? 1.0 : 1.0 - smoothstep((since - out_s - k_hold_s) / k_back_s);
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
    if (name == "slip") return SimulatedKind::slip;
    if (name == "cover") return SimulatedKind::cover;
    if (name == "step-back") return SimulatedKind::step_back;
    if (name == "high-guard") return SimulatedKind::high_guard;
    return std::nullopt;
}

SimulatedUser::SimulatedUser(SimulatedKind kind, std::uint64_t seed, double parameter) : m_kind(kind), m_random{seed} {
    if (kind == SimulatedKind::walk && parameter > 0.0) m_walk_speed_mps = parameter;
    if (answers(kind) && parameter > 0.0) m_answer_delay_s = parameter;
    if (kind == SimulatedKind::counter || kind == SimulatedKind::high_guard || answers(kind)) m_next_punch_s = 1e18; // only in reply, or never
}

void SimulatedUser::on_order(double t_s) {
    if (m_kind != SimulatedKind::dodge) return;
    m_dodge_start_s = t_s + k_dodge_delay_s;
    ++m_dodges;
}

void SimulatedUser::set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding) {
    m_hands.set_opponent(head, chest, guarding);
    // The fighter left its guard (a strike began) since it was last seen: a dodge 0.25 s after that.
    if (m_kind == SimulatedKind::dodge_seen && m_opponent_guarding && !guarding) {
        m_dodge_start_s = m_seen_s + k_dodge_delay_s;
        ++m_dodges;
    }
    if (answers(m_kind) && m_opponent_guarding && !guarding) {
        m_answer_start_s = m_seen_s + m_answer_delay_s;
        ++m_answers;
        m_limbs_at_guard_left = m_opponent_limbs;
        m_cover_side = -1;
        Eigen::Vector3d back = m_last_head - head;
        back.y() = 0.0;
        m_answer_back = back.norm() > 1e-6 ? Eigen::Vector3d(back.normalized()) : Eigen::Vector3d::UnitZ();
    }
    m_opponent_guarding = guarding;
}

Eigen::Vector3d SimulatedUser::head(double t_s) {
    m_seen_s = t_s;
    const Eigen::Vector3d start = start_position();
    switch (m_kind) {
    case SimulatedKind::still:
    case SimulatedKind::punch:
    case SimulatedKind::counter:
    case SimulatedKind::cover:
    case SimulatedKind::high_guard: return m_last_head = start;
    case SimulatedKind::slip:
    case SimulatedKind::step_back: {
        const double amount = answer_amount(t_s - m_answer_start_s, 0.15);
        const Eigen::Vector3d away = m_kind == SimulatedKind::step_back ? Eigen::Vector3d(0.35 * m_answer_back)
                                                                        : Eigen::Vector3d((m_answers % 2 == 1 ? 0.3 : -0.3), 0.0, 0.0);
        return m_last_head = start + amount * away;
    }
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
    if (m_kind == SimulatedKind::cover) {
        UserHands out = m_hands.hands(t_s, m_last_head);
        if (t_s < m_answer_start_s) return out;
        if (m_cover_side < 0) choose_cover(out);
        // Out over 0.1 s, or at 2 m/s on average when shorter: a short move is quick, not slow to start.
        const double out_s = std::clamp((m_cover_point - out.world[m_cover_side]).norm() / 2.0, 0.05, 0.1);
        const double amount = answer_amount(t_s - m_answer_start_s, out_s);
        if (amount <= 0.0) return out;
        out.world[m_cover_side] += amount * (m_cover_point - out.world[m_cover_side]);
        return out;
    }
    if (m_kind == SimulatedKind::high_guard) {
        UserHands out = m_hands.hands(t_s, m_last_head);
        const Eigen::Vector3d left = (out.world[0] - out.world[1]).normalized();
        const Eigen::Vector3d forward = Eigen::Vector3d::UnitY().cross(left);
        for (int side = 0; side < 2; ++side) out.world[side] = m_last_head + 0.10 * forward - 0.05 * Eigen::Vector3d::UnitY() + (side == 0 ? 0.09 : -0.09) * left;
        return out;
    }
    if (answers(m_kind)) return m_hands.hands(t_s, m_last_head);
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

void SimulatedUser::choose_cover(const UserHands& guard) {
    constexpr double k_foot_off_floor_m = 0.25;
    // The blow: the fighter's hand or foot (off the floor) that moved most since it left its guard. The glove nearer
    // goes between it and the nearest point of the user's middle line (the head down to the belly), 20 cm out.
    int blow = 0;
    double most = -1e9;
    for (int limb = 0; limb < 4; ++limb) {
        const bool stepping = limb >= 2 && m_opponent_limbs[limb].y() < k_foot_off_floor_m; // a step, not a kick
        const double moved = (m_opponent_limbs[limb] - m_limbs_at_guard_left[limb]).norm();
        if (!stepping && moved > most) {
            most = moved;
            blow = limb;
        }
    }
    const Eigen::Vector3d& limb = m_opponent_limbs[blow];
    const Eigen::Vector3d motion = limb - m_limbs_at_guard_left[blow];
    const Eigen::Vector3d way = motion.norm() > 1e-6 ? Eigen::Vector3d(motion.normalized()) : Eigen::Vector3d::Zero();
    Eigen::Vector3d front = limb - m_last_head; // the body's front: 8 cm from the head towards the blow
    front.y() = 0.0;
    front = m_last_head + 0.08 * (front.norm() > 1e-6 ? Eigen::Vector3d(front.normalized()) : Eigen::Vector3d::UnitZ());
    Eigen::Vector3d target = front;
    double nearest = 1e9;
    for (int step = 0; step <= 9; ++step) { // every 5 cm down the front, head to solar plexus
        const Eigen::Vector3d point = front - 0.05 * step * Eigen::Vector3d::UnitY();
        const Eigen::Vector3d offset = point - limb;
        const double off_way = (offset - std::max(0.0, offset.dot(way)) * way).norm();
        if (off_way < nearest) {
            nearest = off_way;
            target = point;
        }
    }
    const Eigen::Vector3d out = limb - target;
    m_cover_point = target + 0.2 * (out.norm() > 1e-6 ? Eigen::Vector3d(out.normalized()) : Eigen::Vector3d::UnitZ());
    m_cover_side = (guard.world[0] - m_cover_point).norm() <= (guard.world[1] - m_cover_point).norm() ? 0 : 1;
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
