#pragma once
// Length units of capture files and their detection from a skeleton's standing height.

#include "kumite/core/result.h"

#include <string>
#include <string_view>

namespace kumite {

struct LengthUnit {
    std::string name;      // "m", "cm", "mm", "in", "cmu"
    double metres = 1.0;   // metres per file unit
};

// CMU's ASF/AMC unit: (1 / 0.45) inch = 0.056444 m.
inline constexpr double k_cmu_unit_m = 2.54 / 45.0;

// "m", "cm", "mm", "in", "cmu"; anything else is an error naming the accepted values.
Result<LengthUnit> length_unit_from_name(std::string_view name);

// The unit that makes a human of this height (in file units) between about 1 m and 2.6 m tall:
// < 4 metres, < 44 CMU units, < 100 inches, < 400 centimetres, else millimetres.
LengthUnit length_unit_for_height(double height_in_file_units);

} // namespace kumite
