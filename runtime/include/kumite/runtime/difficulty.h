#pragma once
// The fighter's difficulty by name (`kumite play --difficulty LEVEL`, a drill part's `difficulty`, the supervisor's
// `difficulty LEVEL`): each level is a set of explicit settings (its reaction time, how often it defends, and when it
// attacks on its own, its tempo and its share of combinations). --settings and --set may change any of them after.

#include "kumite/core/result.h"

#include <span>
#include <string_view>

namespace kumite {

struct BoutOptions;
struct AttackSettings;
struct DefenceSettings;

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
// The level of that name, or null.
const DifficultyLevel* difficulty_find(std::string_view name);
// The level whose settings these are, or "custom".
const char* difficulty_of(const DefenceSettings& defence, const AttackSettings& attacks);
const char* difficulty_of(const BoutOptions& options);
// The level's settings into these.
void difficulty_apply(const DifficultyLevel& level, DefenceSettings& defence, AttackSettings& attacks);
// The level's settings into `options`; an error naming the levels when there is none of that name.
Result<void> apply_difficulty(BoutOptions& options, std::string_view name);
// "beginner, intermediate, ..."
const char* difficulty_names();

} // namespace kumite
