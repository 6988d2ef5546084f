#pragma once
// The motion database in a `.kdb` image (database_image.h): which section holds which record of
// core/motion_database.h, the writer, and the opener. Opening checks the structure, in a time that does not grow
// with the pose count: every span, clip, actor, string and cluster the runtime follows is inside the mapping.
// verify() checks every per-pose value too (pose records, MIR frames, features, cluster members) and the content
// hash. A refusal names the section, the record and the byte. What each step checks: formats/README.md.

#include "kumite/core/motion_database.h"
#include "kumite/formats/database_image.h"

namespace kumite {

inline constexpr std::uint32_t k_section_meta = section_tag("META");
inline constexpr std::uint32_t k_section_strings = section_tag("STRS");
inline constexpr std::uint32_t k_section_actors = section_tag("ACTR");
inline constexpr std::uint32_t k_section_clips = section_tag("CLIP");
inline constexpr std::uint32_t k_section_poses = section_tag("POSE");
inline constexpr std::uint32_t k_section_mir_frames = section_tag("MIRF");
inline constexpr std::uint32_t k_section_features = section_tag("FEAT");
inline constexpr std::uint32_t k_section_centroids = section_tag("CENT");
inline constexpr std::uint32_t k_section_clusters = section_tag("CLUS");
inline constexpr std::uint32_t k_section_members = section_tag("MEMB");

// The image's bytes: the same content gives the same bytes.
std::vector<std::byte> motion_database_bytes(const MotionDatabaseView& database);
Result<void> motion_database_write(const std::filesystem::path& path, const MotionDatabaseView& database); // atomic

class MotionDatabase {
public:
    // Maps the file and checks its structure: header, sections, record sizes, META, actors, every clip, every
    // cluster and the centroids; O(sections + actors + clips + clusters), no per-pose record is read. With
    // `verify`, verify() runs too.
    static Result<MotionDatabase> open(const std::filesystem::path& path, bool verify = false);
    // Checks the structure of an image already validated as a container; `source_name` prefixes errors.
    static Result<MotionDatabase> from_image(DatabaseImage image, std::string_view source_name);

    // Every per-pose value: each pose names its own clip and frame, every float is finite, MIR chains fit their
    // arrays, and the cluster members name every pose once. O(poses); the first problem found is returned.
    Result<void> verify_values() const;
    // verify_values(), then the content hash (DatabaseImage::verify_hash).
    Result<void> verify() const;

    const MotionDatabaseView& view() const { return m_view; }
    const DatabaseImage& image() const { return m_image; }

private:
    DatabaseImage m_image;
    std::string m_source_name;
    MotionDatabaseView m_view;
};

} // namespace kumite
