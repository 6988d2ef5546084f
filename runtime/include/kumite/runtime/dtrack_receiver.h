#pragma once
// The tracked user's head from a DTrack system over UDP (dtrack.h for the format). The frame loop calls poll()
// every frame: it reads every datagram waiting on a non-blocking socket (no thread, no allocation), keeps the
// newest valid head and counts what it rejects — malformed datagrams (NaN and inf included), frames older than
// the newest accepted (reordering), heads outside the room, untracked bodies — and bursts (several datagrams in
// one frame, of which only the newest is used). Positions go from the tracker's room frame (millimetres) to world
// metres through a configurable transform. The socket binds to loopback unless told otherwise.
//
// With no head body chosen the head is the only 6d body of the stream when there is exactly one, else the
// centroid of the 3d markers when there are markers and no body; with several bodies the frame is refused as
// ambiguous and take_notice() says once which bodies are there and how to pick one.

#include "kumite/core/result.h"
#include "kumite/runtime/dtrack.h"
#include "kumite/runtime/simulated_hands.h"

#include <Eigen/Geometry>

#include <memory>
#include <string>

namespace kumite {

struct DtrackConfig {
    std::string bind_address = "127.0.0.1";
    int port = 5000;                       // 0: any free port (tests)
    int head_body = -1;                    // 6d body id of the glasses; -1: none chosen (see head_of below)
    std::array<int, 2> hand_ids{-1, -1};   // [left, right]: a 6d body or 3d marker id per hand; -1: not tracked
    Eigen::Affine3d room_to_world = Eigen::Affine3d::Identity(); // metres -> metres
    Eigen::Vector3d room_min = Eigen::Vector3d(-2.0, 0.0, -2.0); // a head outside this box (room frame, metres)
    Eigen::Vector3d room_max = Eigen::Vector3d(2.0, 2.6, 2.0);   // is rejected
};

// A DtrackConfig from a JSON file: {"bind": "127.0.0.1", "port": 5000, "head_body": 1, "left_hand": 2, "right_hand": 3,
// "room_to_world": [16 numbers, row-major 4x4], "room_min": [x,y,z], "room_max": [x,y,z]} (all keys optional).
Result<DtrackConfig> dtrack_config_read(const std::string& path);

struct HeadSample {
    Eigen::Vector3d position_world = Eigen::Vector3d::Zero();
    UserHands hands;         // the hands of the same frame, when configured and tracked
    std::uint64_t frame_number = 0;
    double received_s = 0.0; // the caller's clock at poll()
};

struct TrackerStats {
    std::uint64_t packets = 0;         // datagrams read
    std::uint64_t accepted = 0;
    std::uint64_t malformed = 0;
    std::uint64_t reordered = 0;
    std::uint64_t out_of_room = 0;
    std::uint64_t untracked = 0;       // the head body missing or quality < 0, or no markers
    std::uint64_t ambiguous = 0;       // no head body chosen and several 6d bodies in the frame
    std::uint64_t bursts = 0;          // polls that found more than one datagram
    std::uint64_t rejected() const { return malformed + reordered + out_of_room + untracked + ambiguous; }
};

class DtrackReceiver {
public:
    static Result<std::unique_ptr<DtrackReceiver>> open(const DtrackConfig& config);
    ~DtrackReceiver();
    DtrackReceiver(const DtrackReceiver&) = delete;
    DtrackReceiver& operator=(const DtrackReceiver&) = delete;

    // Reads what is waiting; true when a new head was accepted (then in `head`).
    bool poll(HeadSample& head, double now_s);
    const TrackerStats& stats() const { return m_stats; }
    int port() const { return m_port; } // the bound port
    const char* last_rejection() const { return m_last_rejection; }
    // A message for the supervisor, once (then null): several 6d bodies and none chosen as the head.
    const char* take_notice();

private:
    explicit DtrackReceiver(const DtrackConfig& config) : m_config(config) {}
    // The head of a parsed frame in world metres, or false with the counter to bump.
    bool head_of(const DtrackFrame& frame, Eigen::Vector3d& world);
    // Hand `id` (a 6d body, else a 3d marker) of a parsed frame in world metres, or false (missing, untracked,
    // outside the room).
    bool hand_of(const DtrackFrame& frame, int id, Eigen::Vector3d& world) const;

    DtrackConfig m_config;
    int m_socket = -1;
    int m_port = 0;
    TrackerStats m_stats;
    bool m_have_frame = false;
    std::uint64_t m_last_frame = 0;
    const char* m_last_rejection = "";
    std::array<char, 65536> m_buffer{};
    std::array<char, 512> m_notice{};
    bool m_notice_pending = false;
    bool m_ambiguity_told = false;
    DtrackFrame m_frame;
};

} // namespace kumite
