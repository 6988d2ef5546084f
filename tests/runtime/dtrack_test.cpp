// DTrack input: the parser on datagrams shaped like a real DTrack2's, malformed ones refused with their line,
// and the receiver over real loopback UDP: heads followed, bad datagrams counted, reordering and bursts handled.

#include "kumite/runtime/dtrack_receiver.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <fstream>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

using namespace kumite;

namespace {

const char* k_datagram =
    "fr 21753\r\n"
    "ts 39596.024831\r\n"
    "6dcal 2\r\n"
    "6d 2 [0 1.000][326.848 -187.216 109.503][-0.940508 -0.339238 0.019025 0.333599 -0.932296 -0.139804 0.065164 -0.124007 0.990189]"
    " [1 -1.000][0.000 0.000 0.000][0 0 0 0 0 0 0 0 0]\r\n"
    "3d 3 [72 1.000][174.553 -186.194 -59.053][73 1.000][170.1 -190.2 -60.0][80 0.5][0 0 0]\r\n";

std::string datagram_with_head(std::uint64_t frame, const Eigen::Vector3d& head_mm) {
    char text[256];
    std::snprintf(text, sizeof text, "fr %llu\r\nts 1.0\r\n6d 1 [1 1.000][%.3f %.3f %.3f][1 0 0 0 1 0 0 0 1]\r\n",
                  static_cast<unsigned long long>(frame), head_mm.x(), head_mm.y(), head_mm.z());
    return text;
}

class Sender {
public:
    explicit Sender(int port) : m_socket(socket(AF_INET, SOCK_DGRAM, 0)) {
        m_address.sin_family = AF_INET;
        m_address.sin_port = htons(static_cast<std::uint16_t>(port));
        inet_pton(AF_INET, "127.0.0.1", &m_address.sin_addr);
    }
    ~Sender() { close(m_socket); }
    void send(const std::string& text) {
        REQUIRE(sendto(m_socket, text.data(), text.size(), 0, reinterpret_cast<sockaddr*>(&m_address), sizeof m_address) ==
                static_cast<ssize_t>(text.size()));
    }

private:
    int m_socket;
    sockaddr_in m_address{};
};

// Polls until something arrives (loopback delivery is immediate, but not synchronous).
bool poll_for(DtrackReceiver& receiver, HeadSample& head, std::uint64_t packets) {
    for (int i = 0; i < 1000 && receiver.stats().packets < packets; ++i) {
        receiver.poll(head, 0.0);
        usleep(1000);
    }
    return receiver.stats().packets >= packets;
}

} // namespace

TEST_CASE("dtrack: a DTrack2 datagram is read: frame, time, bodies column-wise, markers, unknown lines skipped", "[runtime]") {
    DtrackFrame frame;
    const DtrackParseResult result = dtrack_parse(k_datagram, frame);
    REQUIRE(result.ok);
    CHECK(frame.frame_number == 21753);
    CHECK(frame.timestamp_s == Approx(39596.024831));
    REQUIRE(frame.body_count == 2);
    CHECK(frame.bodies[0].position_mm.isApprox(Eigen::Vector3d(326.848, -187.216, 109.503)));
    CHECK(frame.bodies[0].rotation(1, 0) == Approx(-0.339238)); // b1 is row 1 of column 0
    CHECK(frame.bodies[0].rotation(0, 1) == Approx(0.333599));
    CHECK(frame.bodies[0].tracked());
    CHECK_FALSE(frame.body(1)->tracked());
    CHECK(frame.body(7) == nullptr);
    CHECK(frame.marker_count == 3);
    CHECK(frame.markers[2].id == 80);
    // Older DTrack: six numbers (position and Euler angles) in the middle bracket.
    REQUIRE(dtrack_parse("fr 1\n6d 1 [3 1.0][1 2 3 10 20 30][1 0 0 0 1 0 0 0 1]\n", frame).ok);
    CHECK(frame.bodies[0].position_mm.isApprox(Eigen::Vector3d(1, 2, 3)));
}

TEST_CASE("dtrack: malformed datagrams are refused with their line", "[runtime]") {
    DtrackFrame frame;
    struct Case {
        const char* text;
        int line;
    };
    for (const Case& c : {Case{"", 0}, Case{"fr x\n", 1}, Case{"fr 1\n6d 2 [0 1.0][1 2 3][1 0 0 0 1 0 0 0 1]\n", 2},
                          Case{"fr 1\n6d 1 [0 1.0][1 2 3][1 0 0 0 1 0 0 0]\n", 2}, Case{"fr 1\n6d 1 [0 1.0][1 2 nan][1 0 0 0 1 0 0 0 1]\n", 2},
                          Case{"fr 1\n6d 1 [0 1.0][1 2 inf][1 0 0 0 1 0 0 0 1]\n", 2}, Case{"fr 1\n3d 1 [0 1.0][1 2]\n", 2},
                          Case{"fr 1\n3d 1 [0 1.0][1 2 3] [4 1.0][1 2 3]\n", 2}, Case{"fr 1\nts\n", 2}, Case{"hello world\n", 1},
                          Case{"6d 1 [0 1.0][1 2 3][1 0 0 0 1 0 0 0 1", 1}, Case{"fr 1\n6d -1\n", 2}, Case{"gl 1\n", 1},
                          Case{"fr 1\n3d 1 [42006900000 1.0][1 2 3]\n", 2} /* found by dtrack_fuzz: an id beyond int */,
                          Case{"fr 1\n6d 1 [1.5 1.0][1 2 3][1 0 0 0 1 0 0 0 1]\n", 2}}) {
        const DtrackParseResult result = dtrack_parse(c.text, frame);
        INFO(c.text);
        CHECK_FALSE(result.ok);
        CHECK(result.line == c.line);
        CHECK(std::string(result.what).size() > 3);
    }
    // A NUL inside the datagram is refused, not read as an end.
    CHECK_FALSE(dtrack_parse(std::string_view("fr 1\n\0 6d 0\n", 12), frame).ok);
    // Beyond the fixed capacity bodies are dropped and counted, never written past the array.
    std::string many = "fr 1\n6d 40";
    for (int i = 0; i < 40; ++i) many += " [" + std::to_string(i) + " 1.0][0 0 0][1 0 0 0 1 0 0 0 1]";
    REQUIRE(dtrack_parse(many, frame).ok);
    CHECK(frame.body_count == k_dtrack_max_bodies);
    CHECK(frame.bodies_dropped == 40 - k_dtrack_max_bodies);
}

TEST_CASE("dtrack: over loopback UDP the receiver follows the head and counts what it rejects", "[runtime]") {
    DtrackConfig config;
    config.port = 0; // any free port
    config.head_body = 1;
    config.room_to_world = Eigen::Translation3d(0.0, 0.0, 2.0) * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()); // facing the fighter
    Result<std::unique_ptr<DtrackReceiver>> opened = DtrackReceiver::open(config);
    REQUIRE(opened.has_value());
    DtrackReceiver& receiver = **opened;
    REQUIRE(receiver.port() > 0);
    Sender sender(receiver.port());
    HeadSample head;

    sender.send(datagram_with_head(10, Eigen::Vector3d(100, 1700, 500)));
    REQUIRE(poll_for(receiver, head, 1));
    CHECK(receiver.stats().accepted == 1);
    CHECK(head.position_world.isApprox(Eigen::Vector3d(-0.1, 1.7, 1.5), 1e-9)); // turned half round, moved 2 m
    CHECK(head.frame_number == 10);

    // Malformed, NaN, out of the room, untracked, reordered: all rejected, the head stays where it was.
    sender.send("fr 11\n6d 1 [1 1.0][garbage]\n");
    sender.send("fr 12\n6d 1 [1 1.0][nan 1 1][1 0 0 0 1 0 0 0 1]\n");
    sender.send(datagram_with_head(13, Eigen::Vector3d(9000, 1700, 0)));
    sender.send("fr 14\n6d 1 [1 -1.0][0 1700 0][1 0 0 0 1 0 0 0 1]\n");
    sender.send(datagram_with_head(9, Eigen::Vector3d(0, 1600, 0)));
    REQUIRE(poll_for(receiver, head, 6));
    CHECK(receiver.stats().malformed == 2);
    CHECK(receiver.stats().out_of_room == 1);
    CHECK(receiver.stats().untracked == 1);
    CHECK(receiver.stats().reordered == 1);
    CHECK(receiver.stats().accepted == 1);
    CHECK(head.frame_number == 10);

    // A burst: only the newest is used.
    for (std::uint64_t f = 20; f < 25; ++f) sender.send(datagram_with_head(f, Eigen::Vector3d(0, 1500 + double(f), 0)));
    usleep(20000);
    receiver.poll(head, 1.0);
    poll_for(receiver, head, 11);
    CHECK(head.frame_number == 24);
    CHECK(head.position_world.y() == Approx(1.524));
    CHECK(receiver.stats().bursts >= 1);
}

TEST_CASE("dtrack: the tracker configuration file is read and checked", "[runtime]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("dtrack");
    std::ofstream(folder / "room.json") << R"({"port": 5001, "head_body": 3, "room_to_world": [1,0,0,0, 0,1,0,0, 0,0,1,2, 0,0,0,1],
                                            "room_min": [-1.5, 0, -1.5], "room_max": [1.5, 2.5, 1.5]})";
    Result<DtrackConfig> config = dtrack_config_read((folder / "room.json").string());
    REQUIRE(config.has_value());
    CHECK(config->port == 5001);
    CHECK(config->head_body == 3);
    CHECK((config->room_to_world * Eigen::Vector3d(0, 0, 0)).isApprox(Eigen::Vector3d(0, 0, 2)));
    CHECK(config->room_max.y() == 2.5);
    std::ofstream(folder / "bad.json") << R"({"port": "five"})";
    CHECK_FALSE(dtrack_config_read((folder / "bad.json").string()).has_value());
    CHECK_FALSE(dtrack_config_read((folder / "missing.json").string()).has_value());
    DtrackConfig wrong;
    wrong.bind_address = "not-an-address";
    CHECK_FALSE(DtrackReceiver::open(wrong).has_value());
}

TEST_CASE("dtrack: with no head body chosen the lone 6d body is followed, markers alone give their centroid, several bodies are named once", "[runtime]") {
    DtrackConfig config;
    config.port = 0;
    config.head_body = -1; // as `--tracker dtrack:PORT` without a body
    Result<std::unique_ptr<DtrackReceiver>> opened = DtrackReceiver::open(config);
    REQUIRE(opened.has_value());
    DtrackReceiver& receiver = **opened;
    Sender sender(receiver.port());
    HeadSample head;

    // A lone 6d body (id 7, not 1) with no 3d markers: it is the head.
    sender.send("fr 1\n6d 1 [7 1.0][250 1650 -300 0 0 0][1 0 0 0 1 0 0 0 1]\n");
    REQUIRE(poll_for(receiver, head, 1));
    CHECK(receiver.stats().accepted == 1);
    CHECK(head.position_world.isApprox(Eigen::Vector3d(0.25, 1.65, -0.3), 1e-9));
    CHECK(receiver.take_notice() == nullptr);
    // Only 3d markers: their centroid.
    sender.send("fr 2\n6d 0\n3d 2 [1 1.0][0 1600 0] [2 1.0][200 1700 0]\n");
    REQUIRE(poll_for(receiver, head, 2));
    CHECK(receiver.stats().accepted == 2);
    CHECK(head.position_world.isApprox(Eigen::Vector3d(0.1, 1.65, 0.0), 1e-9));
    // The lone body untracked: no head this frame.
    sender.send("fr 3\n6d 1 [7 -1.0][0 0 0 0 0 0][1 0 0 0 1 0 0 0 1]\n");
    REQUIRE(poll_for(receiver, head, 3));
    CHECK(receiver.stats().untracked == 1);
    // Two bodies and none chosen: refused, and the supervisor told once which ones there are.
    sender.send("fr 4\n6d 2 [3 1.0][0 1600 0 0 0 0][1 0 0 0 1 0 0 0 1] [5 1.0][0 1000 0 0 0 0][1 0 0 0 1 0 0 0 1]\n");
    sender.send("fr 5\n6d 2 [3 1.0][0 1600 0 0 0 0][1 0 0 0 1 0 0 0 1] [5 1.0][0 1000 0 0 0 0][1 0 0 0 1 0 0 0 1]\n");
    REQUIRE(poll_for(receiver, head, 5));
    CHECK(receiver.stats().ambiguous == 2);
    CHECK(receiver.stats().accepted == 2);
    const char* notice = receiver.take_notice();
    REQUIRE(notice != nullptr);
    const std::string told(notice);
    CHECK(told.find("ids 3, 5") != std::string::npos);
    CHECK(told.find("dtrack:" + std::to_string(receiver.port()) + ":ID") != std::string::npos);
    CHECK(receiver.take_notice() == nullptr); // once
}

TEST_CASE("dtrack: the hands come with the head, as 6d bodies or 3d markers by id", "[runtime]") {
    DtrackConfig config;
    config.port = 0;
    config.head_body = 1;
    config.hand_ids = {2, 30}; // the left hand a 6d body, the right a 3d marker
    Result<std::unique_ptr<DtrackReceiver>> opened = DtrackReceiver::open(config);
    REQUIRE(opened.has_value());
    DtrackReceiver& receiver = **opened;
    Sender sender(receiver.port());
    HeadSample head;
    sender.send("fr 1\n6d 2 [1 1.0][0 1650 1500 0 0 0][1 0 0 0 1 0 0 0 1] [2 1.0][170 1400 1200 0 0 0][1 0 0 0 1 0 0 0 1]\n"
                "3d 2 [30 1.0][-170 1420 1250] [31 1.0][0 0 0]\n");
    REQUIRE(poll_for(receiver, head, 1));
    CHECK(receiver.stats().accepted == 1);
    CHECK(head.position_world.isApprox(Eigen::Vector3d(0.0, 1.65, 1.5), 1e-9));
    REQUIRE(head.hands.present[0]);
    REQUIRE(head.hands.present[1]);
    CHECK(head.hands.world[0].isApprox(Eigen::Vector3d(0.17, 1.4, 1.2), 1e-9));
    CHECK(head.hands.world[1].isApprox(Eigen::Vector3d(-0.17, 1.42, 1.25), 1e-9));
    // An untracked hand body and a missing marker: the head still counts, the hands are absent.
    sender.send("fr 2\n6d 2 [1 1.0][0 1650 1500 0 0 0][1 0 0 0 1 0 0 0 1] [2 -1.0][0 0 0 0 0 0][1 0 0 0 1 0 0 0 1]\n3d 0\n");
    REQUIRE(poll_for(receiver, head, 2));
    CHECK(receiver.stats().accepted == 2);
    CHECK_FALSE(head.hands.present[0]);
    CHECK_FALSE(head.hands.present[1]);
}
