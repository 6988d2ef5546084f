#pragma once
// A scripted user for headless bouts and tests, deterministic from a seed. The fighter starts at the origin
// facing +Z; the user stands 1.5 m in front of it, facing it, head 1.65 m up.
//   still  — stands there.
//   wander — walks slowly (0.4 m/s) between random points of a 3 m x 3 m room centred on its start.
//   walk   — the same at a given speed (default 0.8 m/s; `simulate:walk:1.2`), legs at least 1.5 m long.
//   dodge  — like still, but 0.25 s after each order ducks 0.45 m or sidesteps 0.5 m (alternately) for 1 s.
//   dodge-seen — the same dodges, 0.25 s after the fighter's strike begins (its guard left): what a person in the
//            room can react to. `dodge` keys on the order, which no one in the room sees: it dodges before a strike
//            the fighter begins later than 0.15 s after the order, and so its figure measures that delay too.
//   punch  — like still, with tracked hands that punch at the fighter from t = 3 s every 1.6-2.4 s: straight
//            punches from 0.6-1.0 m, left and right in turn, at the head twice then the chest twice, at 4-8 m/s.
//   counter — like still, with tracked hands that reply: 0.3 s after each of the fighter's strikes, as it comes
//            back to its guard, a straight punch as `punch` throws them.
//   slip, cover, step-back — answer each of the fighter's strikes DELAY s after it leaves its guard (what the room
//            shows; `simulate:slip:0.15`, default 0.25), with tracked hands in a guard: `slip` moves the head 0.3 m
//            aside (left and right in turn), `cover` puts the glove nearer the blow between it and the nearest point of the
//            user's middle line (head to belly), 20 cm out, `step-back` moves the
//            head 0.35 m back, away from the fighter; out over 0.15 s (the glove over 0.1 s, or at 2 m/s when shorter), held 0.75 s, back over
//            0.2 s. Each answer begins at a frame (the strike's start plus DELAY) that answer_starts() tells.
//   high-guard — like still, both gloves held tight at the cheeks (10 cm in front of the head, 5 cm under its centre,
//            9 cm to each side), forearms down in front of the chest: a boxer who covers up.
// Only `punch`, `counter`, `high-guard` and the answering users have tracked hands.

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string_view>

#include "kumite/core/result.h"
#include "kumite/core/split_mix.h"
#include "kumite/runtime/simulated_hands.h"

#include <string>
#include <vector>

namespace kumite {

enum class SimulatedKind { still, wander, walk, dodge, dodge_seen, punch, counter, slip, cover, step_back, high_guard };
std::optional<SimulatedKind> simulated_kind_from_name(std::string_view name);

class SimulatedUser {
public:
    // `parameter`: walk's speed (m/s), or an answering user's delay (s); <= 0: the kind's default.
    SimulatedUser(SimulatedKind kind, std::uint64_t seed, double parameter = 0.0);
    static bool answers(SimulatedKind kind) { return kind == SimulatedKind::slip || kind == SimulatedKind::cover || kind == SimulatedKind::step_back; }

    Eigen::Vector3d head(double t_s); // call with non-decreasing times
    void on_order(double t_s);        // the supervisor gave an order at t
    // Where the fighter's head and chest are and whether it is in its guard (before head(t)), and the hands at t
    // (after it).
    void set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding = true);
    UserHands hands(double t_s);
    // The fighter's hands and feet as the room shows them (before set_opponent): [left hand, right hand, left foot,
    // right foot], world.
    void set_opponent_limbs(const std::array<Eigen::Vector3d, 4>& limbs) { m_opponent_limbs = limbs; }

    static constexpr double k_head_height_m = 1.65;
    static Eigen::Vector3d start_position() { return {0.0, k_head_height_m, 1.5}; }

private:
    void choose_cover(const UserHands& guard); // cover: which glove goes, and where

    SimulatedKind m_kind;
    SplitMix64 m_random;
    double m_walk_speed_mps = 0.8;
    double m_answer_delay_s = 0.25;
    double m_answer_start_s = -1e9; // the answer under way (slip, cover, step-back)
    int m_answers = 0;
    Eigen::Vector3d m_answer_back = Eigen::Vector3d::UnitZ(); // step-back: away from the fighter when it began
    std::array<Eigen::Vector3d, 4> m_opponent_limbs{}, m_limbs_at_guard_left{}; // cover: the fighter's hands and feet
    int m_cover_side = -1;                          // cover: the glove that goes (-1: not chosen yet)
    Eigen::Vector3d m_cover_point = Eigen::Vector3d::Zero();
    // wander: the current leg of the walk
    Eigen::Vector3d m_from = start_position(), m_to = start_position();
    double m_leg_start_s = 0.0, m_leg_end_s = 0.0;
    // dodge: the current move; dodge-seen: when the fighter was last seen (the last head(t))
    double m_dodge_start_s = -1e9;
    double m_seen_s = 0.0;
    int m_dodges = 0;
    // punch: the hands and the next punch
    SimulatedHands m_hands;
    Eigen::Vector3d m_last_head = start_position();
    double m_next_punch_s = 3.0;
    int m_punches = 0;
    bool m_opponent_guarding = true, m_opponent_was_guarding = true; // counter: replies when the guard comes back; dodge-seen: dodges when it goes
};

// A user scripted in a file, one action per line, `<time_s> <action>` ('#' comments), applied in time order:
//   at X Z             stand at (x, z) on the floor (metres, world), head 1.65 m up
//   walk X Z [SPEED]   walk there in a straight line (default 0.8 m/s)
//   crouch DEPTH       lower the head by DEPTH metres over 0.2 s;  stand  rises again
//   sidestep DX        move DX metres along x over 0.2 s
//   dodge duck|side [DELAY]   from now on, DELAY s (default 0.25) after each order, duck 0.45 m or sidestep 0.5 m
//                             for 1 s;  dodge off  stops
//   punch left|right head|chest [SPEED]   a straight punch from that hand's guard at the fighter's head or chest
//                             (default 6 m/s); a script with punches has tracked hands
class ScriptedUser {
public:
    static Result<ScriptedUser> read(const std::string& path);

    Eigen::Vector3d head(double t_s); // call with non-decreasing times
    void on_order(double t_s);
    void set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding = true) { m_hands.set_opponent(head, chest, guarding); }
    UserHands hands(double t_s); // after head(t)

private:
    struct Action {
        double t_s = 0.0;
        enum class Kind { at, walk, crouch, stand, sidestep, dodge, punch } kind = Kind::at;
        double a = 0.0, b = 0.0, c = 0.0; // the action's numbers
        int dodge_mode = 0;               // 0 off, 1 duck, 2 side
        int side = 0;                     // punch: 0 left, 1 right
        bool at_head = true;              // punch
    };
    std::vector<Action> m_actions;
    std::size_t m_next = 0;
    Eigen::Vector2d m_floor = Eigen::Vector2d(0.0, 1.5); // x, z
    Eigen::Vector2d m_walk_from = m_floor, m_walk_to = m_floor;
    double m_walk_start_s = 0.0, m_walk_end_s = 0.0;
    double m_crouch_from = 0.0, m_crouch_to = 0.0, m_crouch_start_s = -1e9;
    double m_side_from = 0.0, m_side_to = 0.0, m_side_start_s = -1e9;
    int m_dodge_mode = 0;
    double m_dodge_delay_s = 0.25;
    double m_dodge_start_s = -1e9;
    SimulatedHands m_hands;
    bool m_has_hands = false;
    Eigen::Vector3d m_last_head = SimulatedUser::start_position();
};

} // namespace kumite
