#include "kumite/runtime/replay_track.h"

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace kumite {
namespace {

constexpr int k_most_fields = 16;

// The comma-separated numbers of `line` into `values` (at most k_most_fields): how many there were, or -1 when
// something else is in it (a word, an empty field, more fields than that).
int read_fields(const std::string& line, double* values) {
    const char* at = line.c_str();
    int count = 0;
    for (;;) {
        char* end = nullptr;
        const double value = std::strtod(at, &end);
        if (end == at || count == k_most_fields) return -1;
        values[count++] = value;
        at = end;
        while (*at == ' ' || *at == '\t' || *at == '\r') ++at;
        if (*at == '\0') return count;
        if (*at != ',') return -1;
        ++at;
    }
}

} // namespace

Result<ReplayTrack> ReplayTrack::read(const std::string& path, double max_gap_s) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the replay file");
    ReplayTrack track;
    track.m_max_gap_s = max_gap_s;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        // t,x,y,z, then the hands (six numbers), then the elbows a recording's guard used (six, not read back: the
        // replay's guard finds them again the same way).
        double values[k_most_fields] = {};
        const int fields = read_fields(line, values);
        const bool with_hands = fields == 10 || fields == 16;
        if (fields != 4 && !with_hands) {
            if (track.m_times.empty() && (std::isalpha(static_cast<unsigned char>(line[first])) != 0)) continue; // a header
            return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": expected t,x,y,z or t,x,y,z,lx,ly,lz,rx,ry,rz (and six elbow numbers)");
        }
        const double t = values[0], x = values[1], y = values[2], z = values[3];
        const double* h = values + 4;
        if (!track.m_times.empty() && with_hands != !track.m_hands.empty()) {
            return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": every line must have the hands, or none");
        }
        if (with_hands) {
            UserHands hands;
            for (int side = 0; side < 2; ++side) {
                const Eigen::Vector3d hand(h[3 * side], h[3 * side + 1], h[3 * side + 2]);
                hands.present[side] = hand.allFinite();
                if (hands.present[side]) hands.world[side] = hand;
                else if (!hand.array().isNaN().all()) {
                    return make_error(ErrorCode::invalid, path + ":" + std::to_string(number) + ": a hand is three numbers or nan,nan,nan");
                }
            }
            track.m_hands.push_back(hands);
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

std::optional<Eigen::Vector3d> ReplayTrack::head(double t_s, UserHands* hands) {
    while (m_next < m_times.size() && m_times[m_next] <= t_s) ++m_next;
    if (m_next == 0) return std::nullopt;
    const std::size_t latest = m_next - 1;
    if (t_s - m_times[latest] > m_max_gap_s) return std::nullopt;
    if (hands && !m_hands.empty()) *hands = m_hands[latest];
    return m_heads[latest];
}

} // namespace kumite
