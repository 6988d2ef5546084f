#include "kumite/formats/body_map_file.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {
Skeleton two_joints() {
    Skeleton skeleton;
    skeleton.names = {"Root", "Wrist_Thing"};
    skeleton.parents = {-1, 0};
    skeleton.rest_offsets = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
    return skeleton;
}
} // namespace

TEST_CASE("body_map_file: overrides set and clear parts", "[formats]") {
    BodyMap detected;
    detected.set(BodyPart::pelvis, 0);
    Result<BodyMap> map = body_map_apply_override(detected, two_joints(),
                                                  R"({"body_map": {"hand_l": "Wrist_Thing", "pelvis": null}})", "o.json");
    REQUIRE(map.has_value());
    CHECK(map->joint(BodyPart::hand_l) == 1);
    CHECK_FALSE(map->has(BodyPart::pelvis));
}

TEST_CASE("body_map_file: errors name the file and the offending entry", "[formats]") {
    const Skeleton skeleton = two_joints();
    auto error = [&](const char* text) {
        Result<BodyMap> map = body_map_apply_override(BodyMap{}, skeleton, text, "o.json");
        REQUIRE_FALSE(map.has_value());
        return map.error().message;
    };
    CHECK_THAT(error("{not json"), Catch::Contains("o.json") && Catch::Contains("not valid JSON"));
    CHECK_THAT(error(R"({"elbow_l": "Root"})"), Catch::Contains("unknown body part \"elbow_l\""));
    CHECK_THAT(error(R"({"hand_l": "Nope"})"), Catch::Contains("\"Nope\""));
    CHECK_THAT(error(R"({"hand_l": 3})"), Catch::Contains("joint name or null"));
    CHECK_THAT(error(R"([1, 2])"), Catch::Contains("expected an object"));
}

TEST_CASE("body_map_file: the sidecar sits beside the capture", "[formats]") {
    CHECK(body_map_sidecar_path("a/walk.bvh") == std::filesystem::path("a/walk.bodymap.json"));
}
