// Every class of malformed input gives an error that names the file and line and says what was expected.

#include "kumite/formats/bvh_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <fstream>

using namespace kumite;

namespace {

const std::string k_header =
    "HIERARCHY\n"                                                      // 1
    "ROOT Hips\n"                                                      // 2
    "{\n"                                                              // 3
    "  OFFSET 0 0 0\n"                                                 // 4
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" // 5
    "  JOINT Spine\n"                                                  // 6
    "  {\n"                                                            // 7
    "    OFFSET 0 10 0\n"                                              // 8
    "    CHANNELS 3 Zrotation Xrotation Yrotation\n"                   // 9
    "  }\n"                                                            // 10
    "}\n"                                                              // 11
    "MOTION\n"                                                         // 12
    "Frames: 2\n"                                                      // 13
    "Frame Time: 0.033333\n";                                          // 14

std::string error_of(const std::string& text) {
    Result<BvhFile> file = bvh_parse(text, "bad.bvh");
    REQUIRE_FALSE(file.has_value());
    return file.error().message;
}

} // namespace

TEST_CASE("bvh_malformed: a valid reference parses", "[formats]") {
    CHECK(bvh_parse(k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1 1\n", "ok.bvh").has_value());
}

TEST_CASE("bvh_malformed: truncated hierarchy", "[formats]") {
    const std::string message = error_of(k_header.substr(0, k_header.find("  }\n")));
    CHECK_THAT(message, Catch::Contains("bad.bvh:10:") && Catch::Contains("missing '}'"));
}

TEST_CASE("bvh_malformed: file ends after the hierarchy", "[formats]") {
    CHECK_THAT(error_of(k_header.substr(0, k_header.find("MOTION"))), Catch::Contains("expected MOTION"));
}

TEST_CASE("bvh_malformed: a frame with too few values", "[formats]") {
    const std::string message = error_of(k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1\n");
    CHECK_THAT(message, Catch::Contains("bad.bvh:16:") && Catch::Contains("frame 1 has 8 values, expected 9"));
}

TEST_CASE("bvh_malformed: a frame with too many values (joint count mismatch)", "[formats]") {
    const std::string message = error_of(k_header + "0 0 0 0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1 1\n");
    CHECK_THAT(message, Catch::Contains("bad.bvh:15:") && Catch::Contains("more than 9 values") && Catch::Contains("2 joints"));
}

TEST_CASE("bvh_malformed: a non-number in a frame", "[formats]") {
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 x 1 1 1 1 1\n"),
               Catch::Contains("bad.bvh:16:") && Catch::Contains("value 4") && Catch::Contains("'x'"));
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 nan\n1 1 1 1 1 1 1 1 1\n"), Catch::Contains("finite number"));
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 1e999\n1 1 1 1 1 1 1 1 1\n"), Catch::Contains("bad.bvh:15:"));
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 1.5.5\n1 1 1 1 1 1 1 1 1\n"), Catch::Contains("bad.bvh:15:"));
}

TEST_CASE("bvh_malformed: fewer frames than declared", "[formats]") {
    // Long numbers, so that the bytes could hold two frames and the reader has to reach the end to notice.
    const std::string frame = "0.0000000000 0.0000000000 0.0000000000 0.0000000000 0.0000000000 0.0000000000 0 0 0\n";
    CHECK_THAT(error_of(k_header + frame), Catch::Contains("ends after 1 frames") && Catch::Contains("declares 2"));
}

TEST_CASE("bvh_malformed: more data than declared that is not whole frames, or not numbers", "[formats]") {
    // Whole frames after the declared ones are read with a warning (bvh_tolerated_test.cpp); a part of a frame or
    // a word is refused.
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1 1\n2 2 2 2\n"),
               Catch::Contains("bad.bvh:17:") && Catch::Contains("more data after the 2 frames") && Catch::Contains("and a part"));
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1 1\nend\n"),
               Catch::Contains("bad.bvh:17:") && Catch::Contains("found 'end'"));
}

TEST_CASE("bvh_malformed: a huge frame count is refused at once, not allocated", "[formats]") {
    std::string text = k_header;
    text.replace(text.find("Frames: 2"), 9, "Frames: 99999999");
    const auto start = std::chrono::steady_clock::now();
    CHECK_THAT(error_of(text + "0 0 0 0 0 0 0 0 0\n"), Catch::Contains("bad.bvh:14:") && Catch::Contains("truncated"));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));
}

TEST_CASE("bvh_malformed: header and channel errors name their line", "[formats]") {
    auto with = [&](const std::string& from, const std::string& to) {
        std::string text = k_header + "0 0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1 1\n";
        text.replace(text.find(from), from.size(), to);
        return error_of(text);
    };
    CHECK_THAT(with("HIERARCHY", "HIERARCHI"), Catch::Contains("bad.bvh:1:") && Catch::Contains("expected HIERARCHY"));
    CHECK_THAT(with("OFFSET 0 10 0", "OFFSET 0 ten 0"), Catch::Contains("bad.bvh:8:") && Catch::Contains("3 numbers after OFFSET"));
    CHECK_THAT(with("CHANNELS 3 Zrotation", "CHANNELS 7 Zrotation"), Catch::Contains("bad.bvh:9:") && Catch::Contains("channel count"));
    CHECK_THAT(with("Zrotation Xrotation Yrotation\n  }", "Zrotation Xrotation Wrotation\n  }"),
               Catch::Contains("bad.bvh:9:") && Catch::Contains("'Wrotation'"));
    CHECK_THAT(with("Zrotation Xrotation Yrotation\n  }", "Zrotation Zrotation Yrotation\n  }"), Catch::Contains("listed twice"));
    CHECK_THAT(with("Frames: 2", "Frames: two"), Catch::Contains("bad.bvh:13:") && Catch::Contains("frame count"));
    CHECK_THAT(with("Frame Time: 0.033333", "Frame Time: -1"), Catch::Contains("bad.bvh:14:") && Catch::Contains("found -1"));
    CHECK_THAT(with("Frame Time: 0.033333", "Frame Time: 1e-13"), Catch::Contains("bad.bvh:14:") && Catch::Contains("1e-06 to 3600"));
    CHECK_THAT(with("CHANNELS 3 Zrotation", "CHANNELS 2.5 Zrotation"), Catch::Contains("found 2.5"));
    CHECK_THAT(with("Frames: 2", "Frames: -2"), Catch::Contains("found -2"));
    CHECK_THAT(with("JOINT Spine", "JOINT Spine {{"), Catch::Contains("bad.bvh:6:") && Catch::Contains("brace"));
    CHECK_THAT(with("OFFSET 0 10 0", "OFFSET 0 1e300 0"), Catch::Contains("bad.bvh:8:") && Catch::Contains("3 numbers after OFFSET"));
    CHECK_THAT(with("    OFFSET 0 10 0\n", ""), Catch::Contains("Spine has no OFFSET"));
    CHECK_THAT(with("JOINT Spine", "JOINT"), Catch::Contains("bad.bvh:6:") && Catch::Contains("joint name"));
}

TEST_CASE("bvh_malformed: empty, binary and non-BVH input", "[formats]") {
    CHECK_THAT(error_of(""), Catch::Contains("bad.bvh:1:") && Catch::Contains("expected HIERARCHY"));
    CHECK_THAT(error_of(std::string("\0\x01\xff\xfe garbage", 12)), Catch::Contains("expected HIERARCHY"));
    CHECK_THAT(error_of("{\"json\": true}"), Catch::Contains("expected HIERARCHY"));
}

TEST_CASE("bvh_malformed: deep nesting and many joints stay bounded", "[formats]") {
    std::string deep = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
    for (int i = 0; i < k_bvh_max_joints + 5; ++i) deep += "JOINT j" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n";
    CHECK_THAT(error_of(deep), Catch::Contains("more than 10000 joints"));
}

TEST_CASE("bvh_malformed: unreadable paths", "[formats]") {
    Result<BvhFile> missing = bvh_read_file("/nonexistent/kumite/none.bvh");
    REQUIRE_FALSE(missing.has_value());
    CHECK_THAT(missing.error().message, Catch::Contains("/nonexistent/kumite/none.bvh") && Catch::Contains("cannot open"));
    Result<BvhFile> directory = bvh_read_file(std::filesystem::temp_directory_path());
    REQUIRE_FALSE(directory.has_value());
    CHECK_THAT(directory.error().message, Catch::Contains("directory"));

    const std::filesystem::path big = kumite::test::make_temp_dir("big") / "big.bvh";
    std::ofstream(big) << k_header;
    BvhReadOptions options;
    options.max_file_bytes = 16;
    Result<BvhFile> too_big = bvh_read_file(big, options);
    REQUIRE_FALSE(too_big.has_value());
    CHECK_THAT(too_big.error().message, Catch::Contains("limit"));
}

TEST_CASE("bvh_malformed: values beyond any plausible magnitude are refused", "[formats]") {
    // 1.7976931348e308 is finite, but written with 10 digits it would round past the largest double.
    CHECK_THAT(error_of(k_header + "0 0 0 0 0 0 0 0 -1.79769313459e308\n1 1 1 1 1 1 1 1 1\n"),
               Catch::Contains("bad.bvh:15:") && Catch::Contains("value 9"));
}

TEST_CASE("bvh_malformed: joints without channels do not trip the size bound", "[formats]") {
    // 1 animated root and 199 fixed joints: 600 frames of 6 values need few bytes but many joint-frames.
    std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
    for (int i = 0; i < 199; ++i) text += "JOINT j" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\n";
    text += "}\nMOTION\nFrames: 600\nFrame Time: 0.01\n";
    for (int i = 0; i < 600; ++i) text += "0 0 0 0 0 0\n";
    Result<BvhFile> file = bvh_parse(text, "fixed.bvh");
    REQUIRE(file.has_value());
    CHECK(file->clip.frame_count() == 600);
}

TEST_CASE("bvh_malformed: a deep chain below a foot is measured in linear time", "[formats]") {
    // A humanoid lying along +X (so the standing height walks the frames) with a 9,000-joint chain under the
    // left foot: the foot subtree is found once, not once per joint per frame (this took seconds before).
    std::string text = "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n"
                       "JOINT Spine\n{\nOFFSET 10 0 0\nCHANNELS 0\nJOINT Head\n{\nOFFSET 10 0 0\nCHANNELS 0\n"
                       "JOINT LeftArm\n{\nOFFSET 1 1 0\nCHANNELS 0\nJOINT LeftForeArm\n{\nOFFSET 1 0 0\nCHANNELS 0\n"
                       "JOINT LeftHand\n{\nOFFSET 1 0 0\nCHANNELS 0\n}\n}\n}\n}\n}\n"
                       "JOINT LeftUpLeg\n{\nOFFSET -1 1 0\nCHANNELS 0\nJOINT LeftLeg\n{\nOFFSET -40 0 0\nCHANNELS 0\n"
                       "JOINT LeftFoot\n{\nOFFSET -40 0 0\nCHANNELS 0\n";
    const int depth = 9000;
    for (int i = 0; i < depth; ++i) text += "JOINT t" + std::to_string(i) + "\n{\nOFFSET 0.001 0 0\nCHANNELS 0\n";
    for (int i = 0; i < depth; ++i) text += "}\n";
    text += "}\n}\n}\n}\nMOTION\nFrames: 200\nFrame Time: 0.01\n";
    for (int i = 0; i < 200; ++i) text += "0 0 90\n";
    Result<BvhFile> file = bvh_parse(text, "deep.bvh");
    REQUIRE(file.has_value());
    CHECK(file->clip.skeleton.joint_count() == depth + 9);
}
