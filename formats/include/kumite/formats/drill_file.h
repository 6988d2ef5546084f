#pragma once
// A drill file: a training session's parts (data/drills/README.md). TOML, because a trainer writes
// it by hand: comments, no braces to balance, a part per [[part]] table, and every error can name its line.
//
//   name = "reaction test"                 # the drill's name (required)
//   [[part]]                               # one or more, run in order
//   name = "twenty single attacks"         # required
//   attacks = ["punch right straight high", "combo one-two"]   # supervisor commands, or:
//   free_sparring = true                   # the fighter attacks on its own (attacks then not given)
//   order = "random"                       # "random" (default) or "in turn": which attack comes next
//   cadence_s = [2.0, 4.0]                 # between attacks: a number (fixed) or [low, high] (random within)
//   count = 20                             # attacks in the part, or:
//   duration_s = 300                       # how long the part lasts (one of count and duration_s)
//   seed = 7                               # default 1: the same drill, the same moments and attacks
//   difficulty = "person"                  # default: the bout's (--difficulty); a level's name
//
// The reader checks the grammar and the structure (types, ranges, required and unknown keys); the attacks'
// grammar and the difficulty's name are the runtime's and the command's, checked by the caller with the lines kept
// here. Every error reads "FILE:LINE: reason".

#include "kumite/core/result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kumite {

struct DrillLine {
    std::string text;
    int line = 0; // in the file, 1-based
};

struct DrillPart {
    std::string name;
    int line = 0;                     // its [[part]] header
    bool free_sparring = false;
    std::vector<DrillLine> attacks;   // supervisor command lines (empty when free sparring)
    bool in_turn = false;             // false: a random one each time
    double cadence_min_s = 2.0, cadence_max_s = 2.0;
    int count = 0;                    // > 0: this many attacks, else...
    double duration_s = 0.0;          // ... this long
    std::uint64_t seed = 1;
    DrillLine difficulty;             // empty text: the bout's
};

struct Drill {
    std::string name;
    std::vector<DrillPart> parts;
};

// `text` as a drill file called `file_name` in messages.
Result<Drill> drill_parse(std::string_view text, const std::string& file_name);
Result<Drill> drill_read(const std::string& path);

} // namespace kumite
