// The motion database in its file: what is written opens to the same records; structure that would send the
// runtime out of bounds (counts, clip and cluster ranges, string references) is refused at open, per-pose values
// (pose records, non-finite numbers, MIR chains, cluster members) by verify; each refusal with the section, the
// record and the byte.

#include "kumite/formats/motion_database_file.h"
#include "support/small_database.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>

using namespace kumite;

namespace {

using kumite::test::small_database;

Result<MotionDatabase> open_bytes(const std::vector<std::byte>& bytes) {
    Result<DatabaseImage> image = DatabaseImage::view(bytes, "x.kdb");
    if (!image) return image.error();
    return MotionDatabase::from_image(std::move(*image), "x.kdb");
}

// The written bytes of small_database() after `change` edits one record.
template <class Record>
std::vector<std::byte> bytes_after(std::uint32_t tag, std::size_t index, void (*change)(Record&)) {
    std::vector<std::byte> bytes = motion_database_bytes(small_database().view());
    Result<DatabaseImage> image = DatabaseImage::view(bytes, "x.kdb");
    REQUIRE(image.has_value());
    const std::size_t offset = image->find(tag)->offset + index * sizeof(Record);
    Record record;
    std::memcpy(&record, bytes.data() + offset, sizeof(Record));
    change(record);
    std::memcpy(bytes.data() + offset, &record, sizeof(Record));
    return bytes;
}

// The error opening gives after `change` (structure: refused at open).
template <class Record>
std::string error_after(std::uint32_t tag, std::size_t index, void (*change)(Record&)) {
    Result<MotionDatabase> opened = open_bytes(bytes_after(tag, index, change));
    REQUIRE_FALSE(opened.has_value());
    return opened.error().message;
}

// The error verifying gives after `change` (a per-pose value: opening accepts it, verify_values refuses it).
template <class Record>
std::string verify_error_after(std::uint32_t tag, std::size_t index, void (*change)(Record&)) {
    const std::vector<std::byte> bytes = bytes_after(tag, index, change);
    Result<MotionDatabase> opened = open_bytes(bytes);
    REQUIRE(opened.has_value());
    Result<void> verified = opened->verify_values();
    REQUIRE_FALSE(verified.has_value());
    Result<void> verified_with_hash = opened->verify(); // values first: the message says which value, not "hash"
    REQUIRE_FALSE(verified_with_hash.has_value());
    CHECK(verified_with_hash.error().message == verified.error().message);
    return verified.error().message;
}

} // namespace

TEST_CASE("motion_database_file: a written database opens to the same records", "[formats][database]") {
    const MotionDatabaseContent content = small_database();
    const std::vector<std::byte> bytes = motion_database_bytes(content.view());
    CHECK(bytes == motion_database_bytes(content.view()));
    Result<MotionDatabase> opened = open_bytes(bytes);
    REQUIRE(opened.has_value());
    const MotionDatabaseView& view = opened->view();
    CHECK(view.clips.size() == 2);
    CHECK(view.poses.size() == 7);
    CHECK(view.string(view.clips[1].name) == "punch_r");
    CHECK(view.string(view.actors[0].name) == "bandai");
    CHECK(view.clips[1].hit_frame == 2);
    CHECK(view.poses[5].hit_point[1] == Approx(1.4f));
    CHECK(view.feature(6)[3] == Approx(0.03f + 3.0f));
    CHECK(view.centroid(0)[k_feature_dimensions - 1] == 0.5f);
    CHECK((reinterpret_cast<const std::byte*>(view.mir_frames.data()) - bytes.data()) % 64 == 0);

    const std::filesystem::path path = kumite::test::make_temp_dir("kdb") / "small.kdb";
    REQUIRE(motion_database_write(path, content.view()).has_value());
    Result<MotionDatabase> mapped = MotionDatabase::open(path, true);
    REQUIRE(mapped.has_value());
    CHECK(mapped->view().members.size() == 7);
    CHECK(reinterpret_cast<std::uintptr_t>(mapped->view().mir_frames.data()) % 64 == 0); // mapped: page-aligned base
}

TEST_CASE("motion_database_file: a MIR frame survives storage to float precision", "[formats][database]") {
    MirFrame frame;
    frame.hip_centre = Eigen::Vector3d(0.1, 1.02, -0.3);
    for (int part = 0; part < k_body_part_count; ++part) {
        frame.has_part[part] = part % 3 != 0;
        frame.part_frames[part] = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * part, Eigen::Vector3d(1, 2, 3).normalized()));
    }
    frame.spine.count = 4;
    for (int k = 0; k < 4; ++k) {
        frame.spine.frames[k] = Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * k, Eigen::Vector3d::UnitY()));
        frame.spine.fractions[k] = k / 3.0;
    }
    frame.extremity[2] = Eigen::Vector3d(0.0, -0.97, 0.1);
    frame.swivel[3] = -0.4;
    DbMirFrame stored;
    db_mir_frame_store(stored, frame);
    MirFrame loaded;
    db_mir_frame_load(loaded, stored);
    CHECK((loaded.hip_centre - frame.hip_centre).norm() < 1e-6);
    for (int part = 0; part < k_body_part_count; ++part) {
        CHECK(loaded.has_part[part] == frame.has_part[part]);
        CHECK(loaded.part_frames[part].angularDistance(frame.part_frames[part]) < 1e-6);
    }
    CHECK(loaded.spine.count == 4);
    CHECK(loaded.spine.fractions[2] == Approx(2.0 / 3.0));
    CHECK(loaded.neck.count == 0);
    CHECK((loaded.extremity[2] - frame.extremity[2]).norm() < 1e-6);
    CHECK(loaded.swivel[3] == Approx(-0.4));
}

TEST_CASE("motion_database_file: structure that points out of bounds is refused at open with section, record and byte", "[formats][database]") {
    const std::string actor = error_after<DbClip>(k_section_clips, 1, [](DbClip& c) { c.actor = 5; });
    CHECK_THAT(actor, Catch::Contains("x.kdb: byte ") && Catch::Contains("CLIP 1") && Catch::Contains("actor 5 is out of range"));
    CHECK_THAT(error_after<DbClip>(k_section_clips, 0, [](DbClip& c) { c.frame_count = 1000000; }), Catch::Contains("CLIP 0"));
    CHECK_THAT(error_after<DbClip>(k_section_clips, 1, [](DbClip& c) { c.name.offset = 0xfffffff0u; }),
               Catch::Contains("outside the string table"));
    CHECK_THAT(error_after<DbClip>(k_section_clips, 1, [](DbClip& c) { c.hit_frame = 4; }), Catch::Contains("hit frame 4"));
    CHECK_THAT(error_after<DbClip>(k_section_clips, 1, [](DbClip& c) { c.segment = 40; }), Catch::Contains("not a body part"));
    CHECK_THAT(error_after<DbClip>(k_section_clips, 0, [](DbClip& c) { c.box_max[1] = NAN; }), Catch::Contains("CLIP 0") && Catch::Contains("box"));
    CHECK_THAT(error_after<DbActor>(k_section_actors, 0, [](DbActor& a) { a.leg_length_m = 0.0f; }), Catch::Contains("ACTR 0"));
    CHECK_THAT(error_after<DbCluster>(k_section_clusters, 0, [](DbCluster& c) { c.member_count = 9; }), Catch::Contains("CLUS 0"));
    CHECK_THAT(error_after<float>(k_section_centroids, 7, [](float& v) { v = INFINITY; }), Catch::Contains("CENT 7"));
    CHECK_THAT(error_after<DbMeta>(k_section_meta, 0, [](DbMeta& m) { m.feature_dimensions = 3; }), Catch::Contains("META 0"));
}

TEST_CASE("motion_database_file: per-pose values are refused by verify with section, record and byte", "[formats][database]") {
    const std::string pose = verify_error_after<DbPose>(k_section_poses, 4, [](DbPose& p) { p.clip = 0; });
    CHECK_THAT(pose, Catch::Contains("x.kdb: byte ") && Catch::Contains("POSE 4") && Catch::Contains("do not match the clip table"));
    CHECK_THAT(verify_error_after<DbPose>(k_section_poses, 5, [](DbPose& p) { p.frame = 7; }), Catch::Contains("POSE 5"));
    CHECK_THAT(verify_error_after<DbPose>(k_section_poses, 2, [](DbPose& p) { p.hit_point[0] = std::numeric_limits<float>::quiet_NaN(); }),
               Catch::Contains("POSE 2") && Catch::Contains("not finite"));
    CHECK_THAT(verify_error_after<DbMirFrame>(k_section_mir_frames, 6, [](DbMirFrame& f) { f.spine_count = 13; }), Catch::Contains("MIRF 6"));
    CHECK_THAT(verify_error_after<DbMirFrame>(k_section_mir_frames, 0, [](DbMirFrame& f) { f.swivel[1] = INFINITY; }), Catch::Contains("MIRF 0"));
    CHECK_THAT(verify_error_after<DbMirFrame>(k_section_mir_frames, 3, [](DbMirFrame& f) { f.neck_fractions[2] = NAN; }), Catch::Contains("MIRF 3"));
    CHECK_THAT(verify_error_after<std::uint32_t>(k_section_members, 3, [](std::uint32_t& m) { m = 70; }),
               Catch::Contains("MEMB 3") && Catch::Contains("pose 70 is out of range"));
    CHECK_THAT(verify_error_after<std::uint32_t>(k_section_members, 5, [](std::uint32_t& m) { m = 1; }),
               Catch::Contains("MEMB 5") && Catch::Contains("pose 1 is a member twice"));
    const std::string feature = verify_error_after<float>(k_section_features, 10, [](float& v) { v = NAN; });
    CHECK_THAT(feature, Catch::Contains("FEAT 10") && Catch::Contains("not a finite number"));
    const std::string late_feature = verify_error_after<float>(k_section_features, 6 * k_feature_dimensions + 119, [](float& v) { v = -INFINITY; });
    CHECK_THAT(late_feature, Catch::Contains("FEAT " + std::to_string(6 * k_feature_dimensions + 119)));

    // The unchanged database verifies; a flipped byte the values do not show is the hash's to find.
    std::vector<std::byte> bytes = motion_database_bytes(small_database().view());
    REQUIRE(open_bytes(bytes)->verify().has_value());
    Result<DatabaseImage> image = DatabaseImage::view(bytes, "x.kdb");
    bytes[image->find(k_section_features)->offset + 1] ^= std::byte{0x01}; // a mantissa bit: still finite
    Result<MotionDatabase> flipped = open_bytes(bytes);
    REQUIRE(flipped.has_value());
    CHECK(flipped->verify_values().has_value());
    REQUIRE_FALSE(flipped->verify().has_value());
    CHECK_THAT(flipped->verify().error().message, Catch::Contains("byte 24") && Catch::Contains("content hash"));
}

TEST_CASE("motion_database_file: open(path, verify) refuses a per-pose value that open alone accepts", "[formats][database]") {
    const std::filesystem::path path = kumite::test::make_temp_dir("kdb-verify") / "nan.kdb";
    const std::vector<std::byte> bytes = bytes_after<float>(k_section_features, 10, [](float& v) { v = NAN; });
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    REQUIRE(MotionDatabase::open(path).has_value());
    Result<MotionDatabase> verified = MotionDatabase::open(path, /*verify=*/true);
    REQUIRE_FALSE(verified.has_value());
    CHECK_THAT(verified.error().message, Catch::Contains(path.string()) && Catch::Contains("FEAT 10"));
}

TEST_CASE("motion_database_file: a container without the motion sections is not a motion database", "[formats][database]") {
    DatabaseImageBuilder builder;
    const std::vector<double> numbers = {1.0, 2.0};
    builder.add_section(section_tag("NUMS"), sizeof(double), std::as_bytes(std::span(numbers)));
    Result<MotionDatabase> opened = open_bytes(builder.build());
    REQUIRE_FALSE(opened.has_value());
    CHECK_THAT(opened.error().message, Catch::Contains("no META section"));

    // Records of another size (a newer layout) are named, not misread.
    DatabaseImageBuilder other;
    const std::vector<std::uint64_t> meta(5, 0);
    other.add_section(k_section_meta, 40, std::as_bytes(std::span(meta)));
    Result<MotionDatabase> wrong_size = open_bytes(other.build());
    REQUIRE_FALSE(wrong_size.has_value());
    CHECK_THAT(wrong_size.error().message, Catch::Contains("META records are 40 bytes"));
}
