#include "kumite/core/clip.h"
#include "support/pose_matchers.h"

using namespace kumite;
using kumite::test::is_near;

namespace {
constexpr double k_pi = 3.14159265358979323846;

Clip two_frame_clip() {
    Clip clip;
    clip.skeleton.names = {"root", "child"};
    clip.skeleton.parents = {-1, 0};
    clip.skeleton.rest_offsets = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 1, 0)};
    clip.frame_time_s = 0.5;
    clip.root_translations = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0)};
    const Eigen::Quaterniond quarter_turn(Eigen::AngleAxisd(k_pi / 2, Eigen::Vector3d::UnitY()));
    clip.local_rotations = {Eigen::Quaterniond::Identity(), Eigen::Quaterniond::Identity(), quarter_turn,
                            Eigen::Quaterniond::Identity()};
    return clip;
}
} // namespace

TEST_CASE("clip: frames, duration and pose views", "[core]") {
    const Clip clip = two_frame_clip();
    CHECK(clip.frame_count() == 2);
    CHECK(clip.duration_s() == Approx(0.5));
    CHECK(clip.pose(1).local_rotations.size() == 2);
    CHECK(clip.pose(1).local_translations.empty());
}

TEST_CASE("clip_sample: slerps rotations and lerps translations between frames", "[core]") {
    const Clip clip = two_frame_clip();
    Pose pose;
    clip_sample(pose, clip, 0.25);
    CHECK_THAT(pose.root_translation, is_near(Eigen::Vector3d(1, 0, 0), 1e-12));
    const Eigen::Quaterniond eighth_turn(Eigen::AngleAxisd(k_pi / 4, Eigen::Vector3d::UnitY()));
    CHECK_THAT(pose.local_rotations[0], is_near(eighth_turn, 1e-12));
}

TEST_CASE("clip_sample: clamps outside the clip", "[core]") {
    const Clip clip = two_frame_clip();
    Pose pose;
    clip_sample(pose, clip, -3.0);
    CHECK_THAT(pose.root_translation, is_near(Eigen::Vector3d(0, 0, 0), 1e-12));
    clip_sample(pose, clip, 99.0);
    CHECK_THAT(pose.root_translation, is_near(Eigen::Vector3d(2, 0, 0), 1e-12));
}
