// The headset's geometry as matrices (runtime/xr/xr_view_math.h): the head's centre behind the eyes, and each
// eye's asymmetric frustum — a point on an edge of the runtime's field of view lands on that edge of the image.

#include "xr_view_math.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kumite::view;

namespace {

Eigen::Vector3f ndc_of(const ViewProjection& vp, const Eigen::Vector3f& world) {
    const Eigen::Vector4f clip = vp.projection * vp.view * world.homogeneous();
    return clip.head<3>() / clip.w();
}

} // namespace

TEST_CASE("xr view math: the head's centre is 9 cm behind the eyes, turning with the head", "[xr]") {
    XrPoseWorld view;
    view.position = {0.2f, 1.6f, 1.0f};
    CHECK((head_centre_from_view(view) - Eigen::Vector3f(0.2f, 1.6f, 1.09f)).norm() < 1e-6f);
    view.orientation = Eigen::Quaternionf(Eigen::AngleAxisf(float(M_PI / 2), Eigen::Vector3f::UnitY())); // looking along -X
    CHECK((head_centre_from_view(view) - Eigen::Vector3f(0.29f, 1.6f, 1.0f)).norm() < 1e-6f);
    const Eigen::Vector3f eyes = view_position_for_head_centre({0.0f, 1.7f, 1.2f}, view.orientation);
    view.position = eyes;
    CHECK((head_centre_from_view(view) - Eigen::Vector3f(0.0f, 1.7f, 1.2f)).norm() < 1e-6f);
}

TEST_CASE("xr view math: an asymmetric field of view puts its four edges on the image's edges", "[xr]") {
    XrPoseWorld eye;
    eye.position = {-0.0315f, 1.6f, 2.0f};
    eye.orientation = Eigen::Quaternionf(Eigen::AngleAxisf(0.4f, Eigen::Vector3f::UnitY()));
    const XrFovRad fov{-0.9f, 0.7f, 0.8f, -0.95f}; // a left eye: wider to the left, taller downwards
    const ViewProjection vp = xr_eye_view_projection(eye, fov, 0.05f, 100.0f);
    const float depth = 3.0f;
    auto world_at = [&](float tan_x, float tan_y) {
        return Eigen::Vector3f(eye.position + eye.orientation * Eigen::Vector3f(tan_x * depth, tan_y * depth, -depth));
    };
    CHECK(ndc_of(vp, world_at(std::tan(fov.left), 0.0f)).x() == Approx(-1.0f).margin(1e-4));
    CHECK(ndc_of(vp, world_at(std::tan(fov.right), 0.0f)).x() == Approx(1.0f).margin(1e-4));
    CHECK(ndc_of(vp, world_at(0.0f, std::tan(fov.up))).y() == Approx(1.0f).margin(1e-4));
    CHECK(ndc_of(vp, world_at(0.0f, std::tan(fov.down))).y() == Approx(-1.0f).margin(1e-4));
    // Straight ahead is not the image's centre when the frustum is asymmetric.
    const Eigen::Vector3f ahead = ndc_of(vp, world_at(0.0f, 0.0f));
    CHECK(ahead.x() == Approx((std::tan(0.9f) - std::tan(0.7f)) / (std::tan(0.7f) + std::tan(0.9f))).margin(1e-4));
    CHECK(ahead.z() > -1.0f);
    CHECK(ahead.z() < 1.0f);
    CHECK((vp.eye - eye.position).norm() < 1e-6f);
}
