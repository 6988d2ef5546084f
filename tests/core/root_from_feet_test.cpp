// Captures whose root never moves (hachaj-shorinryu's inertial suit): told apart from captures that move, and given
// a root that follows the foot the body stands on, so that foot stays put.

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/core/root_from_feet.h"
#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

using namespace kumite;

namespace {

// Hips with two legs (hip, knee, ankle), the left leg swinging forward and up, the right (2 cm longer: the lower
// foot from the first frame) straight; root pinned.
Clip kicking_clip() {
    Clip clip;
    Skeleton& s = clip.skeleton;
    s.names = {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot"};
    s.parents = {-1, 0, 1, 2, 0, 4, 5};
    s.rest_offsets = {{0.0, 0.95, 0.0}, {0.1, 0.0, 0.0}, {0.0, -0.45, 0.0}, {0.0, -0.42, 0.0},
                      {-0.1, 0.0, 0.0}, {0.0, -0.47, 0.0}, {0.0, -0.42, 0.0}};
    clip.frame_time_s = 0.01;
    for (int frame = 0; frame < 60; ++frame) {
        const double swing = 1.2 * std::sin(3.14159265358979 * frame / 59.0); // up to 69 degrees forward
        std::vector<Eigen::Quaterniond> rotations(s.joint_count(), Eigen::Quaterniond::Identity());
        rotations[1] = Eigen::Quaterniond(Eigen::AngleAxisd(-swing, Eigen::Vector3d::UnitX()));
        // The standing hip tilts a little, as a body over one leg does: the support ankle moves under pinned hips.
        rotations[4] = Eigen::Quaterniond(Eigen::AngleAxisd(0.15 * swing, Eigen::Vector3d::UnitX()));
        clip_append_pose(clip, PoseView{s.rest_offsets[0], rotations, {}});
    }
    return clip;
}

Eigen::Vector3d ankle_at(const Clip& clip, int joint, int frame) {
    std::vector<Eigen::Vector3d> positions(clip.skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(clip.skeleton.joint_count());
    forward_kinematics(positions, rotations, clip.skeleton, clip.pose(frame));
    return positions[joint];
}

} // namespace

TEST_CASE("root from feet: a pinned root follows the foot the body stands on", "[core]") {
    Clip clip = kicking_clip();
    REQUIRE(root_is_pinned(clip));
    const Eigen::Vector3d support_before = ankle_at(clip, 6, 30) - ankle_at(clip, 6, 0);
    CHECK(support_before.norm() > 0.05); // the standing foot slides under the pinned hips
    const RootFromFeetReport report = root_motion_from_feet(clip, 3, 6);
    CHECK(report.support_slide_before_m > 0.05);
    CHECK(report.root_travel_m > 0.05);
    CHECK_FALSE(root_is_pinned(clip));
    for (int frame = 0; frame < clip.frame_count(); ++frame) {
        INFO("frame " << frame);
        CHECK((ankle_at(clip, 6, frame) - ankle_at(clip, 6, 0)).norm() < 1e-9); // the standing foot stays put
    }
    // The kicking foot still rises and reaches forward of the standing one.
    CHECK(ankle_at(clip, 3, 30).y() - ankle_at(clip, 6, 30).y() > 0.3);
    CHECK(ankle_at(clip, 3, 30).z() - ankle_at(clip, 6, 30).z() > 0.3);
}

TEST_CASE("root from feet: a root that moves is left alone", "[core]") {
    Clip clip = kicking_clip();
    clip.root_translations[10].x() += 0.01;
    CHECK_FALSE(root_is_pinned(clip));
}

TEST_CASE("root from feet: hachaj-shorinryu's kicks stand on a foot that stays put", "[core][corpus]") {
    const std::filesystem::path folder = kumite::test::mocap_root() / "hachaj-shorinryu";
    if (!std::filesystem::exists(folder)) return;
    int files = 0;
    for (const char* name : {"s1_mae_geri_left_sample0.bvh", "s2_yoko_geri_right_sample3.bvh", "s2_hiza_geri_left_sample0.bvh"}) {
        BvhReadOptions options;
        options.frame_rate_hz = 100.0;
        Result<BvhFile> file = bvh_read_file(folder / name, options);
        REQUIRE(file);
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        REQUIRE(anatomy);
        REQUIRE(root_is_pinned(file->clip));
        const int left = anatomy->limbs[int(Limb::leg_l)].extremity, right = anatomy->limbs[int(Limb::leg_r)].extremity;
        const RootFromFeetReport report = root_motion_from_feet(file->clip, left, right);
        INFO(name << ": slid " << report.support_slide_before_m << " m, root moved " << report.root_travel_m << " m");
        CHECK(report.support_slide_before_m > 0.1); // the capture as it comes: the standing foot slides
        // After: the kicking (or kneeing) foot's partner stays within a centimetre over the half second before the hit.
        const bool kicks_left = std::string(name).find("_left_") != std::string::npos;
        const int support = kicks_left ? right : left, kicking = kicks_left ? left : right;
        int highest = 0;
        for (int frame = 0; frame < file->clip.frame_count(); ++frame) {
            if (ankle_at(file->clip, kicking, frame).y() > ankle_at(file->clip, kicking, highest).y()) highest = frame;
        }
        const Eigen::Vector3d planted = ankle_at(file->clip, support, highest);
        double drift = 0.0;
        for (int frame = std::max(0, highest - 30); frame <= highest; ++frame) {
            Eigen::Vector3d moved = ankle_at(file->clip, support, frame) - planted;
            moved.y() = 0.0;
            drift = std::max(drift, moved.norm());
        }
        CHECK(drift < 0.01);
        ++files;
    }
    CHECK(files == 3);
}
