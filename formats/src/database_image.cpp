#include "kumite/formats/database_image.h"

#include "kumite/formats/atomic_file.h"

#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kumite {
namespace {

// Header, 64 bytes:
//   0 magic[8] | 8 u32 format_version | 12 u32 header_size (64) | 16 u64 byte_size | 24 u64 content_hash
//   32 u32 section_count | 36 u32 reserved (0) | 40 u64 section_table_offset | 48..63 reserved (0)
// Section table entry, 32 bytes: 0 u32 tag | 4 u32 element_size | 8 u64 offset | 16 u64 count | 24 u64 byte_size
constexpr std::size_t k_header_size = 64;
constexpr std::size_t k_entry_size = 32;
constexpr std::uint32_t k_max_sections = 4096;

template <class T>
T read_le(std::span<const std::byte> bytes, std::size_t offset) {
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) value |= T(std::to_integer<std::uint8_t>(bytes[offset + i])) << (8 * i);
    return value;
}

template <class T>
void write_le(std::vector<std::byte>& bytes, std::size_t offset, T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i) bytes[offset + i] = std::byte((value >> (8 * i)) & 0xff);
}

std::size_t align_up(std::size_t value) { return (value + k_database_alignment - 1) / k_database_alignment * k_database_alignment; }

} // namespace

std::string section_tag_name(std::uint32_t tag) {
    std::string name;
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>((tag >> (8 * i)) & 0xff);
        name += (c >= 32 && c < 127) ? c : '?';
    }
    return name;
}

std::uint64_t database_content_hash(std::span<const std::byte> bytes) {
    // FNV-1a on 64-bit little-endian words in four interleaved lanes (four independent multiply chains instead of
    // one per byte: ~10x faster), the tail bytes one by one, then the lanes folded and finalised. Each step is a
    // bijection of the lane for a fixed input, so changing any one word or byte always changes the hash.
    constexpr std::uint64_t prime = 0x100000001b3ull;
    std::uint64_t lanes[4] = {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull, 0x9ce484222325cbf2ull, 0x2325cbf29ce48422ull};
    const std::size_t blocks = bytes.size() / 32;
    const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data());
    for (std::size_t block = 0; block < blocks; ++block) {
        for (int lane = 0; lane < 4; ++lane) {
            std::uint64_t word;
            std::memcpy(&word, data + block * 32 + lane * 8, 8); // little-endian hosts only (see the README)
            lanes[lane] = (lanes[lane] ^ word) * prime;
        }
    }
    std::uint64_t hash = lanes[0];
    for (int lane = 1; lane < 4; ++lane) hash = (hash ^ lanes[lane]) * prime;
    for (std::size_t i = blocks * 32; i < bytes.size(); ++i) hash = (hash ^ data[i]) * prime;
    hash ^= bytes.size();
    hash = (hash ^ (hash >> 30)) * 0xbf58476d1ce4e5b9ull; // splitmix64's finaliser: every bit reaches every bit
    hash = (hash ^ (hash >> 27)) * 0x94d049bb133111ebull;
    return hash ^ (hash >> 31);
}

void DatabaseImageBuilder::add_section(std::uint32_t tag, std::uint32_t element_size, std::span<const std::byte> bytes) {
    m_sections.push_back({tag, element_size, std::vector<std::byte>(bytes.begin(), bytes.end())});
}

std::vector<std::byte> DatabaseImageBuilder::build() const {
    const std::size_t table_offset = k_header_size;
    std::size_t offset = align_up(table_offset + k_entry_size * m_sections.size());
    std::vector<std::size_t> offsets;
    for (const Pending& section : m_sections) {
        offsets.push_back(offset);
        offset = align_up(offset + section.bytes.size());
    }
    std::vector<std::byte> image(offset, std::byte{0});
    std::memcpy(image.data(), k_database_magic, sizeof k_database_magic);
    write_le<std::uint32_t>(image, 8, k_database_format_version);
    write_le<std::uint32_t>(image, 12, k_header_size);
    write_le<std::uint64_t>(image, 16, image.size());
    write_le<std::uint32_t>(image, 32, static_cast<std::uint32_t>(m_sections.size()));
    write_le<std::uint64_t>(image, 40, table_offset);
    for (std::size_t i = 0; i < m_sections.size(); ++i) {
        const Pending& section = m_sections[i];
        const std::size_t entry = table_offset + i * k_entry_size;
        write_le<std::uint32_t>(image, entry, section.tag);
        write_le<std::uint32_t>(image, entry + 4, section.element_size);
        write_le<std::uint64_t>(image, entry + 8, offsets[i]);
        write_le<std::uint64_t>(image, entry + 16, section.element_size ? section.bytes.size() / section.element_size : 0);
        write_le<std::uint64_t>(image, entry + 24, section.bytes.size());
        if (!section.bytes.empty()) std::memcpy(image.data() + offsets[i], section.bytes.data(), section.bytes.size());
    }
    write_le<std::uint64_t>(image, 24, database_content_hash(std::span<const std::byte>(image).subspan(k_header_size)));
    return image;
}

Result<void> DatabaseImageBuilder::write_file(const std::filesystem::path& path) const {
    const std::vector<std::byte> image = build();
    return write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(image.data()), image.size()));
}

const DatabaseSection* DatabaseImage::find(std::uint32_t tag) const {
    for (const DatabaseSection& section : m_sections) {
        if (section.tag == tag) return &section;
    }
    return nullptr;
}

Result<DatabaseImage> DatabaseImage::view(std::span<const std::byte> bytes, std::string_view source_name, bool verify_hash) {
    const std::string source(source_name);
    auto fail = [&](std::size_t offset, const std::string& what) {
        return make_error(ErrorCode::invalid, source + ": byte " + std::to_string(offset) + ": " + what);
    };
    if (bytes.size() < k_header_size) {
        return make_error(ErrorCode::invalid, source + ": " + std::to_string(bytes.size()) +
                                                  " bytes, too short for a kumite database (the header alone is 64)");
    }
    if (std::memcmp(bytes.data(), k_database_magic, sizeof k_database_magic) != 0) {
        return fail(0, "not a kumite database (no KUMITEDB magic); bake one with kumite bake");
    }
    DatabaseImage image;
    image.m_bytes = bytes;
    image.m_source_name = source;
    image.m_format_version = read_le<std::uint32_t>(bytes, 8);
    if (image.m_format_version != k_database_format_version) {
        return fail(8, "format version " + std::to_string(image.m_format_version) + ", this kumite reads version " +
                           std::to_string(k_database_format_version) + "; bake the database again");
    }
    if (read_le<std::uint32_t>(bytes, 12) != k_header_size) return fail(12, "header size is not 64");
    const std::uint64_t declared_size = read_le<std::uint64_t>(bytes, 16);
    if (declared_size != bytes.size()) {
        return fail(16, "the header declares " + std::to_string(declared_size) + " bytes but the file has " +
                            std::to_string(bytes.size()) + " (truncated or padded)");
    }
    image.m_content_hash = read_le<std::uint64_t>(bytes, 24);
    const std::uint32_t count = read_le<std::uint32_t>(bytes, 32);
    const std::uint64_t table = read_le<std::uint64_t>(bytes, 40);
    if (count > k_max_sections) return fail(32, std::to_string(count) + " sections, more than " + std::to_string(k_max_sections));
    if (table < k_header_size || table > bytes.size() || (bytes.size() - table) / k_entry_size < count) {
        return fail(40, "the section table lies outside the file");
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::size_t entry = table + i * k_entry_size;
        DatabaseSection section;
        section.tag = read_le<std::uint32_t>(bytes, entry);
        section.element_size = read_le<std::uint32_t>(bytes, entry + 4);
        section.offset = read_le<std::uint64_t>(bytes, entry + 8);
        section.count = read_le<std::uint64_t>(bytes, entry + 16);
        const std::uint64_t size = read_le<std::uint64_t>(bytes, entry + 24);
        const std::string name = "section " + std::to_string(i) + " (" + section_tag_name(section.tag) + ")";
        if (section.offset % k_database_alignment != 0) return fail(entry + 8, name + " is not 64-byte aligned");
        if (section.offset < table + count * k_entry_size || section.offset > bytes.size() || size > bytes.size() - section.offset) {
            return fail(entry + 8, name + " lies outside the file or over the header");
        }
        const bool sizes_agree = section.element_size == 0 ? size == 0
                                                           : (size % section.element_size == 0 && size / section.element_size == section.count);
        if (!sizes_agree) {
            return fail(entry + 16, name + ": " + std::to_string(section.count) + " elements of " + std::to_string(section.element_size) +
                                        " bytes do not make " + std::to_string(size) + " bytes");
        }
        section.bytes = bytes.subspan(section.offset, size);
        image.m_sections.push_back(section);
    }
    if (verify_hash) {
        if (Result<void> hashed = image.verify_hash(); !hashed) return hashed.error();
    }
    return image;
}

Result<void> DatabaseImage::verify_hash() const {
    if (database_content_hash(m_bytes.subspan(k_header_size)) == m_content_hash) return {};
    return make_error(ErrorCode::invalid, m_source_name + ": byte 24: the content hash does not match: the file is corrupt");
}

Result<DatabaseImage> DatabaseImage::open(const std::filesystem::path& path, bool verify_hash) {
    const std::string source = path.string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return make_error(ErrorCode::io, source + ": cannot open the database file");
    struct stat status {};
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
        ::close(fd);
        return make_error(ErrorCode::io, source + ": not a regular file");
    }
    const std::size_t size = static_cast<std::size_t>(status.st_size);
    if (size == 0) {
        ::close(fd);
        return make_error(ErrorCode::invalid, source + ": the file is empty (0 bytes), not a kumite database");
    }
    void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    ::close(fd);
    if (address == MAP_FAILED) return make_error(ErrorCode::io, source + ": cannot map the file");
    std::shared_ptr<void> mapping(address, [size](void* mapped) { ::munmap(mapped, size); });
    Result<DatabaseImage> image = view(std::span(static_cast<const std::byte*>(address), size), source, verify_hash);
    if (image) image->m_mapping = std::move(mapping);
    return image;
}

} // namespace kumite
