#pragma once
// splitmix64: a tiny random generator that gives the same numbers on every machine and library, for everything
// that must be deterministic from a seed (clustering, simulated users, benchmarks' random targets). std::
// distributions are not used: their algorithms differ between standard libraries.

#include <cstdint>

namespace kumite {

struct SplitMix64 {
    std::uint64_t state = 0;

    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); } // [0, 1)
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
};

} // namespace kumite
