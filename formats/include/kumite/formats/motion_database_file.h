#pragma once
// The motion database in a `.kdb` image (database_image.h): which section holds which record of
// core/motion_database.h, the writer, and an opener that checks every count, index, string reference and float
// before it hands out a MotionDatabaseView. A refusal names the section, the record and the byte.

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
    static Result<MotionDatabase> open(const std::filesystem::path& path, bool verify_hash = false);
    // Checks the content of an image already validated as a container; `source_name` prefixes errors.
    static Result<MotionDatabase> from_image(DatabaseImage image, std::string_view source_name);

    const MotionDatabaseView& view() const { return m_view; }
    const DatabaseImage& image() const { return m_image; }

private:
    DatabaseImage m_image;
    MotionDatabaseView m_view;
};

} // namespace kumite
