#pragma once
// Combinations: two blows, the second begun as the first ends (from its recoil, not back from the guard). The first
// draws the user's guard to its path; the second goes where the guard left. A supervisor orders one with
// `combo NAME`; a fighter that attacks on its own (BoutOptions::attacks) throws one for a share of its attacks.

#include "kumite/core/strike_labels.h"

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

namespace kumite {

struct CombinationBlow {
    const char* semantics; // the database's ("punch", "kick")
    Side side;
    StrikeKind kind;
    StrikeHeight height;
};

struct Combination {
    const char* name;
    std::array<CombinationBlow, 2> blows;
    const char* what; // for --help and the docs
};

inline constexpr std::size_t k_combination_count = 3;
// one-two, jab-hook, jab-body-head.
std::span<const Combination> combinations();
// The index of the combination called `name` in combinations(), else -1.
int combination_index(std::string_view name);
// "one-two, jab-hook, jab-body-head": for messages.
const char* combination_names();

} // namespace kumite
