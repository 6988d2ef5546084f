#pragma once
// BVH reader: HIERARCHY + MOTION text into a Clip in metres, plus the channel layout the writer needs to give
// the file back with the same hierarchy, names, channel order and rotation orders.
//
// Accepts any channel order per joint (0-6 channels, each at most once), mixed rotation orders, CRLF/LF/mixed
// line ends, tabs, numbers like ".1", "2." and "1e-05", blank lines, joints without End Site. Errors come back
// as a Result naming the file and line and what was expected; a hostile file costs at most memory proportional
// to its size (frame counts are checked against the bytes that follow).
//
// Tolerated, as other readers (Blender's) tolerate them, each with a warning "file:line: what" in
// BvhFile::warnings (refused instead with BvhReadOptions::strict): an End block named like a joint ("End ltoes",
// read as End Site); frames not one per line (all values on one line, or frames wrapped over lines: the values
// are read as one stream and cut into frames by the channel count); whole values after the frames 'Frames:'
// declares (ignored); `Frame Time: 0` or no 'Frame Time:' line (read with no rate: Clip::frame_time_s = 0, unless
// BvhReadOptions::frame_rate_hz gives one). Still refused: too few values, a truncated hierarchy, a value that is not a number.

#include "kumite/core/body_map.h"
#include "kumite/core/clip.h"
#include "kumite/core/euler.h"
#include "kumite/core/result.h"
#include "kumite/formats/length_unit.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace kumite {

enum class BvhChannel : std::uint8_t { x_position, y_position, z_position, x_rotation, y_rotation, z_rotation };

std::string_view bvh_channel_name(BvhChannel channel); // "Xposition"

struct BvhJointChannels {
    std::array<BvhChannel, 6> channels{};
    int count = 0;
    EulerOrder rotation_order; // rotation axes as listed; axes without a channel appended in X, Y, Z order

    bool has_position() const;
    bool has_rotation() const;
};

struct BvhLayout {
    std::vector<BvhJointChannels> joints; // [joint]
    int channel_count() const;
};

struct BvhReadOptions {
    std::optional<LengthUnit> unit;                 // none: detect from the standing height
    std::size_t max_file_bytes = std::size_t(1) << 30;
    int threads = 0; // frame parsing threads for large files: 0 = up to 2 when the machine has them, 1 = serial
    bool strict = false; // refuse what is otherwise read with a warning (see above)
    // The capture's rate when the file gives none (`Frame Time: 0` or no such line), e.g. from --fps; it also
    // replaces a rate the file states, with a warning. Must be > 0 and finite.
    std::optional<double> frame_rate_hz;
};

struct BvhFile {
    Clip clip;             // metres
    BvhLayout layout;
    LengthUnit unit;       // the file's unit (detected or forced)
    bool unit_detected = true;
    bool frame_rate_in_file = true; // false: 'Frame Time: 0' or missing (the rate, if any, came from frame_rate_hz)
    double height_m = 0.0; // standing height after conversion
    BodyMap body_map;      // detected from the joint names
    std::vector<std::string> warnings; // "file:line: what was tolerated and how it was read", in file order
};

inline constexpr int k_bvh_max_joints = 10000;
inline constexpr int k_bvh_max_frames = 100000000;
inline constexpr double k_bvh_min_frame_time_s = 1e-6;
inline constexpr double k_bvh_max_frame_time_s = 3600.0;
// Joints x frames a clip may hold (~2.8 GB with translations); larger files are refused as a limit.
inline constexpr std::size_t k_bvh_max_joint_frames = 50000000;

// Parses BVH text; `source_name` (usually the path) prefixes error messages.
Result<BvhFile> bvh_parse(std::string_view text, std::string_view source_name, const BvhReadOptions& options = {});

// Reads and parses a file; errors for unreadable, oversized or malformed files.
Result<BvhFile> bvh_read_file(const std::filesystem::path& path, const BvhReadOptions& options = {});

} // namespace kumite
