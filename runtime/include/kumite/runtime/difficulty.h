#pragma once
// The fighter's difficulty by name, for `kumite play --difficulty LEVEL`: each level is a set of explicit settings
// (its reaction time, how often it defends, and when it attacks on its own, its tempo and its share of combinations),
// applied before --settings and --set, which may change any of them.

#include "kumite/core/result.h"
#include "kumite/runtime/bout.h"

#include <span>
#include <string_view>

namespace kumite::cli {

struct DifficultyLevel {
    const char* name;
    double reaction_delay_s; // defence.reaction_delay_s
    double defend_share;     // defence.defend_share
    double tempo_s;          // attacks.tempo_s (its own attacks, free sparring)
    double combination_share; // attacks.combination_share
    const char* what;        // one line for a trainer
};

// From the easiest to the hardest.
std::span<const DifficultyLevel> difficulty_levels();
// The level whose settings `options` has, or "custom".
const char* difficulty_of(const BoutOptions& options);
// The level's settings into `options`; an error naming the levels when there is none of that name.
Result<void> apply_difficulty(BoutOptions& options, std::string_view name);

} // namespace kumite::cli
