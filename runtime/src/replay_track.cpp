#include "kumite/runtime/replay_track.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace kumite {

Result<ReplayTrack> ReplayTrack::read(const std::string& path, double max_gap_s) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the replay file");
    ReplayTrack track;
    track.m_max_gap_s = max_gap_s;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        double t = 0, x = 0, y = 0, z = 0;
        char extra = 0;
        if (std::sscanf(line.c_str(), " %lf , %lf , %lf , %lf %c", &t, &x, &y, &z, &extra) != 4) {
            if (track.m_times.empty() && (std::isalpha(static_cast<unsigned char>(line[first])) != 0)) continue; // a header
            return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": expected t,x,y,z");
        }
        const Eigen::Vector3d head(x, y, z);
        if (!std::isfinite(t) || !head.allFinite()) return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": not a finite number");
        if (!track.m_times.empty() && t < track.m_times.back()) {
            return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": time goes backwards");
        }
        track.m_times.push_back(t);
        track.m_heads.push_back(head);
    }
    if (track.m_times.empty()) return make_error(ErrorCode::invalid, path + ": no samples");
    return track;
}

std::optional<Eigen::Vector3d> ReplayTrack::head(double t_s) {
    while (m_next < m_times.size() && m_times[m_next] <= t_s) ++m_next;
    if (m_next == 0) return std::nullopt;
    const std::size_t latest = m_next - 1;
    if (t_s - m_times[latest] > m_max_gap_s) return std::nullopt;
    return m_heads[latest];
}

} // namespace kumite
