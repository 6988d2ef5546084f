#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/bvh_reader.h"
#include "support/pose_matchers.h"

using namespace kumite;
using kumite::test::is_near;

namespace {

// A 1.7-unit-tall stick figure is too small to be centimetres; tests force the unit where it matters.
const char* const k_two_joint_bvh =
    "HIERARCHY\n"
    "ROOT hips\n"
    "{\n"
    "  OFFSET 0 0 0\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT chest\n"
    "  {\n"
    "    OFFSET 0 50 0\n"
    "    CHANNELS 3 Xrotation Yrotation Zrotation\n"
    "    End Site\n"
    "    {\n"
    "      OFFSET 0 30 0\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 2\n"
    "Frame Time: 0.5\n"
    "1 100 2 0 0 0 0 0 0\n"
    "0 100 0 90 0 0 0 0 90\n";

BvhReadOptions in_cm() {
    BvhReadOptions options;
    options.unit = LengthUnit{"cm", 0.01};
    return options;
}

std::string repeated(const std::string& text, int count) {
    std::string result;
    for (int i = 0; i < count; ++i) result += text;
    return result;
}

std::vector<Eigen::Vector3d> positions_at(const Clip& clip, int frame) {
    std::vector<Eigen::Vector3d> positions(clip.skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(clip.skeleton.joint_count());
    forward_kinematics(positions, rotations, clip.skeleton, clip.pose(frame));
    return positions;
}

} // namespace

TEST_CASE("bvh_reader: reads hierarchy, channels, frames and converts to metres", "[formats]") {
    Result<BvhFile> file = bvh_parse(k_two_joint_bvh, "two.bvh", in_cm());
    REQUIRE(file.has_value());
    const Clip& clip = file->clip;
    CHECK(clip.skeleton.names == std::vector<std::string>{"hips", "chest"});
    CHECK(clip.skeleton.parents == std::vector<int>{-1, 0});
    CHECK(clip.frame_count() == 2);
    CHECK(clip.frame_time_s == 0.5);
    CHECK(file->layout.channel_count() == 9);
    CHECK(file->layout.joints[0].rotation_order.name() == "ZXY");
    CHECK(file->layout.joints[1].rotation_order.name() == "XYZ");
    CHECK_THAT(clip.skeleton.rest_offsets[1], is_near(Eigen::Vector3d(0, 0.5, 0), 1e-12));
    REQUIRE(clip.skeleton.end_sites.size() == 1);
    CHECK_THAT(clip.skeleton.end_sites[0].offset_in_joint, is_near(Eigen::Vector3d(0, 0.3, 0), 1e-12));
    CHECK_FALSE(clip.has_local_translations());

    CHECK_THAT(positions_at(clip, 0)[1], is_near(Eigen::Vector3d(0.01, 1.5, 0.02), 1e-12));
    // Frame 1: hips turn 90 deg about Z, so the chest's +Y offset points to -X.
    CHECK_THAT(positions_at(clip, 1)[1], is_near(Eigen::Vector3d(-0.5, 1.0, 0), 1e-12));
}

TEST_CASE("bvh_reader: tolerates CRLF, tabs, blank lines, odd numbers and names with colons", "[formats]") {
    const std::string text =
        "HIERARCHY\r\n\r\nROOT mixamorig:Hips\r\n{\r\n\tOFFSET\t.5 2. 1e-05\r\n"
        "\tCHANNELS 6 Zrotation Xposition Yrotation Yposition Xrotation Zposition\n"
        "\tJOINT mixamorig:Spine\r\n\t{\r\n\t\tOFFSET 0 +10 0\n\t\tCHANNELS 3 Yrotation Zrotation Xrotation\r\n\t}\r\n}\r\n"
        "MOTION\r\n\r\nFrames:\t1\r\nFrame Time: .0083333\r\n  10 1.5 -.5 2. 1E+1 3  -0 0 0  \r\n\r\n";
    Result<BvhFile> file = bvh_parse(text, "odd.bvh", in_cm());
    REQUIRE(file.has_value());
    CHECK(file->clip.skeleton.names[0] == "mixamorig:Hips");
    CHECK(file->clip.frame_time_s == Approx(0.0083333));
    CHECK(file->layout.joints[0].rotation_order.name() == "ZYX");
    CHECK(file->layout.joints[1].rotation_order.name() == "YZX");
    // Root translation from the position channels, in their listed slots: X=1.5, Y=2., Z=3 (cm).
    CHECK_THAT(file->clip.root_translations[0], is_near(Eigen::Vector3d(0.015, 0.02, 0.03), 1e-12));
    CHECK(file->clip.skeleton.end_sites.empty());
}

TEST_CASE("bvh_reader: position channels on non-root joints replace the offset", "[formats]") {
    const std::string text =
        "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n"
        "JOINT b\n{\nOFFSET 0 10 0\nCHANNELS 4 Xposition Yposition Zposition Zrotation\n}\n}\n"
        "MOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0 0 20 0 0\n";
    Result<BvhFile> file = bvh_parse(text, "t.bvh", in_cm());
    REQUIRE(file.has_value());
    REQUIRE(file->clip.has_local_translations());
    CHECK_THAT(positions_at(file->clip, 0)[1], is_near(Eigen::Vector3d(0, 0.2, 0), 1e-12));
}

TEST_CASE("bvh_reader: detects the unit from the standing height", "[formats]") {
    // A stick human: legs 90, trunk 80 in file units; the same text read as cm, inches, metres and CMU units.
    auto human = [](double scale) {
        auto n = [&](double v) { return std::to_string(v * scale); };
        return "HIERARCHY\nROOT Hips\n{\nOFFSET 0 " + n(95) + " 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
               "JOINT Spine\n{\nOFFSET 0 " + n(20) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT Chest\n{\nOFFSET 0 " + n(25) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT Neck\n{\nOFFSET 0 " + n(15) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT Head\n{\nOFFSET 0 " + n(10) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\nEnd Site\n{\nOFFSET 0 " + n(10) + " 0\n}\n}\n}\n"
               "JOINT LeftArm\n{\nOFFSET " + n(18) + " 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT LeftForeArm\n{\nOFFSET " + n(28) + " 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT LeftHand\n{\nOFFSET " + n(25) + " 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n}\n}\n}\n}\n}\n"
               "JOINT LeftUpLeg\n{\nOFFSET " + n(10) + " " + n(-5) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT LeftLeg\n{\nOFFSET 0 " + n(-42) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
               "JOINT LeftFoot\n{\nOFFSET 0 " + n(-40) + " 0\nCHANNELS 3 Zrotation Xrotation Yrotation\nEnd Site\n{\nOFFSET 0 " + n(-8) + " " + n(10) + "\n}\n}\n}\n}\n}\n"
               "MOTION\nFrames: 1\nFrame Time: 0.033333\n0 " + n(95) + " 0" + repeated(" 0", 33) + "\n";
    };
    struct Case { double scale; const char* unit; };
    for (const Case& c : {Case{1.0, "cm"}, Case{0.01, "m"}, Case{1.0 / 2.54, "in"}, Case{0.01 / k_cmu_unit_m, "cmu"}, Case{10.0, "mm"}}) {
        Result<BvhFile> file = bvh_parse(human(c.scale), "human.bvh");
        INFO("unit " << c.unit << ": " << (file ? "" : file.error().message));
        REQUIRE(file.has_value());
        CHECK(file->unit.name == c.unit);
        CHECK(file->height_m == Approx(1.75).margin(1e-9)); // head top 95+20+25+15+10+10, sole at 0
        CHECK(file->body_map.mapped_count() == 11); // trunk, left arm without clavicle, left leg without toe
    }
}

TEST_CASE("bvh_reader: a forced unit overrides detection", "[formats]") {
    BvhReadOptions options;
    options.unit = LengthUnit{"m", 1.0};
    Result<BvhFile> file = bvh_parse(k_two_joint_bvh, "two.bvh", options);
    REQUIRE(file.has_value());
    CHECK_FALSE(file->unit_detected);
    CHECK_THAT(file->clip.skeleton.rest_offsets[1], is_near(Eigen::Vector3d(0, 50, 0), 1e-12));
}

TEST_CASE("bvh_reader: a hierarchy with zero frames is a skeleton", "[formats]") {
    std::string text = k_two_joint_bvh;
    text = text.substr(0, text.find("Frames:")) + "Frames: 0\nFrame Time: 0.5\n";
    Result<BvhFile> file = bvh_parse(text, "rest.bvh", in_cm());
    REQUIRE(file.has_value());
    CHECK(file->clip.frame_count() == 0);
}

TEST_CASE("bvh_reader: large files parse the same with two threads, errors included", "[formats]") {
    // ~400 KB of frames with blank lines scattered, so the split lands among them.
    std::string text = "HIERARCHY\nROOT hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                       " JOINT chest\n {\n  OFFSET 0 50 0\n  CHANNELS 3 Xrotation Yrotation Zrotation\n }\n}\n"
                       "MOTION\nFrames: 4000\nFrame Time: 0.008333\n";
    const int header_lines = 14;
    std::vector<int> frame_lines;
    int line = header_lines;
    for (int frame = 0; frame < 4000; ++frame) {
        if (frame % 97 == 0) {
            text += "\r\n";
            ++line;
        }
        char buffer[160];
        std::snprintf(buffer, sizeof buffer, "%.6f 90.123456 %.6f %.6f -12.345678 %.6f 1.5 %.6f -0.25\n", frame * 0.001,
                      frame * -0.002, frame * 0.09, frame * 0.07, frame * 0.05);
        text += buffer;
        frame_lines.push_back(++line);
    }
    BvhReadOptions serial = in_cm(), parallel = in_cm();
    serial.threads = 1;
    parallel.threads = 2;
    Result<BvhFile> a = bvh_parse(text, "big.bvh", serial);
    Result<BvhFile> b = bvh_parse(text, "big.bvh", parallel);
    REQUIRE(a.has_value());
    REQUIRE(b.has_value());
    REQUIRE(b->clip.frame_count() == 4000);
    for (int frame = 0; frame < 4000; ++frame) {
        CHECK(a->clip.root_translations[frame] == b->clip.root_translations[frame]);
        CHECK(a->clip.local_rotations[2 * frame + 1].coeffs() == b->clip.local_rotations[2 * frame + 1].coeffs());
    }

    // One bad value early and one late: both modes report the same line, the earliest in the file.
    for (int bad_frame : {10, 3990}) {
        std::string broken = text;
        size_t position = 0;
        for (int i = 0; i <= bad_frame; ++i) position = broken.find("-12.345678", position + 1);
        broken.replace(position, 10, "-12.34567x");
        Result<BvhFile> serial_error = bvh_parse(broken, "big.bvh", serial);
        Result<BvhFile> parallel_error = bvh_parse(broken, "big.bvh", parallel);
        REQUIRE_FALSE(serial_error.has_value());
        REQUIRE_FALSE(parallel_error.has_value());
        CHECK(serial_error.error().message == parallel_error.error().message);
        CHECK_THAT(parallel_error.error().message, Catch::Contains("big.bvh:" + std::to_string(frame_lines[bad_frame]) + ":"));
    }
    std::string truncated = text.substr(0, text.size() - 200);
    Result<BvhFile> short_serial = bvh_parse(truncated, "big.bvh", serial);
    Result<BvhFile> short_parallel = bvh_parse(truncated, "big.bvh", parallel);
    REQUIRE_FALSE(short_parallel.has_value());
    CHECK(short_serial.error().message == short_parallel.error().message);
}
