// The difficulty levels (play_difficulty.h).

#include "play_difficulty.h"

#include <array>
#include <string>

namespace kumite::cli {
namespace {

constexpr auto k_levels = std::to_array<DifficultyLevel>({
    {"beginner", 0.35, 0.3, "reacts late (0.35 s) and defends one blow in three: most of the trainee's strikes land"},
    {"intermediate", 0.25, 0.6, "a slow person's reaction (0.25 s), defends three blows in five"},
    {"person", 0.20, 0.9, "a person's reaction (0.20 s), defends nine blows in ten"},
    {"expert", 0.15, 1.0, "a trained fighter's reaction (0.15 s), defends every blow it sees"},
    {"faster-than-a-person", 0.0, 1.0, "moves the frame it sees a blow, every blow (the default)"},
});

} // namespace

std::span<const DifficultyLevel> difficulty_levels() { return k_levels; }

const char* difficulty_of(const BoutOptions& options) {
    for (const DifficultyLevel& level : k_levels) {
        if (options.fighter.defence.reaction_delay_s == level.reaction_delay_s && options.fighter.defence.defend_share == level.defend_share) return level.name;
    }
    return "custom";
}

Result<void> apply_difficulty(BoutOptions& options, std::string_view name) {
    for (const DifficultyLevel& level : k_levels) {
        if (name != level.name) continue;
        options.fighter.defence.reaction_delay_s = level.reaction_delay_s;
        options.fighter.defence.defend_share = level.defend_share;
        return {};
    }
    std::string names;
    for (const DifficultyLevel& level : k_levels) names += (names.empty() ? "" : ", ") + std::string(level.name);
    return make_error(ErrorCode::invalid, "--difficulty takes " + names + ", not '" + std::string(name) + "'");
}

} // namespace kumite::cli
