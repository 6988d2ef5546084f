// The bake on real captures: same bytes for the same inputs on any thread count, mirrored clips that are the
// mirror of their originals, hit boxes that hold the hit, contacts on a guard stance, clear errors, and the
// golden database of the current format.

#include "bake.h"

#include "kumite/core/heading_frame.h"
#include "kumite/core/pose_features.h"
#include "kumite/formats/motion_database_file.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>

using namespace kumite;

namespace {

bool have_captures() { return std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1"); }

RawAnnotations golden_annotations() {
    Result<RawAnnotations> annotations = annotations_read_file(kumite::test::source_dir() / "data/annotations/golden.json");
    REQUIRE(annotations.has_value());
    return *annotations;
}

bake::BakeOptions options(int jobs, int clusters = 4) {
    bake::BakeOptions options;
    options.mocap_root = kumite::test::mocap_root();
    options.jobs = jobs;
    options.clusters = clusters;
    return options;
}

std::vector<std::byte> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::byte*>(text.data());
    return {data, data + text.size()};
}

const DbClip& clip_named(const MotionDatabaseView& db, std::string_view name) {
    for (const DbClip& clip : db.clips) {
        if (db.string(clip.name) == name) return clip;
    }
    FAIL("no clip " << name);
    return db.clips[0];
}

Eigen::Vector3d hit_from_start(const MotionDatabaseView& db, const DbClip& clip, int start, int frame) {
    const DbPose& from = db.poses[clip.first_pose + start];
    const DbPose& at = db.poses[clip.first_pose + frame];
    HeadingFrame heading;
    heading.origin = Eigen::Vector3d(from.heading[0], 0.0, from.heading[1]);
    heading.yaw_rad = from.heading[2];
    return heading.to_heading(Eigen::Vector3d(at.hit_point[0], at.hit_point[1], at.hit_point[2]));
}

} // namespace

TEST_CASE("bake: the same annotations give the same bytes on one or two threads", "[bake][corpus]") {
    if (!have_captures()) return;
    const RawAnnotations annotations = golden_annotations();
    Result<bake::BakeResult> one = bake::bake_database(annotations, "golden.json", options(1));
    Result<bake::BakeResult> two = bake::bake_database(annotations, "golden.json", options(2));
    REQUIRE(one.has_value());
    REQUIRE(two.has_value());
    CHECK(motion_database_bytes(one->database.view()) == motion_database_bytes(two->database.view()));
}

TEST_CASE("bake: clips, mirrors, hit boxes and contacts", "[bake][corpus]") {
    if (!have_captures()) return;
    Result<bake::BakeResult> baked = bake::bake_database(golden_annotations(), "golden.json", options(2));
    REQUIRE(baked.has_value());
    const MotionDatabaseView db = baked->database.view();
    REQUIRE(db.clips.size() == 4); // kick, its mirror, punch, guard
    CHECK(db.actors.size() == 1);
    CHECK(db.clusters.size() == 4);

    const DbClip& kick = clip_named(db, "dataset-1_kick_normal_001_foot_r_60");
    const DbClip& mirror = clip_named(db, "dataset-1_kick_normal_001_foot_r_60~mirror");
    CHECK(kick.side == std::uint32_t(Side::right));
    CHECK(kick.segment == int(BodyPart::foot_r));
    CHECK(mirror.side == std::uint32_t(Side::left));
    CHECK(mirror.segment == int(BodyPart::foot_l));
    CHECK((mirror.flags & db_clip_mirrored) != 0);
    CHECK(kick.frame_count == 58); // frames 30..87 at the capture's 30 fps
    CHECK(kick.hit_frame == 30);
    CHECK(mirror.hit_frame == kick.hit_frame);
    for (int start = 0; start < kick.hit_frame; start += 5) {
        const Eigen::Vector3d original = hit_from_start(db, kick, start, kick.hit_frame);
        const Eigen::Vector3d mirrored = hit_from_start(db, mirror, start, kick.hit_frame);
        INFO("start " << start);
        CHECK(original.z() > 0.3); // the kick lands in front, foot high
        CHECK(original.y() > 0.5);
        CHECK(mirrored.x() == Approx(-original.x()).margin(0.01));
        CHECK(mirrored.y() == Approx(original.y()).margin(0.01));
        CHECK(mirrored.z() == Approx(original.z()).margin(0.01));
        // The start's box holds the path from the start to the hit, and the clip's box holds every start's.
        const DbPose& pose = db.poses[kick.first_pose + start];
        for (int frame = start; frame <= kick.hit_frame; ++frame) {
            const Eigen::Vector3d p = hit_from_start(db, kick, start, frame);
            for (int axis = 0; axis < 3; ++axis) {
                CHECK(p[axis] >= pose.start_box_min[axis] - 1e-4);
                CHECK(p[axis] <= pose.start_box_max[axis] + 1e-4);
                CHECK(p[axis] >= kick.box_min[axis] - 1e-4);
                CHECK(p[axis] <= kick.box_max[axis] + 1e-4);
            }
        }
    }
    // Every feature point of the mirror is the reflection of its partner's in the original: arms, spine and head
    // too, on a capture whose every joint has position channels (Bandai).
    for (std::uint32_t frame = 0; frame < kick.frame_count; frame += 4) {
        const std::span<const float> original = db.feature(kick.first_pose + frame);
        const std::span<const float> mirrored = db.feature(mirror.first_pose + frame);
        for (int sample = 0; sample < k_feature_window; ++sample) {
            for (int part = 0; part < k_feature_point_count; ++part) {
                const BodyPart partner = body_part_mirrored(k_feature_parts[part]);
                const int partner_index = int(std::find(k_feature_parts.begin(), k_feature_parts.end(), partner) - k_feature_parts.begin());
                const Eigen::Vector3d a = pose_feature_point(original, sample * k_feature_point_count + part);
                const Eigen::Vector3d b = pose_feature_point(mirrored, sample * k_feature_point_count + partner_index);
                INFO("frame " << frame << " part " << body_part_name(k_feature_parts[part]));
                CHECK((b - Eigen::Vector3d(-a.x(), a.y(), a.z())).norm() < 0.01); // leg lengths
            }
        }
    }
    // And the mirror's MIR frames (body part frames: twists included) are the mirror of the original's.
    for (std::uint32_t frame = 0; frame < kick.frame_count; frame += 4) {
        MirFrame original, mirrored, expected;
        db_mir_frame_load(original, db.mir_frames[kick.first_pose + frame]);
        db_mir_frame_load(mirrored, db.mir_frames[mirror.first_pose + frame]);
        mir_frame_mirror(expected, original, MirrorSymmetry{}, {});
        for (int part = 0; part < k_body_part_count; ++part) {
            if (!expected.has_part[part]) continue;
            INFO("frame " << frame << " part " << body_part_name(static_cast<BodyPart>(part)));
            CHECK(mirrored.part_frames[part].angularDistance(expected.part_frames[part]) < 0.01);
        }
    }
    // At and after the hit a pose is no start: its box is empty.
    CHECK(db.poses[kick.first_pose + kick.hit_frame].start_box_min[0] > db.poses[kick.first_pose + kick.hit_frame].start_box_max[0]);

    // The guard stance stands on both feet most of the time; the kick lifts the right foot at the hit.
    const DbClip& guard = clip_named(db, "guard_kick_normal_001");
    CHECK_FALSE(db_clip_is_strike(guard));
    int both_planted = 0;
    for (std::uint32_t f = 0; f < guard.frame_count; ++f) {
        const std::uint32_t flags = db.poses[guard.first_pose + f].flags;
        both_planted += (flags & db_pose_left_foot_planted) && (flags & db_pose_right_foot_planted);
    }
    CHECK(both_planted > int(guard.frame_count) * 3 / 4);
    const std::uint32_t at_hit = db.poses[kick.first_pose + kick.hit_frame].flags;
    CHECK((at_hit & db_pose_right_foot_planted) == 0);
    CHECK((at_hit & db_pose_left_foot_planted) != 0);

    // A feature's newest pelvis point sits above its heading origin, at about a leg length.
    const std::span<const float> feature = db.feature(guard.first_pose + 5);
    const Eigen::Vector3d pelvis = pose_feature_point(feature, (k_feature_window - 1) * k_feature_point_count);
    CHECK(std::abs(pelvis.x()) < 0.05);
    CHECK(std::abs(pelvis.z()) < 0.05);
    CHECK(pelvis.y() > 0.9);
    CHECK(pelvis.y() < 1.3);
}

TEST_CASE("bake: errors name the clip and what is wrong", "[bake][corpus]") {
    if (!have_captures()) return;
    RawAnnotations missing = golden_annotations();
    missing.clips[1].source = "bandai-namco-1/no_such_capture.bvh";
    Result<bake::BakeResult> no_file = bake::bake_database(missing, "mine.json", options(2));
    REQUIRE_FALSE(no_file.has_value());
    CHECK_THAT(no_file.error().message, Catch::Contains("mine.json: clip 1 (dataset-1_punch_normal_001_hand_l_29)") &&
                                            Catch::Contains("no_such_capture.bvh"));

    RawAnnotations too_long = golden_annotations();
    too_long.clips[2].last_frame = 100000;
    Result<bake::BakeResult> past_end = bake::bake_database(too_long, "mine.json", options(2));
    REQUIRE_FALSE(past_end.has_value());
    CHECK_THAT(past_end.error().message, Catch::Contains("guard_kick_normal_001") && Catch::Contains("past the end"));

    RawAnnotations empty;
    CHECK_FALSE(bake::bake_database(empty, "empty.json", options(1)).has_value());
}

TEST_CASE("bake: the golden database opens, verifies, and is what the bake makes today", "[bake][corpus]") {
    const std::filesystem::path golden = kumite::test::source_dir() / "data/golden" /
                                         ("golden-v" + std::to_string(k_database_format_version) + ".kdb");
    INFO("golden file " << golden.string());
    REQUIRE(std::filesystem::exists(golden));
    Result<MotionDatabase> opened = MotionDatabase::open(golden, true);
    REQUIRE(opened.has_value());
    CHECK(opened->view().clips.size() == 4);
    CHECK(opened->view().clusters.size() == 4);
    if (!have_captures()) return;
    Result<bake::BakeResult> baked = bake::bake_database(golden_annotations(), "golden.json", options(2));
    REQUIRE(baked.has_value());
    INFO("if the bake changed on purpose, run scripts/make_golden_database.sh (and bump the format version when the layout changed)");
    CHECK(motion_database_bytes(baked->database.view()) == read_bytes(golden));
}

TEST_CASE("bake: the reference annotations bake without an unservable strike, pinned roots repaired and said", "[bake][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "hachaj-shorinryu")) return;
    Result<RawAnnotations> annotations = annotations_read_file(kumite::test::source_dir() / "data/annotations/reference.json");
    REQUIRE(annotations);
    bake::BakeOptions options;
    options.mocap_root = kumite::test::mocap_root();
    Result<bake::BakeResult> baked = bake::bake_database(*annotations, "reference.json", options);
    REQUIRE(baked);
    int repaired = 0;
    for (const bake::BakeWarning& warning : baked->warnings) {
        INFO(warning.text());
        CHECK(warning.what.find("never planted") == std::string::npos); // every leg strike can start somewhere
        if (warning.what.starts_with("the root never moves")) {
            CHECK(warning.where.find("hachaj-shorinryu/") != std::string::npos); // the only captures with a pinned root
            ++repaired;
        }
    }
    std::set<std::string> shorinryu_sources;
    for (const RawAnnotatedClip& clip : annotations->clips) {
        if (clip.source.starts_with("hachaj-shorinryu/")) shorinryu_sources.insert(clip.source);
    }
    CHECK(repaired == int(shorinryu_sources.size()));
    CHECK(repaired >= 150);
}
