#pragma once
// Recorded head positions played back: a CSV file of `t,x,y,z` lines (seconds, world metres; '#' comments and a
// header line without numbers are skipped), optionally with the hands: `t,x,y,z,lx,ly,lz,rx,ry,rz` (a hand written
// as nan,nan,nan was not tracked then), and after them six numbers of elbows (what --record-user writes; read past).
// At time t the head is the latest sample at or before t, unless that sample is older than `max_gap_s` (the
// recording had lost the head), when there is none.

#include "kumite/core/result.h"
#include "kumite/runtime/simulated_hands.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace kumite {

class ReplayTrack {
public:
    static Result<ReplayTrack> read(const std::string& path, double max_gap_s = 0.25);

    // Call with non-decreasing times; the hands of the same sample into `hands` when given.
    std::optional<Eigen::Vector3d> head(double t_s, UserHands* hands = nullptr);
    std::size_t samples() const { return m_times.size(); }

private:
    std::vector<double> m_times;
    std::vector<Eigen::Vector3d> m_heads;
    std::vector<UserHands> m_hands; // [sample], or empty when the file has no hand columns
    std::size_t m_next = 0;
    double m_max_gap_s = 0.25;
};

} // namespace kumite
