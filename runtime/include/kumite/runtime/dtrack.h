#pragma once
// A.R.T. DTrack ASCII output, as the tracking system in the VR room sends it: one UDP datagram per frame, lines
// ending CR/LF (or LF), e.g.
//
//   fr 21753
//   ts 39596.024831
//   6d 1 [0 1.000][326.848 -187.216 109.503][-0.940508 -0.339238 0.019025 0.333599 -0.932296 -0.139804 0.065164 -0.124007 0.990189]
//   3d 2 [72 1.000][174.553 -186.194 -59.053][73 1.000][170.1 -190.2 -60.0]
//
// `6d n` lists n bodies [id quality][x y z][b0 .. b8]: position in millimetres, rotation matrix column-wise (older
// DTrack versions put three Euler angles after x y z: accepted, ignored). `3d n` lists n markers [id quality][x y z].
// Other line types (6df, 6dmt, gl, ...) are skipped. A body with quality < 0 is not tracked.
//
// The parser never allocates and never reads past the datagram: it fills a fixed-size frame and refuses a
// malformed datagram with the line and what is wrong. Numbers must be finite.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string_view>

namespace kumite {

struct DtrackBody {
    int id = 0;
    double quality = 0.0;
    Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    bool tracked() const { return quality >= 0.0; }
};

struct DtrackMarker {
    int id = 0;
    double quality = 0.0;
    Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
};

inline constexpr int k_dtrack_max_bodies = 32;
inline constexpr int k_dtrack_max_markers = 64;

struct DtrackFrame {
    bool has_frame_number = false;
    std::uint64_t frame_number = 0;
    bool has_timestamp = false;
    double timestamp_s = 0.0;
    int body_count = 0; // those beyond k_dtrack_max_bodies are dropped (counted in bodies_dropped)
    std::array<DtrackBody, k_dtrack_max_bodies> bodies;
    int marker_count = 0;
    std::array<DtrackMarker, k_dtrack_max_markers> markers;
    int bodies_dropped = 0;
    int markers_dropped = 0;

    const DtrackBody* body(int id) const;
};

struct DtrackParseResult {
    bool ok = true;
    int line = 0;            // 1-based line of the problem
    const char* what = "";   // a static message
};

DtrackParseResult dtrack_parse(std::string_view datagram, DtrackFrame& frame);

} // namespace kumite
