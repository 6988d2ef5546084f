#include "kumite/core/mir.h"
#include "kumite/core/two_bone_ik.h"
#include "support/pose_matchers.h"

using namespace kumite;
using kumite::test::is_near;

TEST_CASE("two_bone_ik: reaches the target with the bone lengths and the swivel asked for", "[core]") {
    const Eigen::Vector3d root(0.1, 1.4, 0.0), target(0.5, 1.1, 0.2), reference(0, -1, 0);
    for (double swivel : {0.0, 0.7, -1.2, 3.0}) {
        const TwoBoneSolution solution = two_bone_ik(root, target, 0.3, 0.28, swivel, reference);
        INFO("swivel " << swivel);
        CHECK(solution.reachable);
        CHECK_THAT(solution.extremity, is_near(target, 1e-12));
        CHECK((solution.middle - root).norm() == Approx(0.3).epsilon(1e-12));
        CHECK((target - solution.middle).norm() == Approx(0.28).epsilon(1e-12));
        CHECK(limb_swivel(root, solution.middle, target, reference) == Approx(std::remainder(swivel, 2 * 3.14159265358979)).margin(1e-9));
    }
}

TEST_CASE("two_bone_ik: an unreachable target ends on the line at full reach", "[core]") {
    const Eigen::Vector3d root = Eigen::Vector3d::Zero(), target(2.0, 0.0, 0.0);
    const TwoBoneSolution solution = two_bone_ik(root, target, 0.3, 0.28, 0.0, Eigen::Vector3d::UnitY());
    CHECK_FALSE(solution.reachable);
    CHECK_THAT(solution.extremity, is_near(Eigen::Vector3d(0.58, 0, 0), 1e-6));
    CHECK((solution.middle - root).norm() == Approx(0.3));
}

TEST_CASE("rotation_between: takes one direction onto another", "[core]") {
    const Eigen::Vector3d from(1, 2, 3), to(-2, 0.5, 1);
    CHECK_THAT(Eigen::Vector3d(rotation_between(from, to) * from.normalized()), is_near(to.normalized(), 1e-12));
}
