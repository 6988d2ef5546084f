#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/bvh_writer.h"
#include "support/pose_matchers.h"
#include "support/test_paths.h"

#include <fstream>

using namespace kumite;

namespace {

// Largest distance between the joints of two clips over all frames, in metres.
double max_position_difference(const Clip& a, const Clip& b) {
    REQUIRE(a.frame_count() == b.frame_count());
    const int joints = a.skeleton.joint_count();
    std::vector<Eigen::Vector3d> pa(joints), pb(joints);
    std::vector<Eigen::Quaterniond> ra(joints), rb(joints);
    double worst = 0.0;
    for (int frame = 0; frame < a.frame_count(); ++frame) {
        forward_kinematics(pa, ra, a.skeleton, a.pose(frame));
        forward_kinematics(pb, rb, b.skeleton, b.pose(frame));
        for (int joint = 0; joint < joints; ++joint) worst = std::max(worst, (pa[joint] - pb[joint]).norm());
    }
    return worst;
}

void check_round_trip(const BvhFile& original, const std::string& name) {
    const std::string text = bvh_write_string(original.clip, original.layout, original.unit);
    BvhReadOptions options;
    options.unit = original.unit;
    Result<BvhFile> again = bvh_parse(text, name, options);
    INFO(name << ": " << (again ? "" : again.error().message));
    REQUIRE(again.has_value());
    CHECK(again->clip.skeleton.names == original.clip.skeleton.names);
    CHECK(again->clip.skeleton.parents == original.clip.skeleton.parents);
    CHECK(again->clip.skeleton.end_sites.size() == original.clip.skeleton.end_sites.size());
    REQUIRE(again->layout.joints.size() == original.layout.joints.size());
    for (size_t joint = 0; joint < original.layout.joints.size(); ++joint) {
        CHECK(again->layout.joints[joint].count == original.layout.joints[joint].count);
        CHECK(again->layout.joints[joint].channels == original.layout.joints[joint].channels);
    }
    CHECK(again->unit.name == original.unit.name);
    CHECK(again->clip.frame_time_s == Approx(original.clip.frame_time_s).epsilon(1e-9));
    const double tolerance = 1e-6 * std::max(original.height_m, 0.1);
    CHECK(max_position_difference(original.clip, again->clip) <= tolerance);
}

} // namespace

TEST_CASE("bvh_writer: round trip keeps layout and positions on a synthetic clip", "[formats]") {
    const std::string text =
        "HIERARCHY\nROOT Hips\n{\n OFFSET 1 2 3\n CHANNELS 6 Yrotation Xposition Zrotation Yposition Xrotation Zposition\n"
        " JOINT a:b\n {\n  OFFSET 0 10 0\n  CHANNELS 3 Xrotation Zrotation Yrotation\n  End Site\n  {\n   OFFSET 0 5 0\n  }\n }\n"
        " JOINT c\n {\n  OFFSET 4 0 0\n  CHANNELS 2 Zrotation Xposition\n }\n}\n"
        "MOTION\nFrames: 3\nFrame Time: 0.0083333\n"
        "10 1 20 2 30 3 40 50 60 70 5\n179 1 -179 2 89.9999 3 -90 90 -180 -45 6\n-170 0 170 0 -89 0 100 -100 135 10 7\n";
    BvhReadOptions options;
    options.unit = LengthUnit{"cm", 0.01};
    Result<BvhFile> file = bvh_parse(text, "synthetic.bvh", options);
    REQUIRE(file.has_value());
    check_round_trip(*file, "synthetic.bvh");
}

TEST_CASE("bvh_writer: canonical angles are written as they were read", "[formats]") {
    // Canonical triples (middle angle within +-90, others within +-180) come back unchanged; a gimbal-locked
    // triple keeps its first angle at zero; a non-canonical one is written as its canonical twin.
    const std::string text =
        "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
        "MOTION\nFrames: 4\nFrame Time: 0.1\n109.754 85.5453 -109.015\n179 10 -179\n0 -90 179.5\n-70 94 70\n";
    BvhReadOptions options;
    options.unit = LengthUnit{"cm", 0.01};
    Result<BvhFile> file = bvh_parse(text, "spin.bvh", options);
    REQUIRE(file.has_value());
    const std::string written = bvh_write_string(file->clip, file->layout, file->unit);
    CHECK_THAT(written, Catch::Contains("\n109.754 85.5453 -109.015\n179 10 -179\n0 -90 179.5\n110 86 -110\n"));
}

TEST_CASE("bvh_writer: deep hierarchies stay linear in size, tiny frame times stay exact", "[formats]") {
    Clip clip;
    const int depth = 2000;
    for (int joint = 0; joint < depth; ++joint) {
        clip.skeleton.names.push_back("j" + std::to_string(joint));
        clip.skeleton.parents.push_back(joint - 1);
        clip.skeleton.rest_offsets.push_back(Eigen::Vector3d(0, 0.01, 0));
    }
    clip.frame_time_s = 1.0 / 120000.0;
    clip.root_translations = {Eigen::Vector3d::Zero()};
    clip.local_rotations.assign(depth, Eigen::Quaterniond::Identity());
    const std::string text = bvh_write_string(clip, bvh_default_layout(clip), LengthUnit{"m", 1.0});
    CHECK(text.size() < 400u * depth); // ~2000 levels of tabs per line would be quadratic
    BvhReadOptions options;
    options.unit = LengthUnit{"m", 1.0};
    Result<BvhFile> again = bvh_parse(text, "deep.bvh", options);
    REQUIRE(again.has_value());
    CHECK(again->clip.skeleton.parents == clip.skeleton.parents);
    CHECK(again->clip.frame_time_s == clip.frame_time_s);
}

TEST_CASE("bvh_writer: a default layout writes any clip", "[formats]") {
    Clip clip;
    clip.skeleton.names = {"root", "tip"};
    clip.skeleton.parents = {-1, 0};
    clip.skeleton.rest_offsets = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 1, 0)};
    clip.root_translations = {Eigen::Vector3d(0.5, 1, 0)};
    clip.local_rotations = {Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized())),
                            Eigen::Quaterniond(Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitX()))};
    BvhFile file;
    file.clip = clip;
    file.layout = bvh_default_layout(clip);
    file.unit = LengthUnit{"m", 1.0};
    file.height_m = 1.0;
    CHECK(file.layout.channel_count() == 9);
    check_round_trip(file, "default.bvh");
}

TEST_CASE("bvh_writer: writes atomically and reports unwritable paths", "[formats]") {
    const std::filesystem::path dir = kumite::test::make_temp_dir("writer");
    Clip clip;
    clip.skeleton.names = {"root"};
    clip.skeleton.parents = {-1};
    clip.skeleton.rest_offsets = {Eigen::Vector3d::Zero()};
    const BvhLayout layout = bvh_default_layout(clip);
    REQUIRE(bvh_write_file(dir / "out.bvh", clip, layout, LengthUnit{"m", 1.0}).has_value());
    CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);

    Result<void> failed = bvh_write_file(dir / "missing-folder" / "out.bvh", clip, layout, LengthUnit{"m", 1.0});
    REQUIRE_FALSE(failed.has_value());
    CHECK_THAT(failed.error().message, Catch::Contains("missing-folder"));
}

TEST_CASE("bvh_writer: every shared capture round-trips to 1e-6 of its height", "[formats][corpus]") {
    const std::vector<std::filesystem::path> files = kumite::test::corpus_files();
    if (files.empty()) WARN("no captures under " << kumite::test::mocap_root());
    for (const std::filesystem::path& path : files) {
        Result<BvhFile> file = bvh_read_file(path);
        REQUIRE(file.has_value());
        check_round_trip(*file, path.string());
    }
}

TEST_CASE("bvh_writer: a skeleton indexed breadth-first (a glTF character's) writes its motion in the hierarchy's order", "[formats]") {
    // root -> a -> a2 and root -> b -> b2, indexed by depth: root, a, b, a2, b2. The file lists them depth-first
    // (root, a, a2, b, b2); each joint's channel values must follow it there.
    Clip clip;
    clip.skeleton.names = {"root", "a", "b", "a2", "b2"};
    clip.skeleton.parents = {-1, 0, 0, 1, 2};
    clip.skeleton.rest_offsets = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0.2, 0, 0), Eigen::Vector3d(-0.2, 0, 0), Eigen::Vector3d(0, -0.5, 0),
                                  Eigen::Vector3d(0, -0.4, 0.1)};
    clip.frame_time_s = 1.0 / 30.0;
    for (int frame = 0; frame < 3; ++frame) {
        clip.root_translations.push_back(Eigen::Vector3d(0.1 * frame, 1.0, 0.0));
        for (int joint = 0; joint < 5; ++joint) {
            clip.local_rotations.push_back(Eigen::Quaterniond(Eigen::AngleAxisd(0.2 + 0.3 * joint + 0.1 * frame, Eigen::Vector3d(1, joint, 2).normalized())));
        }
    }
    const std::string text = bvh_write_string(clip, bvh_default_layout(clip), LengthUnit{"m", 1.0});
    BvhReadOptions options;
    options.unit = LengthUnit{"m", 1.0};
    Result<BvhFile> again = bvh_parse(text, "breadth_first.bvh", options);
    REQUIRE(again.has_value());
    REQUIRE(again->clip.skeleton.names == std::vector<std::string>{"root", "a", "a2", "b", "b2"});
    std::vector<Eigen::Vector3d> written(5), read(5);
    std::vector<Eigen::Quaterniond> written_rotations(5), read_rotations(5);
    for (int frame = 0; frame < 3; ++frame) {
        forward_kinematics(written, written_rotations, clip.skeleton, clip.pose(frame));
        forward_kinematics(read, read_rotations, again->clip.skeleton, again->clip.pose(frame));
        for (int joint = 0; joint < 5; ++joint) {
            const int same = *again->clip.skeleton.find(clip.skeleton.names[std::size_t(joint)]);
            INFO("frame " << frame << " joint " << clip.skeleton.names[std::size_t(joint)]);
            CHECK((read[std::size_t(same)] - written[std::size_t(joint)]).norm() < 1e-8);
        }
    }
}
