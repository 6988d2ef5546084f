#pragma once
// The fighter's own attacks, free sparring (BoutOptions::attacks): when the first fighter is free (no order waiting,
// resting or stepping), an attack every tempo_s on average (0.6 to 1.4 times it, at random): a combination for
// combination_share of them (of those the database can serve: `servable`), else a punch or, for kick_share, a kick,
// its side, kind and height left open (aimed at what the user's guard leaves open when user_guard.aim_at_openings is
// on). The same attacks for the same seed.
// Owns: when the next is due and the random stream. Touches nothing: the bout gives the line it returns.

#include "kumite/core/split_mix.h"
#include "kumite/runtime/attack_settings.h"
#include "kumite/runtime/combinations.h"

#include <array>
#include <cstdint>
#include <string>

namespace kumite {

class OwnAttacks {
public:
    OwnAttacks(const AttackSettings& settings, std::uint64_t seed, std::array<bool, k_combination_count> servable);
    // The supervisor line of the attack due at `t_s` ("punch", "kick", "combo one-two"), or empty: none is due, or
    // the fighter is not `free` (then it comes as soon as it is).
    const std::string& due(double t_s, bool free);
    // New settings from now on (a drill's part, the supervisor's difficulty or spar): switched on, the first
    // attack comes a gap after the next frame.
    void set_settings(const AttackSettings& settings);
    const AttackSettings& settings() const { return m_settings; }

private:
    double next_gap_s();

    AttackSettings m_settings;
    SplitMix64 m_random;
    double m_next_s = -1.0; // < 0: not scheduled yet (the first frame schedules it)
    std::array<bool, k_combination_count> m_servable{}; // the combinations (combinations()) whose every blow the database has
    int m_servable_count = 0;
    std::string m_line;
};

} // namespace kumite
