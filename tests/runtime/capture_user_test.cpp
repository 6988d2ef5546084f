// A recorded person as the user: a capture turned to face the fighter, its mean head put DISTANCE in front, its
// floor on the room's, at its own size; looping at the end; the spec's numbers and bad captures refused with
// what is wrong. On a small capture written here (a performer facing +X, walking along it, in centimetres) and on
// the shared shadow-boxing takes.

#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/head_tracker.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace kumite;

namespace {

// A T-posed humanoid in centimetres, 11 frames at 10 fps: the root turned +90 degrees about Y (so it faces +X) and
// walking 100 cm along +X, the head nodding 10 cm up and down.
std::string walker_bvh(double frame_time_s) {
    std::ostringstream text;
    text << "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
            " JOINT LeftUpLeg\n {\n  OFFSET 10 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "  JOINT LeftLeg\n  {\n   OFFSET 0 -45 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "   JOINT LeftFoot\n   {\n    OFFSET 0 -45 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n    End Site\n    {\n     OFFSET 0 -8 12\n    }\n   }\n  }\n }\n"
            " JOINT RightUpLeg\n {\n  OFFSET -10 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "  JOINT RightLeg\n  {\n   OFFSET 0 -45 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "   JOINT RightFoot\n   {\n    OFFSET 0 -45 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n    End Site\n    {\n     OFFSET 0 -8 12\n    }\n   }\n  }\n }\n"
            " JOINT Spine\n {\n  OFFSET 0 20 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "  JOINT Spine1\n  {\n   OFFSET 0 25 0\n   CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "   JOINT Neck\n   {\n    OFFSET 0 12 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
            "    JOINT Head\n    {\n     OFFSET 0 10 0\n     CHANNELS 3 Zrotation Xrotation Yrotation\n     End Site\n     {\n      OFFSET 0 20 0\n     }\n    }\n   }\n";
    for (const char* side : {"Left", "Right"}) {
        const double x = std::string(side) == "Left" ? 1.0 : -1.0;
        text << "   JOINT " << side << "Shoulder\n   {\n    OFFSET " << 5 * x << " 10 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
             << "    JOINT " << side << "Arm\n    {\n     OFFSET " << 12 * x << " 0 0\n     CHANNELS 3 Zrotation Xrotation Yrotation\n"
             << "     JOINT " << side << "ForeArm\n     {\n      OFFSET " << 28 * x << " 0 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n"
             << "      JOINT " << side << "Hand\n      {\n       OFFSET " << 25 * x << " 0 0\n       CHANNELS 3 Zrotation Xrotation Yrotation\n"
             << "       End Site\n       {\n        OFFSET " << 8 * x << " 0 0\n       }\n      }\n     }\n    }\n   }\n";
    }
    text << "  }\n }\n}\nMOTION\nFrames: 11\nFrame Time: " << frame_time_s << "\n";
    const int channels = 6 + 3 * 18; // the root's six, three for each of 18 joints
    for (int frame = 0; frame < 11; ++frame) {
        text << 200.0 + 10.0 * frame << " " << 98.0 << " " << 50.0 << " 0 0 90";
        for (int c = 6; c < channels; ++c) text << " " << (c == 6 + 3 * 9 + 1 ? (frame % 2 == 0 ? 10.0 : -10.0) : 0.0); // Head's X: a nod
        text << "\n";
    }
    return text.str();
}

std::string write(const std::string& stem, const std::string& text) {
    const std::filesystem::path path = test::make_temp_dir("capture_user") / (stem + ".bvh");
    std::ofstream(path) << text;
    return path.string();
}

} // namespace

TEST_CASE("capture user: a performer facing +X is turned to face the fighter, its mean head DISTANCE in front", "[capture_user]") {
    const std::string path = write("walker", walker_bvh(0.1));
    Result<CaptureUser> user = CaptureUser::open(path + ":1.5");
    REQUIRE(user);
    CHECK(user->placement().distance_m == 1.5);
    CHECK(user->frame_count() == 11);
    CHECK(user->duration_s() == Approx(1.0));
    CHECK(user->mean_head().x() == Approx(0.0).margin(1e-9));
    CHECK(user->mean_head().z() == Approx(1.5).margin(1e-9));

    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    UserHands hands;
    double lowest_hand = 1e9;
    for (int frame = 0; frame < 11; ++frame) {
        const Eigen::Vector3d head = user->head(0.1 * frame, hands);
        mean += head / 11.0;
        REQUIRE(hands.present[0]);
        REQUIRE(hands.present[1]);
        // Facing -Z, the performer's left is -X; the T-posed arms stretch 0.6-0.7 m to either side.
        CHECK(hands.world[0].x() - head.x() < -0.6);
        CHECK(hands.world[1].x() - head.x() > 0.6);
        lowest_hand = std::min(lowest_hand, hands.world[0].y());
    }
    CHECK(mean.z() == Approx(1.5).margin(1e-6));
    // At its own size, in metres, its toes on the floor: the ankle 8 cm up, the hips 90 cm above it, the head joint
    // 67 cm above them, the skull's centre halfway up its 20 cm End Site.
    const Eigen::Vector3d first = user->head(0.0, hands);
    CHECK(first.y() == Approx(0.08 + 0.90 + 0.20 + 0.25 + 0.12 + 0.10 + 0.10).margin(0.03));
    // Walking along its own +X is walking towards the fighter: z falls by 1 m over the capture.
    const Eigen::Vector3d last = user->head(0.999, hands);
    CHECK(first.z() - last.z() == Approx(1.0).margin(0.02));
    CHECK(user->loops() == 0);
}

TEST_CASE("capture user: starts START_S into the capture, interpolates between frames and loops at its end", "[capture_user]") {
    const std::string path = write("walker", walker_bvh(0.1));
    Result<CaptureUser> from_start = CaptureUser::open(path);
    Result<CaptureUser> later = CaptureUser::open(path + ":1.2:0.5");
    REQUIRE(from_start);
    REQUIRE(later);
    CHECK(from_start->placement().distance_m == 1.2);
    UserHands hands;
    const Eigen::Vector3d at_half = from_start->head(0.5, hands);
    CHECK((later->head(0.0, hands) - at_half).norm() < 1e-9);
    // Halfway between frames 2 and 3: the mean of both.
    const Eigen::Vector3d mid = from_start->head(0.25, hands);
    CHECK((mid - 0.5 * (from_start->head(0.2, hands) + from_start->head(0.3, hands))).norm() < 1e-9);
    // 11 frames at 10 fps: the last frame holds until 1.1 s, then the capture starts again.
    const Eigen::Vector3d held = from_start->head(1.05, hands);
    CHECK(from_start->loops() == 0);
    CHECK((held - from_start->head(1.0, hands)).norm() < 1e-12);
    const Eigen::Vector3d looped = from_start->head(1.15, hands);
    CHECK(from_start->loops() == 1);
    CHECK(from_start->capture_time_s() == Approx(0.05));
    CHECK((looped - from_start->head(0.05, hands)).norm() < 1e-12);
}

TEST_CASE("capture user: bad specs and captures are refused with what is wrong", "[capture_user]") {
    const std::string path = write("walker", walker_bvh(0.1));
    Result<CaptureUser> too_near = CaptureUser::open(path + ":0.1");
    REQUIRE(!too_near);
    CHECK(too_near.error().code == ErrorCode::invalid);
    CHECK_THAT(too_near.error().message, Catch::Contains("DISTANCE"));
    Result<CaptureUser> negative_start = CaptureUser::open(path + ":1.2:-3");
    REQUIRE(!negative_start);
    CHECK_THAT(negative_start.error().message, Catch::Contains("START_S"));
    Result<CaptureUser> missing = CaptureUser::open("/nonexistent/opponent.bvh");
    REQUIRE(!missing);
    CHECK_THAT(missing.error().message, Catch::Contains("/nonexistent/opponent.bvh"));
    Result<CaptureUser> no_rate = CaptureUser::open(write("no_rate", walker_bvh(0.0)));
    REQUIRE(!no_rate);
    CHECK_THAT(no_rate.error().message, Catch::Contains("frame rate"));
    // Through the tracker: the same spec, the same refusal.
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("capture:" + path + ":0.1", {}, 1);
    REQUIRE(!tracker);
    CHECK(tracker.error().code == ErrorCode::invalid);
}

TEST_CASE("capture user: the shared shadow boxer faces the fighter, hands in front of the head", "[capture_user][corpus]") {
    const std::filesystem::path boxer = test::mocap_root() / "cmu14-boxing" / "box-1.bvh";
    if (!std::filesystem::exists(boxer)) return; // no shared captures here
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("capture:" + boxer.string(), {}, 1);
    REQUIRE(tracker);
    const CaptureUser* user = (*tracker)->capture();
    REQUIRE(user != nullptr);
    // A boxer's fists are in front of the face (towards the fighter, -Z) most of the time.
    int frames = 0, hands_ahead = 0;
    for (double t = 0.0; t < user->duration_s(); t += 0.05, ++frames) {
        const Eigen::Vector3d* head = (*tracker)->head(t);
        REQUIRE(head != nullptr);
        const UserHands& hands = (*tracker)->hands();
        if (hands.world[0].z() < head->z() && hands.world[1].z() < head->z()) ++hands_ahead;
        CHECK(head->y() > 1.0);
        CHECK(std::abs(head->z() - 1.2) < 0.8);
    }
    CHECK(hands_ahead > 0.8 * frames);
}
