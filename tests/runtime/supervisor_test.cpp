// Supervisor commands (parsing, a TCP stream on loopback) and replayed head tracks.

#include "kumite/runtime/replay_track.h"
#include "kumite/runtime/simulated_user.h"
#include "kumite/runtime/supervisor.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <filesystem>

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
    CHECK(supervisor_command_parse("combo jab-body-head")->verb == SupervisorCommand::Verb::combo);
    CHECK(supervisor_command_parse("combo one-two")->argument == "one-two");
    const Result<SupervisorCommand> unknown_combination = supervisor_command_parse("combo one-two-three");
    REQUIRE_FALSE(unknown_combination.has_value());
    CHECK_THAT(unknown_combination.error().message, Catch::Contains("jab-hook")); // names the ones there are
    for (const char* bad : {"", "punch up", "kick left now", "kick left high front middle", "character", "quit now", "dance", "aim", "aim ahead",
                            "combo", "combo one-two now"}) {
        INFO(bad);
        const Result<SupervisorCommand> parsed = supervisor_command_parse(bad);
        REQUIRE_FALSE(parsed.has_value());
        CHECK(parsed.error().message.size() > 5);
    }
}

TEST_CASE("supervisor: strike orders take side, kind and height in any order, each once, kinds of their semantics", "[runtime]") {
    Result<SupervisorCommand> hook = supervisor_command_parse("punch high hook left");
    REQUIRE(hook.has_value());
    CHECK(hook->verb == SupervisorCommand::Verb::punch);
    CHECK(hook->side == "left");
    CHECK(hook->kind == StrikeKind::hook);
    CHECK(hook->height == StrikeHeight::high);
    Result<SupervisorCommand> kick = supervisor_command_parse("kick roundhouse");
    REQUIRE(kick.has_value());
    CHECK(kick->kind == StrikeKind::roundhouse);
    CHECK(kick->height == StrikeHeight::none);
    CHECK(kick->side.empty());
    Result<SupervisorCommand> low = supervisor_command_parse("kick low");
    REQUIRE(low.has_value());
    CHECK(low->height == StrikeHeight::low);
    CHECK(low->kind == StrikeKind::none);
    Result<SupervisorCommand> slash = supervisor_command_parse("slash right middle");
    REQUIRE(slash.has_value());
    CHECK(std::string(slash->semantics()) == "slash");
    const std::pair<const char*, const char*> bad[] = {{"punch roundhouse", "cannot be a roundhouse"},
                                                       {"kick uppercut", "cannot be a uppercut"},
                                                       {"punch left right", "two sides"},
                                                       {"punch hook straight", "two kinds"},
                                                       {"kick low high", "two heights"},
                                                       {"punch sideways", "not a side"},
                                                       {"punch none", "not a side"},
                                                       {"slash hook", "cannot be a hook"}};
    for (const auto& [line, why] : bad) {
        INFO(line);
        const Result<SupervisorCommand> parsed = supervisor_command_parse(line);
        REQUIRE_FALSE(parsed.has_value());
        CHECK_THAT(parsed.error().message, Catch::Contains(why));
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
    CHECK_FALSE(user.hands(8.0).present[0]); // no punches: no tracked hands
    // A script with a punch has hands; the punch reaches the fighter's chest.
    std::ofstream(path) << "0 at 0 1.2\n1 punch right chest 5\n";
    Result<ScriptedUser> puncher = ScriptedUser::read(path.string());
    REQUIRE(puncher.has_value());
    const Eigen::Vector3d chest(0.0, 1.3, 0.2);
    bool reached = false;
    for (int frame = 0; frame < 150; ++frame) {
        puncher->set_opponent(Eigen::Vector3d(0.0, 1.65, 0.25), chest);
        puncher->head(frame / 60.0);
        const UserHands hands = puncher->hands(frame / 60.0);
        REQUIRE(hands.present[1]);
        reached = reached || (hands.world[1] - chest).norm() < 1e-6;
    }
    CHECK(reached);
    for (const char* bad : {"0 jump", "x at 0 0", "0 walk 1", "0 walk 1 2 0", "0 crouch", "0 dodge sideways", "0 at 0 nan", "0 punch up head",
                            "0 punch left belly", "0 punch left head 90"}) {
        std::ofstream(path) << bad << "\n";
        const Result<ScriptedUser> refused = ScriptedUser::read(path.string());
        INFO(bad);
        REQUIRE_FALSE(refused.has_value());
        CHECK_THAT(refused.error().message, Catch::Contains(":1:"));
    }
}

TEST_CASE("replay: a track with hand columns gives the hands, nan for an untracked one; mixed lines are refused", "[runtime]") {
    const std::filesystem::path path = kumite::test::make_temp_dir("replay_hands") / "track.csv";
    std::ofstream(path) << "t,x,y,z,lx,ly,lz,rx,ry,rz\n0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3\n0.1,0,1.6,1.5,nan,nan,nan,-0.1,1.5,1.0\n";
    Result<ReplayTrack> track = ReplayTrack::read(path.string());
    REQUIRE(track.has_value());
    UserHands hands;
    REQUIRE(track->head(0.05, &hands).has_value());
    CHECK(hands.present[0]);
    CHECK(hands.world[1].isApprox(Eigen::Vector3d(-0.2, 1.4, 1.3)));
    REQUIRE(track->head(0.12, &hands).has_value());
    CHECK_FALSE(hands.present[0]);
    CHECK(hands.world[1].isApprox(Eigen::Vector3d(-0.1, 1.5, 1.0)));
    std::ofstream(path) << "0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3\n0.1,0,1.6,1.5\n";
    Result<ReplayTrack> mixed = ReplayTrack::read(path.string());
    REQUIRE_FALSE(mixed.has_value());
    CHECK(mixed.error().message.find(":2:") != std::string::npos);
    // What --record-user writes: the elbows after the hands, read past; a line of 11 or 17 numbers is refused.
    std::ofstream(path) << "0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3,0.3,1.2,1.4,-0.3,1.2,1.4\n0.1,0,1.6,1.5,nan,nan,nan,-0.1,1.5,1.0,nan,nan,nan,-0.3,1.2,1.3\n";
    Result<ReplayTrack> with_elbows = ReplayTrack::read(path.string());
    REQUIRE(with_elbows.has_value());
    REQUIRE(with_elbows->head(0.12, &hands).has_value());
    CHECK_FALSE(hands.present[0]);
    CHECK(hands.world[1].isApprox(Eigen::Vector3d(-0.1, 1.5, 1.0)));
    for (const char* line : {"0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3,0.3\n", "0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3,0.3,1.2,1.4,-0.3,1.2,1.4,9\n",
                             "0.0,0,1.6,1.5,0.2,1.4,1.3,-0.2,1.4,1.3,,1.2,1.4,-0.3,1.2,1.4\n"}) {
        std::ofstream(path) << line;
        Result<ReplayTrack> refused = ReplayTrack::read(path.string());
        REQUIRE_FALSE(refused.has_value());
        CHECK(refused.error().message.find(":1:") != std::string::npos);
    }
}

TEST_CASE("simulated hands: a punching user punches from the guard at the fighter's head and chest at 4-8 m/s", "[runtime]") {
    SimulatedUser user(SimulatedKind::punch, 9);
    const Eigen::Vector3d fighter_head(0.0, 1.7, 0.3), fighter_chest(0.0, 1.35, 0.25);
    int punches_at_head = 0, punches_at_chest = 0;
    double previous_t = 0.0;
    Eigen::Vector3d previous[2];
    double fastest = 0.0;
    for (int frame = 0; frame < 60 * 12; ++frame) {
        const double t = frame / 60.0;
        user.set_opponent(fighter_head, fighter_chest);
        user.head(t);
        const UserHands hands = user.hands(t);
        REQUIRE(hands.present[0]);
        REQUIRE(hands.present[1]);
        for (int side = 0; side < 2; ++side) {
            if (frame > 0) fastest = std::max(fastest, (hands.world[side] - previous[side]).norm() / (t - previous_t));
            punches_at_head += (hands.world[side] - fighter_head).norm() < 1e-6;
            punches_at_chest += (hands.world[side] - fighter_chest).norm() < 1e-6;
            previous[side] = hands.world[side];
        }
        previous_t = t;
    }
    CHECK(punches_at_head >= 2); // held for a few frames at full extension
    CHECK(punches_at_chest >= 2);
    CHECK(fastest >= 4.0);
    CHECK(fastest <= 8.0 + 1e-6);
    // Users that do not punch have no tracked hands.
    SimulatedUser still(SimulatedKind::still, 9);
    still.head(0.0);
    CHECK_FALSE(still.hands(0.0).present[0]);
}

TEST_CASE("simulated hands: a countering user punches only in reply to the fighter's guard coming back", "[runtime]") {
    SimulatedUser user(SimulatedKind::counter, 3);
    const Eigen::Vector3d fighter_head(0.0, 1.7, 0.3), fighter_chest(0.0, 1.35, 0.25);
    double first_arrival = -1.0;
    for (int frame = 0; frame < 60 * 6; ++frame) {
        const double t = frame / 60.0;
        const bool guarding = !(t >= 3.0 && t < 4.0); // the fighter strikes from 3 s to 4 s
        user.set_opponent(fighter_head, fighter_chest, guarding);
        user.head(t);
        const UserHands hands = user.hands(t);
        REQUIRE(hands.present[0]);
        const bool arrived = (hands.world[0] - fighter_head).norm() < 1e-6 || (hands.world[1] - fighter_head).norm() < 1e-6;
        if (arrived && first_arrival < 0.0) first_arrival = t;
    }
    // Nothing while the guard stays; the reply lands 0.3 s after the guard is back, plus its draw and thrust.
    REQUIRE(first_arrival > 4.0);
    CHECK(first_arrival < 4.0 + 0.3 + SimulatedHands::k_draw_s + 0.3);
}

TEST_CASE("simulated user: dodge-seen dodges 0.25 s after the fighter leaves its guard, not at the order", "[runtime]") {
    SimulatedUser user(SimulatedKind::dodge_seen, 1);
    const Eigen::Vector3d fighter_head(0.0, 1.7, 0.3), fighter_chest(0.0, 1.35, 0.25), start = SimulatedUser::start_position();
    double moved_from = -1.0, out_by = -1.0;
    for (int frame = 0; frame < 60 * 5; ++frame) {
        const double t = frame / 60.0;
        if (frame == 60) user.on_order(t);                  // an order at 1 s: nothing to see yet
        const bool guarding = !(t >= 2.0 && t < 2.6);       // the strike begins at 2 s
        user.set_opponent(fighter_head, fighter_chest, guarding);
        const double off = (user.head(t) - start).norm();
        if (off > 1e-6 && moved_from < 0.0) moved_from = t;
        if (off > 0.44 && out_by < 0.0) out_by = t;
    }
    // The first dodge is a duck of 0.45 m, begun 0.25 s after the frame that last saw the guard, out in 0.15 s.
    CHECK(moved_from > 2.2);
    CHECK(moved_from <= 2.25 + 1e-9);
    CHECK(out_by <= 2.45);
    // The order-keyed dodger moves at the order instead.
    SimulatedUser keyed(SimulatedKind::dodge, 1);
    keyed.on_order(1.0);
    CHECK((keyed.head(1.3) - start).norm() > 0.01);
    CHECK((keyed.head(1.2) - start).norm() < 1e-9);
}
