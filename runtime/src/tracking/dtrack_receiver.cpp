#include "kumite/runtime/dtrack_receiver.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace kumite {
namespace {

Result<Eigen::Vector3d> vector_from(const nlohmann::json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3) return make_error(ErrorCode::invalid, where + ": expected [x, y, z]");
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number()) return make_error(ErrorCode::invalid, where + ": expected numbers");
        v[i] = value[i].get<double>();
    }
    if (!v.allFinite()) return make_error(ErrorCode::invalid, where + ": not finite");
    return v;
}

} // namespace

Result<DtrackConfig> dtrack_config_read(const std::string& path) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the tracker configuration");
    const nlohmann::json document = nlohmann::json::parse(in, nullptr, false);
    if (document.is_discarded() || !document.is_object()) return make_error(ErrorCode::parse, path + ": not a JSON object");
    DtrackConfig config;
    if (document.contains("bind")) {
        if (!document["bind"].is_string()) return make_error(ErrorCode::invalid, path + ": \"bind\" must be an address string");
        config.bind_address = document["bind"].get<std::string>();
    }
    for (auto [key, target] : {std::pair{"port", &config.port}, std::pair{"head_body", &config.head_body},
                               std::pair{"left_hand", &config.hand_ids[0]}, std::pair{"right_hand", &config.hand_ids[1]}}) {
        if (!document.contains(key)) continue;
        if (!document[key].is_number_integer()) return make_error(ErrorCode::invalid, path + ": \"" + key + "\" must be an integer");
        *target = document[key].get<int>();
    }
    if (config.port < 0 || config.port > 65535) return make_error(ErrorCode::invalid, path + ": \"port\" must be 0 to 65535");
    if (document.contains("room_to_world")) {
        const nlohmann::json& m = document["room_to_world"];
        if (!m.is_array() || m.size() != 16) return make_error(ErrorCode::invalid, path + ": \"room_to_world\" must hold 16 numbers (row-major 4x4)");
        Eigen::Matrix4d matrix;
        for (int i = 0; i < 16; ++i) {
            if (!m[i].is_number()) return make_error(ErrorCode::invalid, path + ": \"room_to_world\" must hold numbers");
            matrix(i / 4, i % 4) = m[i].get<double>();
        }
        if (!matrix.allFinite()) return make_error(ErrorCode::invalid, path + ": \"room_to_world\" is not finite");
        config.room_to_world.matrix() = matrix;
    }
    for (auto [key, target] : {std::pair{"room_min", &config.room_min}, std::pair{"room_max", &config.room_max}}) {
        if (!document.contains(key)) continue;
        Result<Eigen::Vector3d> v = vector_from(document[key], path + ": \"" + key + "\"");
        if (!v) return v.error();
        *target = *v;
    }
    return config;
}

Result<std::unique_ptr<DtrackReceiver>> DtrackReceiver::open(const DtrackConfig& config) {
    std::unique_ptr<DtrackReceiver> receiver(new DtrackReceiver(config));
    const std::string where = "dtrack:" + config.bind_address + ":" + std::to_string(config.port);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(config.port));
    if (inet_pton(AF_INET, config.bind_address.c_str(), &address.sin_addr) != 1) {
        return make_error(ErrorCode::invalid, where + ": not an IPv4 address");
    }
    receiver->m_socket = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (receiver->m_socket < 0) return make_error(ErrorCode::io, where + ": cannot create a UDP socket: " + std::strerror(errno));
    if (bind(receiver->m_socket, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        return make_error(ErrorCode::io, where + ": cannot bind: " + std::strerror(errno));
    }
    socklen_t length = sizeof address;
    getsockname(receiver->m_socket, reinterpret_cast<sockaddr*>(&address), &length);
    receiver->m_port = ntohs(address.sin_port);
    return receiver;
}

DtrackReceiver::~DtrackReceiver() {
    if (m_socket >= 0) close(m_socket);
}

bool DtrackReceiver::head_of(const DtrackFrame& frame, Eigen::Vector3d& world) {
    Eigen::Vector3d room_mm;
    // The head body: the one chosen, or with none chosen the only one in the frame.
    const DtrackBody* body = m_config.head_body >= 0 ? frame.body(m_config.head_body) : frame.body_count == 1 ? &frame.bodies[0] : nullptr;
    if (m_config.head_body < 0 && frame.body_count > 1) {
        ++m_stats.ambiguous;
        m_last_rejection = "several 6d bodies and none chosen as the head";
        if (!m_ambiguity_told) {
            m_ambiguity_told = m_notice_pending = true;
            int written = std::snprintf(m_notice.data(), m_notice.size(), "the DTrack stream has %d 6d bodies (ids", frame.body_count);
            for (int i = 0; i < frame.body_count && written > 0 && written < int(m_notice.size()) - 120; ++i) {
                written += std::snprintf(m_notice.data() + written, m_notice.size() - std::size_t(written), "%s %d", i ? "," : "", frame.bodies[i].id);
            }
            if (written > 0 && written < int(m_notice.size())) {
                std::snprintf(m_notice.data() + written, m_notice.size() - std::size_t(written),
                              ") and no head body is chosen: pick the glasses with --tracker dtrack:%d:ID (or \"head_body\" in "
                              "--tracker-config)\n", m_port);
            }
        }
        return false;
    }
    if (m_config.head_body >= 0 || body) {
        if (!body || !body->tracked()) {
            ++m_stats.untracked;
            m_last_rejection = "the head body is missing or not tracked";
            return false;
        }
        room_mm = body->position_mm;
    } else {
        if (frame.marker_count == 0) {
            ++m_stats.untracked;
            m_last_rejection = "no 6d body and no 3d markers";
            return false;
        }
        room_mm.setZero();
        for (int i = 0; i < frame.marker_count; ++i) room_mm += frame.markers[i].position_mm;
        room_mm /= frame.marker_count;
    }
    const Eigen::Vector3d room = room_mm / 1000.0;
    if ((room.array() < m_config.room_min.array()).any() || (room.array() > m_config.room_max.array()).any()) {
        ++m_stats.out_of_room;
        m_last_rejection = "the head is outside the room";
        return false;
    }
    world = m_config.room_to_world * room;
    return true;
}

bool DtrackReceiver::hand_of(const DtrackFrame& frame, int id, Eigen::Vector3d& world) const {
    Eigen::Vector3d room_mm;
    if (const DtrackBody* body = frame.body(id)) {
        if (!body->tracked()) return false;
        room_mm = body->position_mm;
    } else {
        const DtrackMarker* marker = nullptr;
        for (int i = 0; i < frame.marker_count && !marker; ++i) {
            if (frame.markers[i].id == id) marker = &frame.markers[i];
        }
        if (!marker) return false;
        room_mm = marker->position_mm;
    }
    const Eigen::Vector3d room = room_mm / 1000.0;
    if ((room.array() < m_config.room_min.array()).any() || (room.array() > m_config.room_max.array()).any()) return false;
    world = m_config.room_to_world * room;
    return true;
}

const char* DtrackReceiver::take_notice() {
    if (!m_notice_pending) return nullptr;
    m_notice_pending = false;
    return m_notice.data();
}

bool DtrackReceiver::poll(HeadSample& head, double now_s) {
    bool accepted = false;
    int read_now = 0;
    while (true) {
        const ssize_t size = recv(m_socket, m_buffer.data(), m_buffer.size(), MSG_DONTWAIT);
        if (size < 0) break; // EAGAIN: nothing more waiting (other errors: try again next frame)
        ++m_stats.packets;
        ++read_now;
        const DtrackParseResult parsed = dtrack_parse(std::string_view(m_buffer.data(), static_cast<std::size_t>(size)), m_frame);
        if (!parsed.ok) {
            ++m_stats.malformed;
            m_last_rejection = parsed.what;
            continue;
        }
        if (m_frame.has_frame_number && m_have_frame && m_frame.frame_number <= m_last_frame) {
            ++m_stats.reordered;
            m_last_rejection = "a frame older than the newest one";
            continue;
        }
        Eigen::Vector3d world;
        if (!head_of(m_frame, world)) continue;
        if (m_frame.has_frame_number) {
            m_have_frame = true;
            m_last_frame = m_frame.frame_number;
        }
        ++m_stats.accepted;
        head.position_world = world;
        for (int side = 0; side < 2; ++side) {
            head.hands.present[side] = m_config.hand_ids[side] >= 0 && hand_of(m_frame, m_config.hand_ids[side], head.hands.world[side]);
        }
        head.frame_number = m_frame.frame_number;
        head.received_s = now_s;
        accepted = true;
    }
    if (read_now > 1) ++m_stats.bursts;
    return accepted;
}

} // namespace kumite
