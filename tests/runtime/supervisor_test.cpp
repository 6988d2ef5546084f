// Supervisor commands (parsing, a TCP stream on loopback) and replayed head tracks.

#include "kumite/runtime/replay_track.h"
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
    for (const char* bad : {"", "punch up", "kick left now", "character", "quit now", "dance"}) {
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
