#include "kumite/core/euler.h"
#include "support/pose_matchers.h"

#include <random>

using namespace kumite;
using kumite::test::is_near;

namespace {
const std::array<EulerOrder, 6> k_orders = {EulerOrder{{0, 1, 2}}, EulerOrder{{0, 2, 1}}, EulerOrder{{1, 0, 2}},
                                            EulerOrder{{1, 2, 0}}, EulerOrder{{2, 0, 1}}, EulerOrder{{2, 1, 0}}};
constexpr double k_pi = 3.14159265358979323846;
} // namespace

TEST_CASE("euler: rotations apply in the listed order", "[core]") {
    // ZXY with Z = 90 deg then X = 90 deg: R = Rz Rx, so the local +Y axis goes to Rz(Rx(+Y)) = Rz(+Z) = +Z.
    const Eigen::Quaterniond rotation = quaternion_from_euler({k_pi / 2, k_pi / 2, 0.0}, EulerOrder{{2, 0, 1}});
    CHECK_THAT(Eigen::Vector3d(rotation * Eigen::Vector3d::UnitY()), is_near(Eigen::Vector3d::UnitZ(), 1e-12));
    // And local +X goes to Rz(Rx(+X)) = Rz(+X) = +Y.
    CHECK_THAT(Eigen::Vector3d(rotation * Eigen::Vector3d::UnitX()), is_near(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST_CASE("euler: names list the axes in order", "[core]") {
    CHECK(EulerOrder{{2, 0, 1}}.name() == "ZXY");
    CHECK(EulerOrder{{0, 1, 2}}.name() == "XYZ");
}

TEST_CASE("euler: extraction gives back the rotation for every order", "[core]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(-k_pi, k_pi);
    for (const EulerOrder& order : k_orders) {
        for (int i = 0; i < 500; ++i) {
            const Eigen::Vector3d angles(angle(random), angle(random) / 2, angle(random));
            const Eigen::Quaterniond rotation = quaternion_from_euler(angles, order);
            const Eigen::Vector3d extracted = euler_from_quaternion(rotation, order);
            INFO("order " << order.name() << " angles " << angles.transpose());
            CHECK_THAT(quaternion_from_euler(extracted, order), is_near(rotation, 1e-9));
            CHECK(extracted.isApprox(angles, 1e-9)); // middle angle within (-pi/2, pi/2): unique
        }
    }
}

TEST_CASE("euler: extraction survives gimbal lock", "[core]") {
    for (const EulerOrder& order : k_orders) {
        for (double middle : {k_pi / 2, -k_pi / 2, k_pi / 2 - 1e-9}) {
            const Eigen::Quaterniond rotation = quaternion_from_euler({0.3, middle, -0.7}, order);
            INFO("order " << order.name() << " middle " << middle);
            CHECK_THAT(quaternion_from_euler(euler_from_quaternion(rotation, order), order), is_near(rotation, 1e-7));
        }
    }
}
