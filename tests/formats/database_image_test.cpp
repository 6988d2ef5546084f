// The database image: what the builder writes, the view accepts; every corruption class is refused with a reason
// and a byte offset.

#include "kumite/formats/database_image.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace kumite;

namespace {

constexpr std::uint32_t k_numbers = section_tag("NUMS");
constexpr std::uint32_t k_names = section_tag("STRS");

std::vector<std::byte> sample_image() {
    std::vector<double> numbers = {1.5, -2.25, 3.0};
    const std::string names("kick_r\0punch_l\0", 15);
    DatabaseImageBuilder builder;
    builder.add_section(k_numbers, sizeof(double), std::as_bytes(std::span(numbers)));
    builder.add_section(k_names, 1, std::as_bytes(std::span(names.data(), names.size())));
    return builder.build();
}

std::string error_of(const std::vector<std::byte>& bytes, bool verify = true) {
    Result<DatabaseImage> image = DatabaseImage::view(bytes, "x.kdb", verify);
    REQUIRE_FALSE(image.has_value());
    return image.error().message;
}

void put_u64(std::vector<std::byte>& bytes, size_t offset, std::uint64_t value) {
    for (int i = 0; i < 8; ++i) bytes[offset + i] = std::byte((value >> (8 * i)) & 0xff);
}

} // namespace

TEST_CASE("database_image: sections come back aligned and unchanged", "[formats]") {
    const std::vector<std::byte> bytes = sample_image();
    Result<DatabaseImage> image = DatabaseImage::view(bytes, "x.kdb", true);
    REQUIRE(image.has_value());
    CHECK(image->format_version() == k_database_format_version);
    CHECK(image->byte_size() == bytes.size());
    REQUIRE(image->sections().size() == 2);
    const DatabaseSection* numbers = image->find(k_numbers);
    REQUIRE(numbers != nullptr);
    CHECK(numbers->offset % k_database_alignment == 0);
    CHECK(numbers->count == 3);
    const double* values = reinterpret_cast<const double*>(numbers->bytes.data());
    CHECK(values[1] == -2.25);
    CHECK(image->find(k_names)->count == 15);
    CHECK(image->find(section_tag("NONE")) == nullptr);
    CHECK(sample_image() == bytes); // the same input gives the same bytes
}

TEST_CASE("database_image: corrupt, truncated and foreign files are refused with the byte", "[formats]") {
    const std::vector<std::byte> good = sample_image();
    auto flipped = [&](size_t offset) {
        std::vector<std::byte> bytes = good;
        bytes[offset] ^= std::byte{0x40};
        return bytes;
    };
    CHECK_THAT(error_of(flipped(good.size() - 70)), Catch::Contains("byte 24") && Catch::Contains("content hash"));
    CHECK(DatabaseImage::view(flipped(good.size() - 70), "x.kdb", false).has_value()); // only --verify reads every byte
    CHECK_THAT(error_of(flipped(0)), Catch::Contains("byte 0") && Catch::Contains("magic"));
    CHECK_THAT(error_of(flipped(8)), Catch::Contains("byte 8") && Catch::Contains("format version"));
    CHECK_THAT(error_of(std::vector<std::byte>(good.begin(), good.end() - 10)), Catch::Contains("byte 16") && Catch::Contains("truncated"));
    CHECK_THAT(error_of(std::vector<std::byte>(good.begin(), good.begin() + 20)), Catch::Contains("too short"));
    CHECK_THAT(error_of({}), Catch::Contains("too short"));
    const std::string bvh = "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n}\nMOTION\n";
    CHECK_THAT(error_of(std::vector<std::byte>(reinterpret_cast<const std::byte*>(bvh.data()), reinterpret_cast<const std::byte*>(bvh.data()) + bvh.size())),
               Catch::Contains("not a kumite database"));

    std::vector<std::byte> outside = good;
    put_u64(outside, 64 + 8, good.size() + 64); // first section's offset past the end
    CHECK_THAT(error_of(outside, false), Catch::Contains("byte 72") && Catch::Contains("outside the file"));
    std::vector<std::byte> misaligned = good;
    put_u64(misaligned, 64 + 8, 136);
    CHECK_THAT(error_of(misaligned, false), Catch::Contains("not 64-byte aligned"));
    std::vector<std::byte> miscounted = good;
    put_u64(miscounted, 64 + 16, 4); // 4 doubles claimed, 3 stored
    CHECK_THAT(error_of(miscounted, false), Catch::Contains("byte 80") && Catch::Contains("do not make"));
    std::vector<std::byte> table_outside = good;
    put_u64(table_outside, 40, 1u << 30);
    CHECK_THAT(error_of(table_outside, false), Catch::Contains("byte 40") && Catch::Contains("section table"));
}

TEST_CASE("database_image: files are mapped, and empty or missing files refused", "[formats]") {
    const std::filesystem::path dir = kumite::test::make_temp_dir("kdb");
    DatabaseImageBuilder builder;
    std::vector<float> values(1000, 0.5f);
    builder.add_section(section_tag("VALS"), sizeof(float), std::as_bytes(std::span(values)));
    REQUIRE(builder.write_file(dir / "a.kdb").has_value());
    Result<DatabaseImage> image = DatabaseImage::open(dir / "a.kdb", true);
    REQUIRE(image.has_value());
    CHECK(image->find(section_tag("VALS"))->count == 1000);

    std::ofstream(dir / "empty.kdb").close();
    Result<DatabaseImage> empty = DatabaseImage::open(dir / "empty.kdb");
    REQUIRE_FALSE(empty.has_value());
    CHECK_THAT(empty.error().message, Catch::Contains("empty"));
    CHECK_FALSE(DatabaseImage::open(dir / "missing.kdb").has_value());
    CHECK_FALSE(DatabaseImage::open(dir).has_value()); // a folder
}
