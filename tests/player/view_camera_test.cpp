#include "scene_geometry.h"
#include "view_camera.h"
#include "viewer_settings.h"

#include <catch2/catch.hpp>

using namespace kumite::view;

namespace {

Eigen::Vector2f ndc_of(const ViewProjection& vp, const Eigen::Vector3f& p) {
    Eigen::Vector2f ndc;
    float depth = 0.0f;
    REQUIRE(project_point(vp, p, ndc, depth));
    return ndc;
}

} // namespace

TEST_CASE("view: the off-axis projection maps the screen's corners to the viewport's corners from any eye", "[player]") {
    ScreenCorners screen; // 3 m x 2.25 m wall at z = -0.5
    const Eigen::Vector3f upper_right = screen.lower_right + (screen.upper_left - screen.lower_left);
    for (const Eigen::Vector3f& eye : {Eigen::Vector3f(0.0f, 1.1f, 1.0f), Eigen::Vector3f(-1.2f, 1.7f, 0.3f), Eigen::Vector3f(1.4f, 0.4f, 2.5f)}) {
        const ViewProjection vp = off_axis_view_projection(screen, eye, 0.05f, 50.0f);
        CHECK((ndc_of(vp, screen.lower_left) - Eigen::Vector2f(-1, -1)).norm() < 1e-4f);
        CHECK((ndc_of(vp, screen.lower_right) - Eigen::Vector2f(1, -1)).norm() < 1e-4f);
        CHECK((ndc_of(vp, screen.upper_left) - Eigen::Vector2f(-1, 1)).norm() < 1e-4f);
        CHECK((ndc_of(vp, upper_right) - Eigen::Vector2f(1, 1)).norm() < 1e-4f);
        CHECK((vp.eye - eye).norm() < 1e-6f);
    }
    // A point between the eye and the screen moves on the picture as the eye moves (motion parallax), a point
    // on the screen does not.
    const Eigen::Vector3f on_screen(0.3f, 1.0f, -0.5f), in_room(0.3f, 1.0f, 0.7f);
    const ViewProjection left = off_axis_view_projection(screen, {-0.5f, 1.6f, 1.5f}, 0.05f, 50.0f);
    const ViewProjection right = off_axis_view_projection(screen, {0.5f, 1.6f, 1.5f}, 0.05f, 50.0f);
    CHECK((ndc_of(left, on_screen) - ndc_of(right, on_screen)).norm() < 1e-4f);
    CHECK((ndc_of(left, in_room) - ndc_of(right, in_room)).norm() > 0.1f);
    // An eye behind the wall is kept in front of it: the matrices stay finite.
    const ViewProjection behind = off_axis_view_projection(screen, {0.0f, 1.0f, -3.0f}, 0.05f, 50.0f);
    CHECK(behind.projection.allFinite());
    CHECK(behind.view.allFinite());
}

TEST_CASE("view: the orbit camera frames a box and picking finds the capsule under the point", "[player]") {
    OrbitCamera camera;
    camera.frame(Eigen::AlignedBox3f(Eigen::Vector3f(-0.5f, 0.0f, -0.5f), Eigen::Vector3f(0.5f, 2.0f, 0.5f)));
    const ViewProjection vp = camera.view_projection(16.0f / 9.0f);
    CHECK(ndc_of(vp, {0.0f, 1.0f, 0.0f}).norm() < 1e-4f);
    for (const Eigen::Vector3f& corner : {Eigen::Vector3f(-0.5f, 0.0f, -0.5f), Eigen::Vector3f(0.5f, 2.0f, 0.5f)}) {
        CHECK(ndc_of(vp, corner).cwiseAbs().maxCoeff() <= 1.0f);
    }
    Scene scene;
    scene.capsules.push_back({{0.0f, 0.5f, 0.0f}, {0.0f, 1.5f, 0.0f}, 0.05f, {1, 1, 1}, 7});
    scene.capsules.push_back({{0.0f, 0.5f, -3.0f}, {0.0f, 1.5f, -3.0f}, 0.05f, {1, 1, 1}, 8}); // hidden behind the first
    scene.capsules.push_back({{1.0f, 0.5f, 0.0f}, {1.0f, 1.5f, 0.0f}, 0.05f, {1, 1, 1}, -1}); // not pickable
    CHECK(pick_capsule(scene, vp, ndc_of(vp, {0.0f, 1.0f, 0.0f})) == 7);
    CHECK(pick_capsule(scene, vp, ndc_of(vp, {1.0f, 1.0f, 0.0f})) == -1);
    CHECK(pick_capsule(scene, vp, ndc_of(vp, {0.4f, 1.0f, 0.0f})) == -1);
    camera.orbit(100.0f, 0.0f);
    camera.zoom(2.0f);
    const ViewProjection turned = camera.view_projection(1.0f);
    CHECK(pick_capsule(scene, turned, ndc_of(turned, {0.0f, 1.2f, 0.0f})) == 7);
}

TEST_CASE("view: viewer settings are read with clear errors", "[player]") {
    const auto good = viewer_settings_parse(R"({"camera": "head_coupled", "stereo": "side_by_side", "eye_separation_m": 0.06,
        "screen": {"lower_left": [-2, 0.2, -1], "lower_right": [2, 0.2, -1], "upper_left": [-2, 2.7, -1]}, "window": [800, 600]})", "room.json");
    REQUIRE(good);
    CHECK(good->camera == Projection::head_coupled);
    CHECK(good->stereo == StereoMode::side_by_side);
    CHECK(good->coupling.screen.lower_right.x() == 2.0f);
    CHECK(good->width == 800);
    CHECK(good->orbit_yaw_deg == Approx(68.75f)); // the orbit camera's start, unchanged when not given
    const auto orbit = viewer_settings_parse(R"({"orbit": {"yaw_deg": -30, "pitch_deg": 5, "distance_m": 2.5, "target": [0, 1.4, 0.6]}})", "room.json");
    REQUIRE(orbit);
    CHECK(orbit->orbit_yaw_deg == -30.0f);
    CHECK(orbit->orbit_pitch_deg == 5.0f);
    CHECK(orbit->orbit_distance_m == 2.5f);
    CHECK(orbit->orbit_target.y() == Approx(1.4f));
    const std::pair<const char*, const char*> bad[] = {
        {"[1, 2", "not JSON"},
        {R"({"camera": "fisheye"})", "\"camera\""},
        {R"({"orbit": [1, 2]})", "\"orbit\""},
        {R"({"orbit": {"pitch_deg": 95}})", "orbit.pitch_deg"},
        {R"({"orbit": {"distance_m": "far"}})", "orbit.distance_m"},
        {R"({"orbit": {"target": [0, 1]}})", "orbit.target"},
        {R"({"stereo": true})", "\"stereo\""},
        {R"({"eye_separation_m": 3})", "eye_separation_m"},
        {R"({"screen": {"lower_left": [0, 0, 0], "lower_right": [1, 0, 0]}})", "screen.upper_left"},
        {R"({"screen": {"lower_left": [0, 0, 0], "lower_right": [1, 0, 0], "upper_left": [1, 1, 0]}})", "right angles"},
        {R"({"screen": {"lower_left": [0, 0, 0], "lower_right": [0, 0, 0], "upper_left": [0, 1, 0]}})", "1 cm"},
        {R"({"window": [10, 10]})", "\"window\""},
    };
    for (const auto& [text, expected] : bad) {
        const auto parsed = viewer_settings_parse(text, "room.json");
        REQUIRE_FALSE(parsed);
        CHECK_THAT(parsed.error().message, Catch::Contains("room.json") && Catch::Contains(expected));
    }
}
