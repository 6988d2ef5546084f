#pragma once
// A scripted user for headless bouts and tests, deterministic from a seed. The fighter starts at the origin
// facing +Z; the user stands 1.5 m in front of it, facing it, head 1.65 m up.
//   still  — stands there.
//   wander — walks slowly (0.4 m/s) between random points of a 3 m x 3 m room centred on its start.
//   dodge  — like still, but 0.25 s after each order ducks 0.45 m or sidesteps 0.5 m (alternately) for 1 s.

#include <Eigen/Core>

#include <optional>
#include <string_view>

#include "kumite/core/split_mix.h"

namespace kumite {

enum class SimulatedKind { still, wander, dodge };
std::optional<SimulatedKind> simulated_kind_from_name(std::string_view name);

class SimulatedUser {
public:
    SimulatedUser(SimulatedKind kind, std::uint64_t seed);

    Eigen::Vector3d head(double t_s); // call with non-decreasing times
    void on_order(double t_s);        // the supervisor gave an order at t

    static constexpr double k_head_height_m = 1.65;
    static Eigen::Vector3d start_position() { return {0.0, k_head_height_m, 1.5}; }

private:
    SimulatedKind m_kind;
    SplitMix64 m_random;
    // wander: the current leg of the walk
    Eigen::Vector3d m_from = start_position(), m_to = start_position();
    double m_leg_start_s = 0.0, m_leg_end_s = 0.0;
    // dodge: the current move
    double m_dodge_start_s = -1e9;
    int m_dodges = 0;
};

} // namespace kumite
