// The difficulty levels (difficulty.h).

#include "kumite/runtime/difficulty.h"

#include "kumite/runtime/bout.h"

#include <array>
#include <string>

namespace kumite {
namespace {

constexpr auto k_levels = std::to_array<DifficultyLevel>({
    {"beginner", 0.35, 0.3, 4.0, 0.0,
     "reacts late (0.35 s) and defends one blow in three: most of the trainee's strikes land; attacks every 4 s, single blows"},
    {"intermediate", 0.25, 0.6, 3.0, 0.15,
     "a slow person's reaction (0.25 s), defends three blows in five; attacks every 3 s, one in seven a combination"},
    {"person", 0.20, 0.9, 2.5, 0.3, "a person's reaction (0.20 s), defends nine blows in ten; attacks every 2.5 s, three in ten combinations"},
    {"expert", 0.15, 1.0, 2.0, 0.4, "a trained fighter's reaction (0.15 s), defends every blow it sees; attacks every 2 s, two in five combinations"},
    {"faster-than-a-person", 0.0, 1.0, 2.0, 0.4, "moves the frame it sees a blow, every blow; attacks as the expert (the default)"},
});

} // namespace

std::span<const DifficultyLevel> difficulty_levels() { return k_levels; }

const DifficultyLevel* difficulty_find(std::string_view name) {
    for (const DifficultyLevel& level : k_levels) {
        if (name == level.name) return &level;
    }
    return nullptr;
}

const char* difficulty_of(const DefenceSettings& defence, const AttackSettings& attacks) {
    for (const DifficultyLevel& level : k_levels) {
        if (defence.reaction_delay_s == level.reaction_delay_s && defence.defend_share == level.defend_share && attacks.tempo_s == level.tempo_s &&
            attacks.combination_share == level.combination_share) {
            return level.name;
        }
    }
    return "custom";
}

const char* difficulty_of(const BoutOptions& options) { return difficulty_of(options.fighter.defence, options.attacks); }

void difficulty_apply(const DifficultyLevel& level, DefenceSettings& defence, AttackSettings& attacks) {
    defence.reaction_delay_s = level.reaction_delay_s;
    defence.defend_share = level.defend_share;
    attacks.tempo_s = level.tempo_s;
    attacks.combination_share = level.combination_share;
}

Result<void> apply_difficulty(BoutOptions& options, std::string_view name) {
    if (const DifficultyLevel* level = difficulty_find(name)) {
        difficulty_apply(*level, options.fighter.defence, options.attacks);
        return {};
    }
    return make_error(ErrorCode::invalid, "difficulty takes " + std::string(difficulty_names()) + ", not '" + std::string(name) + "'");
}

const char* difficulty_names() {
    static const std::string names = [] {
        std::string text;
        for (const DifficultyLevel& level : k_levels) text += (text.empty() ? "" : ", ") + std::string(level.name);
        return text;
    }();
    return names.c_str();
}

} // namespace kumite
