// The fighter's fists (fist_pose.h): the human body's fingers curl into its palm and its thumb folds across them,
// through the decoder as the fighter is shown, on the skinned mesh too; the mannequins, which have no fingers,
// are left as they were.

#include "kumite/core/fist_pose.h"
#include "kumite/core/forward_kinematics.h"
#include "kumite/core/mir.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/gltf_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

struct Posed {
    std::vector<Eigen::Vector3d> positions;
    std::vector<Eigen::Quaterniond> rotations;
};

Posed pose_with(const Skeleton& skeleton, const Pose& rest, std::span<const Eigen::Quaterniond> local_rotations) {
    Pose pose = rest;
    pose.local_rotations.assign(local_rotations.begin(), local_rotations.end());
    Posed out{std::vector<Eigen::Vector3d>(std::size_t(skeleton.joint_count())), std::vector<Eigen::Quaterniond>(std::size_t(skeleton.joint_count()))};
    forward_kinematics(out.positions, out.rotations, skeleton, pose.view());
    return out;
}

// A leaf's tip: its End Site in the pose.
Eigen::Vector3d tip_of(const Skeleton& skeleton, const Posed& posed, int leaf) {
    for (const EndSite& end : skeleton.end_sites) {
        if (end.joint == leaf) return posed.positions[std::size_t(leaf)] + posed.rotations[std::size_t(leaf)] * end.offset_in_joint;
    }
    FAIL("joint " << skeleton.names[std::size_t(leaf)] << " has no End Site");
    return {};
}

GltfCharacter human() {
    Result<GltfCharacter> read = gltf_read_file(kumite::test::source_dir() / "data/bodies/quaternius-adventurer/Adventurer.glb");
    REQUIRE(read.has_value());
    return std::move(*read);
}

int joint_named(const Skeleton& skeleton, const std::string& name) {
    const std::optional<int> joint = skeleton.find(name);
    REQUIRE(joint.has_value());
    return *joint;
}

} // namespace

TEST_CASE("fist pose: the human body's fingertips curl into its palms and its thumbs fold across", "[core]") {
    const GltfCharacter body = human();
    const Skeleton& skeleton = body.character.clip.skeleton;
    const Pose rest = body.character.clip.rest_pose();
    const std::vector<Eigen::Quaterniond> fist = fist_local_rotations(skeleton, body.character.body_map, rest_model_positions(skeleton));
    const Posed open = pose_with(skeleton, rest, rest.local_rotations);
    const Posed closed = pose_with(skeleton, rest, fist);

    for (const char* side : {"L", "R"}) {
        CAPTURE(side);
        const std::string s = side;
        const int hand = joint_named(skeleton, "Hand." + s);
        const Eigen::Vector3d wrist = closed.positions[std::size_t(hand)];
        REQUIRE((wrist - open.positions[std::size_t(hand)]).norm() < 1e-9); // the arm did not move
        // The hand points along the forearm, sideways in the T-pose; its palm faces down.
        const Eigen::Vector3d outward = (wrist - open.positions[std::size_t(joint_named(skeleton, "LowerArm." + s))]).normalized();
        for (const char* finger : {"Index", "Middle", "Ring", "Pinky"}) {
            CAPTURE(finger);
            const int knuckle = joint_named(skeleton, std::string(finger) + "2." + s);
            const int middle = joint_named(skeleton, std::string(finger) + "3." + s);
            const int last = joint_named(skeleton, std::string(finger) + "4." + s);
            const Eigen::Vector3d open_tip = tip_of(skeleton, open, last), closed_tip = tip_of(skeleton, closed, last);
            CHECK((closed_tip - wrist).norm() < 0.6 * (open_tip - wrist).norm());
            // Curled to the palm's side (down), the tip back behind the knuckle towards the wrist.
            CHECK(closed.positions[std::size_t(middle)].y() < closed.positions[std::size_t(knuckle)].y() - 0.02);
            CHECK((closed_tip - wrist).dot(outward) < (closed.positions[std::size_t(knuckle)] - wrist).dot(outward) - 0.02);
            // Bent at the knuckle by 80 to 100 degrees.
            const Eigen::Vector3d open_bone = open.positions[std::size_t(middle)] - open.positions[std::size_t(knuckle)];
            const Eigen::Vector3d closed_bone = closed.positions[std::size_t(middle)] - closed.positions[std::size_t(knuckle)];
            const double knuckle_deg = std::acos(std::clamp(open_bone.normalized().dot(closed_bone.normalized()), -1.0, 1.0)) * 180.0 / 3.14159265358979;
            CHECK(knuckle_deg > 80.0);
            CHECK(knuckle_deg < 100.0);
        }
        // The thumb's tip goes across the palm (from the index's edge, +Z in the T-pose, towards the little
        // finger's), under the knuckles' line, and nearer the wrist than the index's curled tip is to the knuckles.
        const int thumb = joint_named(skeleton, "Thumb3." + s);
        const Eigen::Vector3d open_thumb = tip_of(skeleton, open, thumb), closed_thumb = tip_of(skeleton, closed, thumb);
        CHECK(closed_thumb.z() < open_thumb.z() - 0.04);
        CHECK(closed_thumb.y() < closed.positions[std::size_t(joint_named(skeleton, "Index2." + s))].y() - 0.02);
        CHECK((closed_thumb - open_thumb).norm() > 0.05);
    }
    // Nothing but the fingers moves: every joint outside the hands keeps its rest rotation.
    for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
        const bool in_hand = skeleton.is_ancestor(joint_named(skeleton, "Hand.L"), joint) || skeleton.is_ancestor(joint_named(skeleton, "Hand.R"), joint);
        const bool is_hand = joint == joint_named(skeleton, "Hand.L") || joint == joint_named(skeleton, "Hand.R");
        if (!in_hand || is_hand) CHECK(fist[std::size_t(joint)].angularDistance(Eigen::Quaterniond::Identity()) < 1e-12);
    }
}

TEST_CASE("fist pose: the left fist is the right one mirrored", "[core]") {
    const GltfCharacter body = human();
    const Skeleton& skeleton = body.character.clip.skeleton;
    const Pose rest = body.character.clip.rest_pose();
    const Posed closed = pose_with(skeleton, rest, fist_local_rotations(skeleton, body.character.body_map, rest_model_positions(skeleton)));
    for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
        const std::string& name = skeleton.names[std::size_t(joint)];
        if (!name.ends_with(".L")) continue;
        const int partner = joint_named(skeleton, name.substr(0, name.size() - 2) + ".R");
        const Eigen::Vector3d mirrored(-closed.positions[std::size_t(partner)].x(), closed.positions[std::size_t(partner)].y(),
                                       closed.positions[std::size_t(partner)].z());
        CAPTURE(name);
        CHECK((closed.positions[std::size_t(joint)] - mirrored).norm() < 1e-3);
    }
}

TEST_CASE("fist pose: the decoder shows the fingers as fists, and the skinned hand closes with them", "[core]") {
    const GltfCharacter body = human();
    const Skeleton& skeleton = body.character.clip.skeleton;
    const Pose rest = body.character.clip.rest_pose();
    Result<RestAnatomy> anatomy = rest_anatomy_build(body.character.clip, body.character.body_map);
    REQUIRE(anatomy.has_value());
    MirEncoder encoder(skeleton, *anatomy);
    MirFrame frame;
    encoder.encode(frame, rest.view());
    MirDecoder decoder(skeleton, *anatomy, {});
    Pose decoded;
    decoder.decode(decoded, frame);
    const int index = joint_named(skeleton, "Index3.R");
    CHECK(decoded.local_rotations[std::size_t(index)].angularDistance(anatomy->fist_local_rotations[std::size_t(index)]) < 1e-6);
    CHECK(anatomy->fist_local_rotations[std::size_t(index)].angularDistance(Eigen::Quaterniond::Identity()) > 1.0);

    // The mesh: the hands' vertices (those bound most to a joint below a wrist) no farther from their wrist than
    // 75% of where the open hand had them.
    const std::size_t joints = std::size_t(skeleton.joint_count());
    std::vector<Eigen::Matrix4f> open_skin(joints), closed_skin(joints);
    const Posed open = pose_with(skeleton, rest, rest.local_rotations);
    skin_matrices(open_skin, body.mesh, open.positions, open.rotations);
    skin_matrices(closed_skin, body.mesh, decoder.model_positions(), decoder.model_rotations());
    for (const char* side : {"L", "R"}) {
        const int hand = joint_named(skeleton, std::string("Hand.") + side);
        double open_reach = 0.0, closed_reach = 0.0;
        for (std::size_t v = 0; v < body.mesh.vertex_count(); ++v) {
            const auto& weights = body.mesh.weights[v];
            const int heaviest = body.mesh.joints[v][std::size_t(std::max_element(weights.begin(), weights.end()) - weights.begin())];
            if (heaviest == hand || !skeleton.is_ancestor(hand, heaviest)) continue;
            open_reach = std::max(open_reach, double((skin_vertex(body.mesh, open_skin, v) - open.positions[std::size_t(hand)].cast<float>()).norm()));
            closed_reach = std::max(closed_reach, double((skin_vertex(body.mesh, closed_skin, v) - decoder.model_positions()[std::size_t(hand)].cast<float>()).norm()));
        }
        CAPTURE(side, open_reach, closed_reach);
        CHECK(open_reach > 0.15);
        CHECK(closed_reach < 0.75 * open_reach);
    }
}

TEST_CASE("fist pose: the mannequins, whose hands have no fingers, are left as they were", "[core]") {
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) {
        CAPTURE(name);
        Result<BvhFile> file = bvh_read_file(kumite::test::source_dir() / "data/characters" / (std::string(name) + ".bvh"));
        REQUIRE(file.has_value());
        const Skeleton& skeleton = file->clip.skeleton;
        const std::vector<Eigen::Quaterniond> fist = fist_local_rotations(skeleton, file->body_map, rest_model_positions(skeleton));
        REQUIRE(fist.size() == std::size_t(skeleton.joint_count()));
        for (const Eigen::Quaterniond& rotation : fist) CHECK(rotation.angularDistance(Eigen::Quaterniond::Identity()) < 1e-12);
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        REQUIRE(anatomy.has_value());
        REQUIRE(anatomy->fist_local_rotations.size() == fist.size());
        for (const Eigen::Quaterniond& rotation : anatomy->fist_local_rotations) CHECK(rotation.angularDistance(Eigen::Quaterniond::Identity()) < 1e-12);
    }
}
