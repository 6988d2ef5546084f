#pragma once
// The C1 ease used by every blend and ramp: 0 at s <= 0, 1 at s >= 1, zero slope at both ends.

#include <algorithm>

namespace kumite {

inline double smoothstep(double s) {
    s = std::clamp(s, 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

} // namespace kumite
