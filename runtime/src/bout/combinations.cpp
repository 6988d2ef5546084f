// The combinations a fighter throws (combinations.h). Right is the lead hand: the guard clips of the reference
// captures stand right foot and right hand forward, so the jab is a right straight and the cross a left one.

#include "kumite/runtime/combinations.h"

namespace kumite {
namespace {

constexpr std::array<Combination, k_combination_count> k_combinations{{
    {"one-two",
     {{{"punch", Side::right, StrikeKind::straight, StrikeHeight::high}, {"punch", Side::left, StrikeKind::straight, StrikeHeight::high}}},
     "the jab (the lead hand's straight), then the cross (the rear hand's), at the head"},
    {"jab-hook",
     {{{"punch", Side::right, StrikeKind::straight, StrikeHeight::high}, {"punch", Side::left, StrikeKind::hook, StrikeHeight::high}}},
     "the jab at the head, then the rear hand's hook round the guard"},
    {"jab-body-head",
     {{{"punch", Side::right, StrikeKind::straight, StrikeHeight::middle}, {"punch", Side::left, StrikeKind::straight, StrikeHeight::high}}},
     "the jab to the body, then the cross at the head the lowered guard leaves open"},
}};

} // namespace

std::span<const Combination> combinations() { return k_combinations; }

int combination_index(std::string_view name) {
    for (std::size_t i = 0; i < k_combinations.size(); ++i) {
        if (name == k_combinations[i].name) return int(i);
    }
    return -1;
}

const char* combination_names() { return "one-two, jab-hook, jab-body-head"; }

} // namespace kumite
