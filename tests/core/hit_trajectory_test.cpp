#include "kumite/core/hit_trajectory.h"
#include "kumite/formats/bvh_reader.h"
#include "support/pose_matchers.h"
#include "support/test_paths.h"

using namespace kumite;
using kumite::test::is_near;

TEST_CASE("heading_frame: facing +X puts the heading's +Z on world +X", "[core]") {
    const HeadingFrame frame = heading_frame_from(Eigen::Vector3d(1.0, 0.9, 2.0), Eigen::Vector3d(1.0, -0.3, 0.0));
    CHECK_THAT(frame.to_world(Eigen::Vector3d(0, 0, 1)), is_near(Eigen::Vector3d(2.0, 0.0, 2.0), 1e-12));
    // World +Z is this character's right (left is up x facing = -Z), so it maps to heading -X.
    CHECK_THAT(frame.to_heading(Eigen::Vector3d(1.0, 1.5, 2.5)), is_near(Eigen::Vector3d(-0.5, 1.5, 0.0), 1e-12));
    const Eigen::Vector3d p(-0.3, 0.4, 7.0);
    CHECK_THAT(frame.to_world(frame.to_heading(p)), is_near(p, 1e-12));
    // A direction turns without the origin: the difference of two points, each taken across.
    const Eigen::Vector3d q(2.0, -1.0, 0.5);
    CHECK_THAT(frame.direction_to_heading(p - q), is_near(frame.to_heading(p) - frame.to_heading(q), 1e-12));
    CHECK_THAT(frame.direction_to_world(Eigen::Vector3d(0, 0, 1)), is_near(Eigen::Vector3d(1.0, 0.0, 0.0), 1e-12));
}

TEST_CASE("hit_trajectory: a right kick rises in front of its start poses, inside its box", "[core][corpus]") {
    const std::filesystem::path path = kumite::test::mocap_root() / "bandai-namco-1/dataset-1_kick_normal_001.bvh";
    if (!std::filesystem::exists(path)) return;
    Result<BvhFile> file = bvh_read_file(path);
    REQUIRE(file.has_value());
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    REQUIRE(anatomy.has_value());
    const int foot = file->body_map.joint(BodyPart::foot_r);
    const HitTrajectory trajectory = hit_trajectory_compute(file->clip, *anatomy, ContactPoint{foot}, 30, 60, 87);
    REQUIRE(trajectory.hit_frame == 30);
    REQUIRE(trajectory.hit_points.size() == 58);
    REQUIRE(trajectory.start_boxes.size() == 30);
    for (int start = 0; start < 30; ++start) {
        const Eigen::Vector3d at_hit = trajectory.point_from(start, 30);
        INFO("start " << start);
        CHECK(at_hit.z() > 0.3);  // in front of the body
        CHECK(at_hit.y() > 0.5);  // foot raised well above the floor
        for (int frame = start; frame <= 30; ++frame) {
            CHECK(trajectory.start_boxes[start].contains(trajectory.point_from(start, frame)));
            CHECK(trajectory.box_in_heading.contains(trajectory.point_from(start, frame)));
        }
    }
    CHECK(trajectory.box_in_heading.distance_to(Eigen::Vector3d(0, 0.8, 5.0)) > 3.0);
}
