// Files that other readers (Blender's) read and that kumite reads too, with a warning naming file and line:
// an End block named like a joint, frames not one per line, whole frames after the declared ones. The world
// positions are those of the same motion written plainly; --strict (BvhReadOptions::strict) refuses each.

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/bvh_reader.h"
#include "support/pose_matchers.h"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace kumite;

namespace {

// A 1.7 m figure in centimetres: Hips, Spine, Head (with an End block), LeftLeg; 15 channels.
std::string hierarchy(const std::string& end_block) {
    return "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 95 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
           "  JOINT Spine\n  {\n    OFFSET 0 20 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
           "    JOINT Head\n    {\n      OFFSET 0 55 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n" +
           end_block +
           "    }\n  }\n  JOINT LeftLeg\n  {\n    OFFSET 10 -5 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
           "    End Site\n    {\n      OFFSET 0 -85 0\n    }\n  }\n}\n";
}
const std::string k_end_site = "      End Site\n      {\n        OFFSET 0 10 0\n      }\n";

std::vector<std::vector<double>> some_frames(int count) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> angle(-40.0, 40.0);
    std::vector<std::vector<double>> frames(count, std::vector<double>(15));
    for (auto& frame : frames) {
        for (double& value : frame) value = std::round(angle(random) * 1000.0) / 1000.0;
        frame[1] += 95.0;
    }
    return frames;
}

std::string motion(int declared, const std::vector<std::vector<double>>& frames, const char* between_values, const char* between_frames) {
    std::ostringstream text;
    text << "MOTION\nFrames: " << declared << "\nFrame Time: 0.0333333\n";
    for (std::size_t f = 0; f < frames.size(); ++f) {
        for (std::size_t v = 0; v < frames[f].size(); ++v) text << (v ? between_values : "") << frames[f][v];
        text << (f + 1 < frames.size() ? between_frames : "\n");
    }
    return text.str();
}

// The world positions of every joint of every frame.
std::vector<Eigen::Vector3d> all_positions(const Clip& clip) {
    std::vector<Eigen::Vector3d> all, positions(clip.skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(clip.skeleton.joint_count());
    for (int frame = 0; frame < clip.frame_count(); ++frame) {
        forward_kinematics(positions, rotations, clip.skeleton, clip.pose(frame));
        all.insert(all.end(), positions.begin(), positions.end());
    }
    return all;
}

void check_same_motion(const BvhFile& read, const BvhFile& plain) {
    REQUIRE(read.clip.frame_count() == plain.clip.frame_count());
    const std::vector<Eigen::Vector3d> a = all_positions(read.clip), b = all_positions(plain.clip);
    for (std::size_t i = 0; i < a.size(); ++i) CHECK_THAT(a[i], kumite::test::is_near(b[i], 1e-12));
}

BvhReadOptions strict() {
    BvhReadOptions options;
    options.strict = true;
    return options;
}

} // namespace

TEST_CASE("bvh_tolerated: the plain file has no warning", "[formats]") {
    Result<BvhFile> plain = bvh_parse(hierarchy(k_end_site) + motion(31, some_frames(31), " ", "\n"), "plain.bvh");
    REQUIRE(plain.has_value());
    CHECK(plain->warnings.empty());
    CHECK(plain->clip.frame_count() == 31);
}

TEST_CASE("bvh_tolerated: an End block named like a joint is an End Site, with a warning", "[formats]") {
    const std::string frames = motion(31, some_frames(31), " ", "\n");
    const std::string text = hierarchy("      End ltoes\n      {\n        OFFSET 0 10 0\n      }\n") + frames;
    Result<BvhFile> read = bvh_parse(text, "named.bvh");
    REQUIRE(read.has_value());
    REQUIRE(read->warnings.size() == 1);
    CHECK_THAT(read->warnings[0], Catch::Contains("named.bvh:14:") && Catch::Contains("End ltoes"));
    CHECK(read->clip.skeleton.end_sites.size() == 2);
    check_same_motion(*read, *bvh_parse(hierarchy(k_end_site) + frames, "plain.bvh"));
    CHECK_THAT(bvh_parse(text, "named.bvh", strict()).error().message, Catch::Contains("named.bvh:14:") && Catch::Contains("strict"));
    // "End" followed by a brace is no End block at all.
    CHECK_FALSE(bvh_parse(hierarchy("      End\n      {\n        OFFSET 0 10 0\n      }\n") + frames, "broken.bvh").has_value());
}

TEST_CASE("bvh_tolerated: all frames on one line, or wrapped over lines, are one stream of values", "[formats]") {
    const std::vector<std::vector<double>> frames = some_frames(31);
    const BvhFile plain = *bvh_parse(hierarchy(k_end_site) + motion(31, frames, " ", "\n"), "plain.bvh");
    for (const auto& [between_values, between_frames] : {std::pair{" ", " "}, std::pair{"\n", "\n"}, std::pair{" ", "\n\n"}}) {
        const std::string text = hierarchy(k_end_site) + motion(31, frames, between_values, between_frames);
        Result<BvhFile> read = bvh_parse(text, "stream.bvh");
        INFO("values separated by '" << between_values << "', frames by '" << between_frames << "'");
        REQUIRE(read.has_value());
        if (std::string(between_values) == " ") {
            // One frame a line (with blank lines between) is plain; the others are streams.
            CHECK(read->warnings.size() == (std::string(between_frames) == " " ? 1u : 0u));
        } else {
            REQUIRE(read->warnings.size() == 1);
            CHECK_THAT(read->warnings[0], Catch::Contains("stream.bvh:") && Catch::Contains("one stream") && Catch::Contains("15 to a frame"));
            CHECK_FALSE(bvh_parse(text, "stream.bvh", strict()).has_value());
        }
        check_same_motion(*read, plain);
    }
    Result<BvhFile> one_line = bvh_parse(hierarchy(k_end_site) + motion(31, frames, " ", " "), "one.bvh");
    CHECK_THAT(one_line->warnings.at(0), Catch::Contains("one.bvh:33:"));
}

TEST_CASE("bvh_tolerated: whole frames after the declared ones are ignored with a warning", "[formats]") {
    const std::vector<std::vector<double>> frames = some_frames(32);
    const std::string text = hierarchy(k_end_site) + motion(31, frames, " ", "\n");
    Result<BvhFile> read = bvh_parse(text, "extra.bvh");
    REQUIRE(read.has_value());
    REQUIRE(read->warnings.size() == 1);
    CHECK_THAT(read->warnings[0], Catch::Contains("extra.bvh:64:") && Catch::Contains("15 values (1 frame) after the 31 frames"));
    check_same_motion(*read, *bvh_parse(hierarchy(k_end_site) + motion(31, some_frames(31), " ", "\n"), "plain.bvh"));
    CHECK_THAT(bvh_parse(text, "extra.bvh", strict()).error().message, Catch::Contains("extra.bvh:64:") && Catch::Contains("strict"));
}

TEST_CASE("bvh_tolerated: 'Frame Time: 0' or no Frame Time line reads without a rate, with a warning", "[formats]") {
    const std::string plain_text = hierarchy(k_end_site) + motion(31, some_frames(31), " ", "\n");
    const BvhFile plain = *bvh_parse(plain_text, "plain.bvh");
    std::string zero = plain_text, missing = plain_text;
    zero.replace(zero.find("Frame Time: 0.0333333"), 21, "Frame Time: 0.0");
    missing.erase(missing.find("Frame Time: 0.0333333\n"), 22);
    for (const auto& [text, line] : {std::pair{zero, 32}, std::pair{missing, 32}}) {
        Result<BvhFile> read = bvh_parse(text, "norate.bvh");
        REQUIRE(read.has_value());
        CHECK_FALSE(read->clip.has_frame_rate());
        CHECK_FALSE(read->frame_rate_in_file);
        CHECK(read->clip.duration_s() == 0.0);
        REQUIRE(read->warnings.size() == 1);
        CHECK_THAT(read->warnings[0], Catch::Contains("norate.bvh:" + std::to_string(line) + ":") && Catch::Contains("no frame rate") &&
                                          Catch::Contains("--fps N"));
        check_same_motion(*read, plain); // positions per frame need no rate
        CHECK_THAT(bvh_parse(text, "norate.bvh", strict()).error().message, Catch::Contains("norate.bvh:") && Catch::Contains("strict"));
        // A given rate fills the gap (still with a warning: the file is defective).
        BvhReadOptions at_100;
        at_100.frame_rate_hz = 100.0;
        Result<BvhFile> rated = bvh_parse(text, "norate.bvh", at_100);
        REQUIRE(rated.has_value());
        CHECK(rated->clip.frame_time_s == Approx(0.01));
        CHECK(rated->clip.duration_s() == Approx(0.3));
        REQUIRE(rated->warnings.size() == 1);
        CHECK_THAT(rated->warnings[0], Catch::Contains("read at 100 fps"));
    }
    // A given rate replaces a stated one, saying so; the same rate says nothing.
    BvhReadOptions at_60;
    at_60.frame_rate_hz = 60.0;
    Result<BvhFile> replaced = bvh_parse(plain_text, "plain.bvh", at_60);
    REQUIRE(replaced->warnings.size() == 1);
    CHECK_THAT(replaced->warnings[0], Catch::Contains("the file says 30") && Catch::Contains("read at 60 fps"));
    at_60.frame_rate_hz = 1.0 / 0.0333333;
    CHECK(bvh_parse(plain_text, "plain.bvh", at_60)->warnings.empty());
    // Other frame times are still refused.
    std::string negative = plain_text;
    negative.replace(negative.find("Frame Time: 0.0333333"), 21, "Frame Time: -0.01");
    CHECK_THAT(bvh_parse(negative, "neg.bvh").error().message, Catch::Contains("neg.bvh:32:"));
}

TEST_CASE("bvh_tolerated: what is truly malformed is still refused, saying where", "[formats]") {
    const std::vector<std::vector<double>> frames = some_frames(31);
    std::string one_line = hierarchy(k_end_site) + motion(31, frames, " ", " ");
    // Too few values: the last one missing.
    const std::string too_few = one_line.substr(0, one_line.find_last_of(' '));
    CHECK_THAT(bvh_parse(too_few, "short.bvh").error().message, Catch::Contains("short.bvh:33:") && Catch::Contains("ends after 30 frames"));
    // A word among the values.
    std::string word = one_line;
    word.replace(word.rfind(' '), 1, " x ");
    CHECK_THAT(bvh_parse(word, "word.bvh").error().message, Catch::Contains("word.bvh:33:") && Catch::Contains("'x'"));
    // A channel count that does not match the data: a part of a frame left over.
    std::string wrong = hierarchy(k_end_site) + motion(31, frames, " ", "\n");
    const std::string leg_channels = "OFFSET 10 -5 0\n    CHANNELS 3 Zrotation Xrotation Yrotation";
    wrong.replace(wrong.find(leg_channels), leg_channels.size(), "OFFSET 10 -5 0\n    CHANNELS 2 Zrotation Xrotation");
    CHECK_FALSE(bvh_parse(wrong, "wrong.bvh").has_value());
}
