#pragma once
// The database file as an image to map, not a stream to parse (STYLE.md 3): a fixed header, a section table and
// aligned sections of fixed-size elements, little-endian, no pointers. Opening maps the file and validates the
// header, the table and every section's bounds and alignment; the content hash is checked on request. Any
// corrupt, truncated or foreign file is refused with what is wrong and at which byte. Layout byte by byte:
// formats/README.md.

#include "kumite/core/result.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace kumite {

inline constexpr char k_database_magic[8] = {'K', 'U', 'M', 'I', 'T', 'E', 'D', 'B'};
// Version 2 added each clip's strike kind and height (CLIP records of 84 bytes).
inline constexpr std::uint32_t k_database_format_version = 2;
inline constexpr std::size_t k_database_alignment = 64;

// A section's type: four characters, e.g. section_tag("CLIP").
constexpr std::uint32_t section_tag(const char (&name)[5]) {
    return std::uint32_t(std::uint8_t(name[0])) | std::uint32_t(std::uint8_t(name[1])) << 8 |
           std::uint32_t(std::uint8_t(name[2])) << 16 | std::uint32_t(std::uint8_t(name[3])) << 24;
}
std::string section_tag_name(std::uint32_t tag);

struct DatabaseSection {
    std::uint32_t tag = 0;
    std::uint32_t element_size = 0;
    std::uint64_t offset = 0; // from the start of the file, a multiple of k_database_alignment
    std::uint64_t count = 0;
    std::span<const std::byte> bytes;
};

// Collects sections, then writes the image: same sections in the same order, same bytes.
class DatabaseImageBuilder {
public:
    void add_section(std::uint32_t tag, std::uint32_t element_size, std::span<const std::byte> bytes);
    std::vector<std::byte> build() const;
    Result<void> write_file(const std::filesystem::path& path) const; // atomic

private:
    struct Pending {
        std::uint32_t tag;
        std::uint32_t element_size;
        std::vector<std::byte> bytes;
    };
    std::vector<Pending> m_sections;
};

// A mapped, validated image. Sections point into the mapping, which lives as long as the view. Opening reads the
// header and the section table only (no section's bytes), so it takes the same time for any file size.
class DatabaseImage {
public:
    static Result<DatabaseImage> open(const std::filesystem::path& path, bool verify_hash = false);
    // Validates bytes already in memory (the caller keeps them alive); `source_name` prefixes errors.
    static Result<DatabaseImage> view(std::span<const std::byte> bytes, std::string_view source_name, bool verify_hash = false);

    // Rehashes every byte after the header against the header's content hash: O(file size).
    Result<void> verify_hash() const;

    const std::string& source_name() const { return m_source_name; }
    std::uint32_t format_version() const { return m_format_version; }
    std::uint64_t byte_size() const { return m_bytes.size(); }
    std::uint64_t content_hash() const { return m_content_hash; }
    const std::vector<DatabaseSection>& sections() const { return m_sections; }
    const DatabaseSection* find(std::uint32_t tag) const;

private:
    std::shared_ptr<void> m_mapping; // unmaps when the last copy goes
    std::span<const std::byte> m_bytes;
    std::string m_source_name;
    std::uint32_t m_format_version = 0;
    std::uint64_t m_content_hash = 0;
    std::vector<DatabaseSection> m_sections;
};

// The content hash over every byte after the header: FNV-1a on 64-bit words in four lanes, finalised
// (formats/README.md gives the exact steps).
std::uint64_t database_content_hash(std::span<const std::byte> bytes);

} // namespace kumite
