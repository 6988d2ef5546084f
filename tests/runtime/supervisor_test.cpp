// Supervisor commands (parsing, a TCP stream on loopback) and replayed head tracks.

#include "kumite/runtime/replay_track.h"
#include "kumite/runtime/simulated_user.h"
#include "kumite/runtime/supervisor.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <fstream>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

using namespace kumite;

TEST_CASE("supervisor: command lines are parsed, bad ones explained", "[runtime]") {
    Result<SupervisorCommand> punch = supervisor_command_parse("punch left");
    REQUIRE(punch.has_value());
    CHECK(punch->verb == SupervisorCommand::Verb::punch);
    CHECK(punch->side == "left");
    CHECK(supervisor_command_parse("  kick\r")->side.empty());
    CHECK(supervisor_command_parse("character giant")->argument == "giant");
    CHECK(supervisor_command_parse("quit")->verb == SupervisorCommand::Verb::quit);
    CHECK(supervisor_command_parse("aim predicted")->verb == SupervisorCommand::Verb::aim);
    CHECK(supervisor_command_parse("aim latched")->argument == "latched");
    for (const char* bad : {"", "punch up", "kick left now", "character", "quit now", "dance", "aim", "aim ahead"}) {
        INFO(bad);
        const Result<SupervisorCommand> parsed = supervisor_command_parse(bad);
        REQUIRE_FALSE(parsed.has_value());
        CHECK(parsed.error().message.size() > 5);
    }
}

TEST_CASE("supervisor: commands over TCP on loopback arrive as lines, replies go back", "[runtime]") {
    Result<std::unique_ptr<CommandStream>> opened = CommandStream::open("tcp:0");
    REQUIRE(opened.has_value());
    CommandStream& stream = **opened;
    REQUIRE(stream.port() > 0);
    const int client = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(stream.port()));
    inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
    REQUIRE(connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
    const std::string text = "punch left\nkick\r\nchar";
    REQUIRE(send(client, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()));
    std::vector<std::string> lines;
    for (int i = 0; i < 500 && lines.size() < 2; ++i) {
        stream.poll([&](std::string_view line) { lines.emplace_back(line); });
        usleep(2000);
    }
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "punch left");
    CHECK(lines[1] == "kick\r");
    const std::string rest = "acter giant\n";
    send(client, rest.data(), rest.size(), 0);
    for (int i = 0; i < 500 && lines.size() < 3; ++i) {
        stream.poll([&](std::string_view line) { lines.emplace_back(line); });
        usleep(2000);
    }
    REQUIRE(lines.size() == 3);
    CHECK(lines[2] == "character giant"); // a line split across packets is joined
    stream.reply("error: unknown command\n");
    char buffer[64] = {};
    ssize_t got = 0;
    for (int i = 0; i < 500 && got <= 0; ++i) {
        got = recv(client, buffer, sizeof buffer - 1, MSG_DONTWAIT);
        usleep(2000);
    }
    CHECK(std::string(buffer) == "error: unknown command\n");
    close(client);
    CHECK_FALSE(CommandStream::open("tcp:notaport").has_value());
    CHECK_FALSE(CommandStream::open("serial:1").has_value());
}

TEST_CASE("replay: a recorded head track is played back, gaps are untracked", "[runtime]") {
    const std::filesystem::path path = kumite::test::make_temp_dir("replay") / "head.csv";
    std::ofstream(path) << "t,x,y,z\n0.0,0,1.6,1.5\n0.1,0.1,1.6,1.5\n# lost for a second\n1.2,0.2,1.5,1.4\n";
    Result<ReplayTrack> track = ReplayTrack::read(path.string());
    REQUIRE(track.has_value());
    CHECK(track->samples() == 3);
    CHECK(track->head(0.05)->x() == 0.0);
    CHECK(track->head(0.15)->x() == Approx(0.1));
    CHECK_FALSE(track->head(0.6).has_value()); // the gap
    CHECK(track->head(1.3)->y() == Approx(1.5));
    std::ofstream(path) << "0,0,1.6,1.5\n0.1,nan,1.6,1.5\n";
    CHECK_FALSE(ReplayTrack::read(path.string()).has_value());
    std::ofstream(path) << "1,0,1.6,1.5\n0.5,0,1.6,1.5\n";
    const Result<ReplayTrack> backwards = ReplayTrack::read(path.string());
    REQUIRE_FALSE(backwards.has_value());
    CHECK_THAT(backwards.error().message, Catch::Contains(":2:"));
}

TEST_CASE("scripted user: a file walks, crouches, sidesteps and dodges on orders", "[runtime]") {
    const std::filesystem::path path = kumite::test::make_temp_dir("scripted") / "user.txt";
    std::ofstream(path) << "# a user for a bout\n0 at 0 2\n1 walk 0 1 1.0\n3 crouch 0.3\n4 stand\n5 sidestep 0.4\n6 dodge duck 0.25\n";
    Result<ScriptedUser> read = ScriptedUser::read(path.string());
    REQUIRE(read.has_value());
    ScriptedUser& user = *read;
    CHECK(user.head(0.5).isApprox(Eigen::Vector3d(0.0, 1.65, 2.0)));
    CHECK(user.head(1.5).z() == Approx(1.5));             // half way, 1 m/s
    CHECK(user.head(2.5).z() == Approx(1.0));             // arrived
    CHECK(user.head(3.5).y() == Approx(1.35));            // crouched
    CHECK(user.head(4.5).y() == Approx(1.65));            // stood up
    CHECK(user.head(5.5).x() == Approx(0.4));             // stepped aside
    user.head(6.1);
    user.on_order(6.1);
    CHECK(user.head(6.3).y() == Approx(1.65));            // the dodge starts 0.25 s after the order
    CHECK(user.head(6.8).y() == Approx(1.2));             // ducked
    CHECK(user.head(8.0).y() == Approx(1.65));            // and back
    for (const char* bad : {"0 jump", "x at 0 0", "0 walk 1", "0 walk 1 2 0", "0 crouch", "0 dodge sideways", "0 at 0 nan"}) {
        std::ofstream(path) << bad << "\n";
        const Result<ScriptedUser> refused = ScriptedUser::read(path.string());
        INFO(bad);
        REQUIRE_FALSE(refused.has_value());
        CHECK_THAT(refused.error().message, Catch::Contains(":1:"));
    }
}
