// The morphology-independent representation on real captures: exact on the actor's own skeleton, consistent
// under mirroring, and within the retargeting quality bounds on the five shipped characters.

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/mir_edit.h"
#include "kumite/core/retarget_clip.h"
#include "kumite/formats/bvh_reader.h"
#include "support/pose_matchers.h"
#include "support/test_paths.h"

using namespace kumite;

namespace {

std::optional<BvhFile> read_capture(const std::string& relative) {
    const std::filesystem::path path = kumite::test::mocap_root() / relative;
    if (!std::filesystem::exists(path)) return std::nullopt;
    Result<BvhFile> file = bvh_read_file(path);
    REQUIRE(file.has_value());
    return std::move(*file);
}

std::vector<Eigen::Vector3d> positions_of(const Skeleton& skeleton, const PoseView& pose) {
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    forward_kinematics(positions, rotations, skeleton, pose);
    return positions;
}

const char* const k_self_captures[] = {"bandai-namco-1/dataset-1_walk_normal_001.bvh", "bandai-namco-1/dataset-1_kick_normal_001.bvh",
                                       "cmu-hahne-mb/02_05.bvh", "cmu-iclone-cc4/002_05.bvh"};

} // namespace

TEST_CASE("mir: encode -> decode onto the actor's own skeleton reproduces the capture within 1 mm", "[core][corpus]") {
    for (const char* relative : k_self_captures) {
        const std::optional<BvhFile> file = read_capture(relative);
        if (!file) {
            WARN("missing " << relative);
            continue;
        }
        INFO(relative);
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        REQUIRE(anatomy.has_value());
        MirEncoder encoder(file->clip.skeleton, *anatomy);
        MirDecoder decoder(file->clip.skeleton, *anatomy, file->clip.skeleton.names);
        MirFrame frame;
        Pose decoded;
        double worst = 0.0;
        // Decoded poses stand on y = 0; the capture stands on its own floor.
        const Eigen::Vector3d floor(0.0, anatomy->floor_y, 0.0);
        for (int f = 0; f < file->clip.frame_count(); ++f) {
            encoder.encode(frame, file->clip.pose(f));
            decoder.decode(decoded, frame);
            const auto original = positions_of(file->clip.skeleton, file->clip.pose(f));
            const auto again = positions_of(file->clip.skeleton, decoded.view());
            for (size_t joint = 0; joint < original.size(); ++joint) worst = std::max(worst, (original[joint] - floor - again[joint]).norm());
        }
        CHECK(worst < 0.001);

        // The whole pipeline, foot locking included, changes nothing on the actor's own skeleton either.
        RetargetReport report;
        const Clip self = retarget_clip(report, file->clip, *anatomy, file->clip.skeleton, *anatomy);
        double worst_clip = 0.0;
        for (int f = 0; f < self.frame_count(); ++f) {
            const auto original = positions_of(file->clip.skeleton, file->clip.pose(f));
            const auto again = positions_of(self.skeleton, self.pose(f));
            for (size_t joint = 0; joint < original.size(); ++joint) worst_clip = std::max(worst_clip, (original[joint] - floor - again[joint]).norm());
        }
        CHECK(worst_clip < 0.001);
        CHECK(report.limb_extension_error < 1e-6);
    }
}

TEST_CASE("mir: the encoding of a mirrored capture is the mirror of its encoding", "[core][corpus]") {
    // Bandai's offsets are symmetric to the micrometre, not to rounding, so the two agree to about 1e-6.
    constexpr double k_frame_tolerance_rad = 1e-3, k_extremity_tolerance = 1e-4, k_swivel_tolerance_rad = 1e-3;
    const std::optional<BvhFile> file = read_capture("bandai-namco-1/dataset-1_kick_normal_001.bvh");
    if (!file) return;
    Result<MirrorSymmetry> symmetry = mirror_symmetry_find(file->clip.skeleton);
    REQUIRE(symmetry.has_value());
    const Clip mirrored = clip_mirror(file->clip, *symmetry);
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    REQUIRE(anatomy.has_value());

    MirEncoder encoder(file->clip.skeleton, *anatomy);
    MirFrame original, of_mirrored, mirror_of_original;
    for (int f = 0; f < file->clip.frame_count(); f += 7) {
        INFO("frame " << f);
        encoder.encode(original, file->clip.pose(f));
        encoder.encode(of_mirrored, mirrored.pose(f));
        mir_frame_mirror(mirror_of_original, original, *symmetry, file->clip.skeleton.parents);
        CHECK_THAT(of_mirrored.hip_centre, kumite::test::is_near(mirror_of_original.hip_centre, 1e-3));
        for (int part = 0; part < k_body_part_count; ++part) {
            if (!original.has_part[part]) continue;
            INFO("part " << body_part_name(BodyPart(part)));
            CHECK_THAT(of_mirrored.part_frames[part], kumite::test::is_near(mirror_of_original.part_frames[part], k_frame_tolerance_rad));
        }
        for (int limb = 0; limb < k_limb_count; ++limb) {
            INFO("limb " << limb);
            CHECK_THAT(of_mirrored.extremity[limb], kumite::test::is_near(mirror_of_original.extremity[limb], k_extremity_tolerance));
            CHECK(std::remainder(of_mirrored.swivel[limb] - mirror_of_original.swivel[limb], 2 * 3.14159265358979) ==
                  Approx(0).margin(k_swivel_tolerance_rad));
        }
    }
}

TEST_CASE("clip_mirror: a right kick becomes a left kick, and twice is the original", "[core][corpus]") {
    const std::optional<BvhFile> file = read_capture("bandai-namco-1/dataset-1_kick_normal_001.bvh");
    if (!file) return;
    Result<MirrorSymmetry> symmetry = mirror_symmetry_find(file->clip.skeleton);
    REQUIRE(symmetry.has_value());
    const Clip mirrored = clip_mirror(file->clip, *symmetry);
    const Clip twice = clip_mirror(mirrored, *symmetry);
    const int foot_l = file->body_map.joint(BodyPart::foot_l), foot_r = file->body_map.joint(BodyPart::foot_r);
    const int apex = 60; // the first right kick's apex
    const auto original = positions_of(file->clip.skeleton, file->clip.pose(apex));
    const auto reflected = positions_of(mirrored.skeleton, mirrored.pose(apex));
    CHECK_THAT(reflected[foot_l], kumite::test::is_near(symmetry->reflection * original[foot_r], 1e-6));
    CHECK(reflected[foot_l].y() > 0.5); // the left foot is up now
    const auto back = positions_of(twice.skeleton, twice.pose(apex));
    for (size_t joint = 0; joint < back.size(); ++joint) CHECK_THAT(back[joint], kumite::test::is_near(original[joint], 1e-9));
}

TEST_CASE("clip_mirror: joints numbered on one side only (SNU's LeftShoulder1, RightShoulder) still pair", "[core][corpus]") {
    const std::optional<BvhFile> file = read_capture("snu-boxing/boxman_hited_dir.bvh");
    if (!file) return;
    Result<MirrorSymmetry> symmetry = mirror_symmetry_find(file->clip.skeleton);
    REQUIRE(symmetry.has_value());
    const Skeleton& skeleton = file->clip.skeleton;
    auto joint = [&](const char* name) { return int(std::find(skeleton.names.begin(), skeleton.names.end(), name) - skeleton.names.begin()); };
    CHECK(symmetry->partner[joint("LeftShoulder1")] == joint("RightShoulder"));
    CHECK(symmetry->partner[joint("LeftShoulder1Dummy")] == joint("RightShoulderDummy"));
    CHECK(symmetry->partner[joint("RightShoulder")] == joint("LeftShoulder1"));
    const Clip mirrored = clip_mirror(file->clip, *symmetry);
    const int hand_l = file->body_map.joint(BodyPart::hand_l), hand_r = file->body_map.joint(BodyPart::hand_r);
    const int frame = 88; // the first reaction's largest displacement, the left glove dropped
    const auto original = positions_of(skeleton, file->clip.pose(frame));
    const auto reflected = positions_of(mirrored.skeleton, mirrored.pose(frame));
    // (within a millimetre: the capture's two sides are not exact mirror images)
    CHECK_THAT(reflected[hand_r], kumite::test::is_near(symmetry->reflection * original[hand_l], 1e-3));
    CHECK_THAT(reflected[hand_l], kumite::test::is_near(symmetry->reflection * original[hand_r], 1e-3));
}

TEST_CASE("retarget: locomotion, strikes and a CMU capture onto all five characters", "[core][corpus]") {
    const std::filesystem::path characters = kumite::test::source_dir() / "data/characters";
    std::vector<std::pair<std::string, BvhFile>> targets;
    for (const char* name : {"kid", "scout", "brawler", "giant", "runner"}) {
        Result<BvhFile> character = bvh_read_file(characters / (std::string(name) + ".bvh"));
        REQUIRE(character.has_value());
        targets.emplace_back(name, std::move(*character));
    }
    for (const char* relative : {"bandai-namco-1/dataset-1_walk_normal_001.bvh", "bandai-namco-1/dataset-1_run_normal_001.bvh",
                                 "bandai-namco-1/dataset-1_dash_active_001.bvh", "bandai-namco-1/dataset-1_walk-back_sad_001.bvh",
                                 "bandai-namco-1/dataset-1_walk-left_normal_001.bvh", "bandai-namco-1/dataset-1_walk-right_normal_001.bvh",
                                 "bandai-namco-1/dataset-1_kick_normal_001.bvh", "bandai-namco-1/dataset-1_punch_normal_001.bvh",
                                 "bandai-namco-1/dataset-1_punch_normal_002.bvh", "bandai-namco-1/dataset-1_slash_normal_002.bvh",
                                 "cmu-hahne-mb/02_05.bvh"}) {
        const std::optional<BvhFile> source = read_capture(relative);
        if (!source) {
            WARN("missing " << relative);
            continue;
        }
        Result<RestAnatomy> source_anatomy = rest_anatomy_build(source->clip, source->body_map);
        REQUIRE(source_anatomy.has_value());
        for (const auto& [name, character] : targets) {
            Result<RestAnatomy> target_anatomy = rest_anatomy_build(character.clip, character.body_map);
            REQUIRE(target_anatomy.has_value());
            RetargetReport report;
            const Clip output = retarget_clip(report, source->clip, *source_anatomy, character.clip.skeleton, *target_anatomy);
            INFO(relative << " onto " << name);
            CHECK(output.frame_count() == source->clip.frame_count());
            CHECK(report.contacts > 0);
            CHECK(report.bone_length_error_m <= 1e-4);
            CHECK(report.foot_drift_m <= 0.02);
            CHECK(report.floor_penetration_m <= 0.01);
            // Planted feet stay exactly where they landed while the legs reach them; with both down, the hips take
            // the shift from which both legs keep (nearly) the source's extension (it was 0.015 on the giant's
            // punch_normal_002 with the feet's mean shift).
            CHECK(report.limb_extension_error <= 0.01);
        }
    }
}

TEST_CASE("rest_anatomy: a skeleton without limbs is refused with the missing part named", "[core]") {
    Clip clip;
    clip.skeleton.names = {"Hips", "Spine", "Head"};
    clip.skeleton.parents = {-1, 0, 1};
    clip.skeleton.rest_offsets = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0.2, 0), Eigen::Vector3d(0, 0.5, 0)};
    Result<RestAnatomy> anatomy = rest_anatomy_build(clip, detect_body_map(clip.skeleton));
    REQUIRE_FALSE(anatomy.has_value());
    CHECK_THAT(anatomy.error().message, Catch::Contains("body map has no"));
}

TEST_CASE("mir_frame_blend: between frames of two skeletons the shoulders stay on their way and the arms keep their reach", "[core][corpus]") {
    // Skeletons differ in how a clavicle's or upper arm's frame turns about its bone (the rest pose's secondary
    // axis): a frame encoded from one capture and one from another can be half a turn apart about the bone. A
    // blend between them (a strike taking over from the guard) moved a shoulder 9 cm up in one frame when the
    // frames were slerped whole, and the extremity, interpolated in those frames (or on a straight line), folded
    // the arm on the way: over these pairs a hand came 0.12 m nearer its shoulder than at either end (0.15 on a
    // straight line), the elbow bending and straightening in every blend. Every pair of these captures' first
    // frames, blended in 20 steps and decoded on the first: each shoulder stays near the straight way between its
    // ends, each hand's distance from its shoulder stays between the ends' (the arm swings, it does not fold), no
    // hand jumps.
    const char* const captures[] = {"bandai-namco-1/dataset-1_punch_normal_001.bvh", "cmu-hahne-mb/02_05.bvh", "cmu-iclone-cc4/002_05.bvh",
                                    "hachaj-kata/1-pinian_shodan.bvh", "snu-boxing/boxman_stand_dir_01.bvh"};
    struct Source { BvhFile file; RestAnatomy anatomy; MirFrame frame; };
    std::vector<Source> sources;
    for (const char* relative : captures) {
        std::optional<BvhFile> file = read_capture(relative);
        if (!file) continue;
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        REQUIRE(anatomy.has_value());
        MirEncoder encoder(file->clip.skeleton, *anatomy);
        MirFrame frame;
        encoder.encode(frame, file->clip.pose(0));
        frame.hip_centre = Eigen::Vector3d(0.0, frame.hip_centre.y(), 0.0); // side by side, not across the room
        sources.push_back(Source{std::move(*file), std::move(*anatomy), frame});
    }
    if (sources.size() < 2) {
        WARN("missing captures");
        return;
    }
    const Source& body = sources[0];
    MirDecoder decoder(body.file.clip.skeleton, body.anatomy, body.file.clip.skeleton.names);
    double worst_shoulder_off_m = 0.0, worst_reach_out_m = 0.0, largest_hand_step_m = 0.0;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        for (std::size_t j = 0; j < sources.size(); ++j) {
            if (i == j) continue;
            INFO(captures[i] << " -> " << captures[j]);
            std::vector<std::vector<Eigen::Vector3d>> path;
            MirFrame blended;
            Pose pose;
            for (int step = 0; step <= 20; ++step) {
                mir_frame_blend(blended, sources[i].frame, sources[j].frame, step / 20.0);
                decoder.decode(pose, blended);
                path.push_back(positions_of(body.file.clip.skeleton, pose.view()));
            }
            for (const Limb arm : {Limb::arm_l, Limb::arm_r}) {
                const std::size_t shoulder = std::size_t(body.anatomy.limbs[int(arm)].root), hand = std::size_t(body.anatomy.limbs[int(arm)].extremity);
                const Eigen::Vector3d from = path.front()[shoulder], way = path.back()[shoulder] - from;
                const double reach_a = (path.front()[hand] - path.front()[shoulder]).norm(), reach_b = (path.back()[hand] - path.back()[shoulder]).norm();
                for (std::size_t k = 0; k < path.size(); ++k) {
                    const Eigen::Vector3d& p = path[k][shoulder];
                    const double along = way.squaredNorm() > 1e-12 ? std::clamp((p - from).dot(way) / way.squaredNorm(), 0.0, 1.0) : 0.0;
                    const double off = (p - (from + along * way)).norm();
                    const double reach = (path[k][hand] - p).norm();
                    const double out = std::max({0.0, std::min(reach_a, reach_b) - reach, reach - std::max(reach_a, reach_b)});
                    worst_shoulder_off_m = std::max(worst_shoulder_off_m, off);
                    worst_reach_out_m = std::max(worst_reach_out_m, out);
                    CHECK(off < 0.12);
                    CHECK(out < 0.02);
                    if (k > 0) {
                        largest_hand_step_m = std::max(largest_hand_step_m, (path[k][hand] - path[k - 1][hand]).norm());
                        CHECK((path[k][hand] - path[k - 1][hand]).norm() < 0.15);
                    }
                }
            }
        }
    }
    WARN("farthest a shoulder left its straight way " << worst_shoulder_off_m << " m; a hand's reach out of its ends' " << worst_reach_out_m
                                                      << " m; largest hand step " << largest_hand_step_m << " m");
}
