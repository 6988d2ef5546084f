#include "remote_driver_client.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace kumite::test {

RemotePose remote_pose(const Eigen::Quaternionf& q, const Eigen::Vector3f& p) {
    return {q.x(), q.y(), q.z(), q.w(), p.x(), p.y(), p.z()};
}

RemoteDriverClient::~RemoteDriverClient() {
    if (m_socket >= 0) ::close(m_socket);
}

bool RemoteDriverClient::connect(int port, double timeout_s, bool (*keep_trying)(void*), void* context, std::string& error) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(std::uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    while (true) {
        m_socket = ::socket(AF_INET, SOCK_STREAM, 0);
        if (m_socket >= 0 && ::connect(m_socket, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) break;
        if (m_socket >= 0) ::close(m_socket), m_socket = -1;
        if (std::chrono::steady_clock::now() > until || !keep_trying(context)) {
            error = "no remote driver listening on 127.0.0.1:" + std::to_string(port);
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    int one = 1;
    ::setsockopt(m_socket, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    RemoteData received[2];
    std::size_t have = 0;
    char* bytes = reinterpret_cast<char*>(received);
    while (have < sizeof received) {
        const ssize_t n = ::recv(m_socket, bytes + have, sizeof received - have, 0);
        if (n <= 0) {
            error = "the remote driver closed the connection before sending its state (" + std::string(std::strerror(errno)) + ")";
            return false;
        }
        have += std::size_t(n);
    }
    m_latest = received[1];
    return true;
}

bool RemoteDriverClient::send(const RemoteData& data, std::string& error) {
    const char* bytes = reinterpret_cast<const char*>(&data);
    std::size_t sent = 0;
    while (sent < sizeof data) {
        const ssize_t n = ::send(m_socket, bytes + sent, sizeof data - sent, MSG_NOSIGNAL);
        if (n <= 0) {
            error = "sending to the remote driver failed: " + std::string(std::strerror(errno));
            return false;
        }
        sent += std::size_t(n);
    }
    return true;
}

} // namespace kumite::test
