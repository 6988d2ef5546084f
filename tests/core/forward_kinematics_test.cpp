#include "kumite/core/forward_kinematics.h"
#include "support/pose_matchers.h"

using namespace kumite;
using kumite::test::is_near;

namespace {
constexpr double k_pi = 3.14159265358979323846;

// root -> a (offset +Y 1) -> b (offset +X 0.5), End Site on b at +X 0.25.
Skeleton chain() {
    Skeleton skeleton;
    skeleton.names = {"root", "a", "b"};
    skeleton.parents = {-1, 0, 1};
    skeleton.rest_offsets = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0.5, 0, 0)};
    skeleton.end_sites = {{2, Eigen::Vector3d(0.25, 0, 0)}};
    return skeleton;
}

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double angle) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)); }
} // namespace

TEST_CASE("forward_kinematics: rest pose stacks offsets", "[core]") {
    const Skeleton skeleton = chain();
    const std::vector<Eigen::Quaterniond> rotations(3, Eigen::Quaterniond::Identity());
    std::vector<Eigen::Vector3d> positions(3);
    std::vector<Eigen::Quaterniond> model_rotations(3);
    forward_kinematics(positions, model_rotations, skeleton, {Eigen::Vector3d(2, 0, 0), rotations, {}});
    CHECK_THAT(positions[0], is_near(Eigen::Vector3d(2, 0, 0), 1e-12));
    CHECK_THAT(positions[1], is_near(Eigen::Vector3d(2, 1, 0), 1e-12));
    CHECK_THAT(positions[2], is_near(Eigen::Vector3d(2.5, 1, 0), 1e-12));
}

TEST_CASE("forward_kinematics: hand-computed rotated chain", "[core]") {
    // Root turns 90 deg about Z: a's offset +Y goes to -X; a turns 90 deg about Y: b's offset +X, rotated by
    // Rz(90) Ry(90), goes to Rz(90)(-Z) = -Z. The End Site then adds another 0.25 along -Z.
    const Skeleton skeleton = chain();
    const std::vector<Eigen::Quaterniond> rotations = {about(Eigen::Vector3d::UnitZ(), k_pi / 2),
                                                       about(Eigen::Vector3d::UnitY(), k_pi / 2),
                                                       Eigen::Quaterniond::Identity()};
    std::vector<Eigen::Vector3d> positions(3);
    std::vector<Eigen::Quaterniond> model_rotations(3);
    forward_kinematics(positions, model_rotations, skeleton, {Eigen::Vector3d(0, 0, 0), rotations, {}});
    CHECK_THAT(positions[1], is_near(Eigen::Vector3d(-1, 0, 0), 1e-12));
    CHECK_THAT(positions[2], is_near(Eigen::Vector3d(-1, 0, -0.5), 1e-12));

    std::vector<Eigen::Vector3d> end_sites(1);
    end_site_positions(end_sites, skeleton, positions, model_rotations);
    CHECK_THAT(end_sites[0], is_near(Eigen::Vector3d(-1, 0, -0.75), 1e-12));
}

TEST_CASE("forward_kinematics: animated translations replace rest offsets", "[core]") {
    const Skeleton skeleton = chain();
    const std::vector<Eigen::Quaterniond> rotations(3, Eigen::Quaterniond::Identity());
    const std::vector<Eigen::Vector3d> translations = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(0, 0, 3)};
    std::vector<Eigen::Vector3d> positions(3);
    std::vector<Eigen::Quaterniond> model_rotations(3);
    forward_kinematics(positions, model_rotations, skeleton, {Eigen::Vector3d(1, 0, 0), rotations, translations});
    CHECK_THAT(positions[0], is_near(Eigen::Vector3d(1, 0, 0), 1e-12)); // the root follows root_translation
    CHECK_THAT(positions[1], is_near(Eigen::Vector3d(1, 2, 0), 1e-12));
    CHECK_THAT(positions[2], is_near(Eigen::Vector3d(1, 2, 3), 1e-12));
}
