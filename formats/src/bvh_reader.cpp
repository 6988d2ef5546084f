#include "kumite/formats/bvh_reader.h"

#include "kumite/core/standing_height.h"
#include "bvh_raw.h"
#include "text_cursor.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <system_error>
#include <thread>

namespace kumite {
namespace {

bool equals_ignore_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string format_number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

std::optional<BvhChannel> channel_from_name(std::string_view name) {
    for (int i = 0; i < 6; ++i) {
        if (equals_ignore_case(name, bvh_channel_name(static_cast<BvhChannel>(i)))) return static_cast<BvhChannel>(i);
    }
    return std::nullopt;
}

class HierarchyParser {
public:
    HierarchyParser(TextCursor& cursor, std::string_view source, bool strict, std::vector<std::string>& warnings)
        : m_cursor(cursor), m_source(source), m_strict(strict), m_warnings(warnings) {}

    Result<void> parse(RawBvh& raw);

private:
    Error fail(const std::string& what) const {
        return make_error(ErrorCode::parse, std::string(m_source) + ":" + std::to_string(m_cursor.line()) + ": " + what);
    }
    Result<Eigen::Vector3d> parse_offset();
    Result<void> parse_channels(BvhJointChannels& channels);
    Result<void> open_joint(RawBvh& raw, int parent);

    TextCursor& m_cursor;
    std::string_view m_source;
    bool m_strict = false;
    std::vector<std::string>& m_warnings;
    std::vector<int> m_open_joints; // joints whose '}' is still expected
    std::vector<bool> m_has_offset;
};

Result<Eigen::Vector3d> HierarchyParser::parse_offset() {
    Eigen::Vector3d offset;
    for (int axis = 0; axis < 3; ++axis) {
        if (!m_cursor.parse_number(offset[axis])) {
            return fail("expected 3 numbers after OFFSET, found " + m_cursor.peek_for_message());
        }
    }
    return offset;
}

Result<void> HierarchyParser::parse_channels(BvhJointChannels& joint) {
    double count = 0;
    if (!m_cursor.parse_number(count)) {
        return fail("expected a channel count from 0 to 6 after CHANNELS, found " + m_cursor.peek_for_message());
    }
    if (count != std::floor(count) || count < 0 || count > 6) {
        return fail("expected a channel count from 0 to 6 after CHANNELS, found " + format_number(count));
    }
    joint.count = static_cast<int>(count);
    std::array<bool, 6> seen{};
    int rotation_axes = 0;
    for (int i = 0; i < joint.count; ++i) {
        const std::string_view token = m_cursor.next_token();
        const std::optional<BvhChannel> channel = channel_from_name(token);
        if (!channel) {
            return fail("expected a channel name (Xposition ... Zrotation), found '" + std::string(token) + "'");
        }
        if (seen[static_cast<int>(*channel)]) return fail("channel " + std::string(token) + " listed twice");
        seen[static_cast<int>(*channel)] = true;
        joint.channels[i] = *channel;
        if (*channel >= BvhChannel::x_rotation) {
            joint.rotation_order.axes[rotation_axes++] = static_cast<int>(*channel) - 3;
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!seen[3 + axis]) joint.rotation_order.axes[rotation_axes++] = axis;
    }
    return {};
}

Result<void> HierarchyParser::open_joint(RawBvh& raw, int parent) {
    std::string_view name = m_cursor.rest_of_line();
    bool brace_on_name_line = false;
    if (name.ends_with("{")) {
        brace_on_name_line = true;
        name.remove_suffix(1);
        while (!name.empty() && TextCursor::is_blank(name.back())) name.remove_suffix(1);
    }
    if (name.empty()) return fail("expected a joint name");
    if (name.find_first_of("{}") != std::string_view::npos) {
        return fail("joint name '" + std::string(name.substr(0, 40)) + "' contains a brace");
    }
    if (raw.skeleton.joint_count() >= k_bvh_max_joints) {
        return make_error(ErrorCode::limit, std::string(m_source) + ":" + std::to_string(m_cursor.line()) +
                                                ": more than " + std::to_string(k_bvh_max_joints) + " joints");
    }
    if (!brace_on_name_line) {
        const std::string_view brace = m_cursor.next_token();
        if (brace != "{") return fail("expected '{' after joint " + std::string(name) + ", found '" + std::string(brace) + "'");
    }
    raw.skeleton.names.emplace_back(name);
    raw.skeleton.parents.push_back(parent);
    raw.skeleton.rest_offsets.push_back(Eigen::Vector3d::Zero());
    raw.layout.joints.emplace_back();
    m_has_offset.push_back(false);
    m_open_joints.push_back(raw.skeleton.joint_count() - 1);
    return {};
}

Result<void> HierarchyParser::parse(RawBvh& raw) {
    if (const std::string_view token = m_cursor.next_token(); !equals_ignore_case(token, "HIERARCHY")) {
        return fail("expected HIERARCHY at the start of a BVH file, found '" + std::string(token.substr(0, 24)) + "'");
    }
    if (const std::string_view token = m_cursor.next_token(); !equals_ignore_case(token, "ROOT")) {
        return fail("expected ROOT, found '" + std::string(token.substr(0, 24)) + "'");
    }
    if (Result<void> opened = open_joint(raw, -1); !opened) return opened;

    while (!m_open_joints.empty()) {
        const std::string_view token = m_cursor.next_token();
        const int joint = m_open_joints.back();
        if (token.empty()) {
            return fail("the hierarchy ends inside joint " + raw.skeleton.names[joint] + " (missing '}')");
        } else if (equals_ignore_case(token, "OFFSET")) {
            Result<Eigen::Vector3d> offset = parse_offset();
            if (!offset) return offset.error();
            raw.skeleton.rest_offsets[joint] = *offset;
            m_has_offset[joint] = true;
        } else if (equals_ignore_case(token, "CHANNELS")) {
            if (Result<void> parsed = parse_channels(raw.layout.joints[joint]); !parsed) return parsed;
        } else if (equals_ignore_case(token, "JOINT")) {
            if (Result<void> opened = open_joint(raw, joint); !opened) return opened;
        } else if (equals_ignore_case(token, "End")) {
            const int end_line = m_cursor.line();
            const std::string_view site = m_cursor.next_token();
            if (!equals_ignore_case(site, "Site")) {
                // "End ltoes": some exporters name the End block like a joint. An End block has no channels and
                // no children, so it is read as the End Site it is.
                if (site.empty() || site == "{" || site == "}" || m_strict) {
                    return fail("expected 'Site' after 'End', found '" + std::string(site.substr(0, 24)) + "'" + (m_strict ? " (refused: strict)" : ""));
                }
                m_warnings.push_back(std::string(m_source) + ":" + std::to_string(end_line) + ": 'End " + std::string(site.substr(0, 40)) +
                                     "' read as an End Site of joint " + raw.skeleton.names[joint]);
            }
            if (m_cursor.next_token() != "{") return fail("expected '{' after End Site");
            if (!equals_ignore_case(m_cursor.next_token(), "OFFSET")) return fail("expected OFFSET in End Site");
            Result<Eigen::Vector3d> offset = parse_offset();
            if (!offset) return offset.error();
            if (m_cursor.next_token() != "}") return fail("expected '}' closing End Site");
            raw.skeleton.end_sites.push_back({joint, *offset});
        } else if (token == "}") {
            if (!m_has_offset[joint]) return fail("joint " + raw.skeleton.names[joint] + " has no OFFSET");
            m_open_joints.pop_back();
        } else if (equals_ignore_case(token, "ROOT")) {
            return make_error(ErrorCode::unsupported, std::string(m_source) + ":" + std::to_string(m_cursor.line()) +
                                                          ": a second ROOT inside a joint (missing '}')");
        } else {
            return fail("expected OFFSET, CHANNELS, JOINT, End Site or '}' in joint " + raw.skeleton.names[joint] +
                        ", found '" + std::string(token.substr(0, 24)) + "'");
        }
    }
    return {};
}

Result<void> parse_motion_header(TextCursor& cursor, std::string_view source, bool strict, RawBvh& raw) {
    auto fail = [&](const std::string& what) {
        return make_error(ErrorCode::parse, std::string(source) + ":" + std::to_string(cursor.line()) + ": " + what);
    };
    const std::string_view motion = cursor.next_token();
    if (equals_ignore_case(motion, "ROOT")) {
        return make_error(ErrorCode::unsupported, std::string(source) + ":" + std::to_string(cursor.line()) +
                                                      ": several ROOT hierarchies in one file are not supported");
    }
    if (!equals_ignore_case(motion, "MOTION")) {
        return fail(motion.empty() ? "the file ends after the hierarchy (expected MOTION)"
                                   : "expected MOTION after the hierarchy, found '" + std::string(motion.substr(0, 24)) + "'");
    }
    std::string_view frames = cursor.next_token();
    if (equals_ignore_case(frames, "Frames")) frames = cursor.next_token(); // "Frames :"
    else if (!equals_ignore_case(frames.substr(0, 7), "Frames:")) return fail("expected 'Frames:'");
    double frame_count = 0;
    if (!cursor.parse_number(frame_count)) return fail("expected a frame count after 'Frames:', found " + cursor.peek_for_message());
    if (frame_count < 0 || frame_count != std::floor(frame_count) || frame_count > k_bvh_max_frames) {
        return fail("expected a frame count from 0 to " + std::to_string(k_bvh_max_frames) + " after 'Frames:', found " +
                    format_number(frame_count));
    }
    raw.frame_count = static_cast<int>(frame_count);
    // "Frame Time: t". Captures from the wild say 0 (the rate was not recorded) or leave the line out: the
    // positions of each frame need no rate, so those read with a warning and no rate (frame_time_s = 0).
    cursor.skip_whitespace();
    const TextCursor before_frame_time = cursor;
    const int frame_time_line = cursor.line();
    if (!equals_ignore_case(cursor.next_token(), "Frame")) {
        if (strict) return fail("expected 'Frame Time:' (refused: strict)");
        cursor = before_frame_time;
        raw.frame_time_s = 0.0;
        raw.frame_time_note = std::string(source) + ":" + std::to_string(frame_time_line) +
                              ": no 'Frame Time:' line: the capture has no frame rate";
        return {};
    }
    if (!equals_ignore_case(cursor.next_token().substr(0, 5), "Time:")) return fail("expected 'Frame Time:'");
    if (!cursor.parse_number(raw.frame_time_s)) {
        return fail("expected the frame time in seconds after 'Frame Time:', found " + cursor.peek_for_message());
    }
    if (raw.frame_time_s == 0.0 && !strict) {
        raw.frame_time_note = std::string(source) + ":" + std::to_string(cursor.line()) + ": 'Frame Time: 0': the capture has no frame rate";
        return {};
    }
    if (raw.frame_time_s < k_bvh_min_frame_time_s || raw.frame_time_s > k_bvh_max_frame_time_s) {
        return fail("expected a frame time from 1e-06 to 3600 seconds after 'Frame Time:', found " + format_number(raw.frame_time_s) +
                    (raw.frame_time_s == 0.0 ? " (refused: strict)" : ""));
    }
    return {};
}

// The rate: the file's, or options.frame_rate_hz (which also overrides a stated rate, with a warning), or none
// (frame_time_s = 0) with a warning that says how to give one.
void apply_frame_rate(RawBvh& raw, std::string_view source, const BvhReadOptions& options, std::vector<std::string>& warnings) {
    if (options.frame_rate_hz) {
        const double given_s = 1.0 / *options.frame_rate_hz;
        if (!raw.frame_time_note.empty()) {
            warnings.push_back(raw.frame_time_note + "; read at " + format_number(*options.frame_rate_hz) + " fps (--fps)");
        } else if (std::abs(given_s - raw.frame_time_s) > 1e-9 * raw.frame_time_s) {
            warnings.push_back(std::string(source) + ": the file says " + format_number(1.0 / raw.frame_time_s) + " fps; read at " +
                               format_number(*options.frame_rate_hz) + " fps (--fps)");
        }
        raw.frame_time_s = given_s;
        return;
    }
    if (!raw.frame_time_note.empty()) {
        warnings.push_back(raw.frame_time_note + "; positions are read per frame, and what needs time (suggest, bake, "
                                                      "retarget, replay) needs the rate: --fps N, or \"fps\" in the annotation file");
    }
}

} // namespace

std::string_view bvh_channel_name(BvhChannel channel) {
    static constexpr std::array<std::string_view, 6> k_names = {"Xposition", "Yposition", "Zposition",
                                                                "Xrotation", "Yrotation", "Zrotation"};
    return k_names[static_cast<int>(channel)];
}

bool BvhJointChannels::has_position() const {
    return std::any_of(channels.begin(), channels.begin() + count, [](BvhChannel c) { return c <= BvhChannel::z_position; });
}

bool BvhJointChannels::has_rotation() const {
    return std::any_of(channels.begin(), channels.begin() + count, [](BvhChannel c) { return c >= BvhChannel::x_rotation; });
}

int BvhLayout::channel_count() const {
    int count = 0;
    for (const BvhJointChannels& joint : joints) count += joint.count;
    return count;
}

Result<BvhFile> bvh_parse(std::string_view text, std::string_view source_name, const BvhReadOptions& options) {
    TextCursor cursor(text);
    RawBvh raw;
    BvhFile file;
    HierarchyParser hierarchy(cursor, source_name, options.strict, file.warnings);
    if (Result<void> parsed = hierarchy.parse(raw); !parsed) return parsed.error();
    if (Result<void> parsed = parse_motion_header(cursor, source_name, options.strict, raw); !parsed) return parsed.error();
    apply_frame_rate(raw, source_name, options, file.warnings);

    const int threads = options.threads > 0 ? options.threads : static_cast<int>(std::min(2u, std::thread::hardware_concurrency()));
    if (Result<void> parsed = bvh_parse_frames(cursor, source_name, raw, file.clip, threads, options.strict, file.warnings); !parsed) {
        return parsed.error();
    }
    file.clip.skeleton = std::move(raw.skeleton);
    file.clip.frame_time_s = raw.frame_time_s;
    file.frame_rate_in_file = raw.frame_time_note.empty();
    file.layout = std::move(raw.layout);

    // Unit: measure in file units, then convert every length once.
    file.body_map = detect_body_map(file.clip.skeleton);
    const double height_in_file_units = standing_height(file.clip, file.body_map).height;
    file.unit_detected = !options.unit.has_value();
    file.unit = options.unit ? *options.unit : length_unit_for_height(height_in_file_units);
    const double scale = file.unit.metres;
    for (Eigen::Vector3d& offset : file.clip.skeleton.rest_offsets) offset *= scale;
    for (EndSite& end_site : file.clip.skeleton.end_sites) end_site.offset_in_joint *= scale;
    for (Eigen::Vector3d& translation : file.clip.root_translations) translation *= scale;
    for (Eigen::Vector3d& translation : file.clip.local_translations) translation *= scale;
    file.height_m = height_in_file_units * scale;
    return file;
}

Result<BvhFile> bvh_read_file(const std::filesystem::path& path, const BvhReadOptions& options) {
    const std::string source = path.string();
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        return make_error(ErrorCode::io, source + ": is a directory, expected a .bvh file");
    }
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return make_error(ErrorCode::io, source + ": cannot open file (does it exist and is it readable?)");
    stream.seekg(0, std::ios::end);
    const std::streamoff size = stream.tellg();
    if (size < 0) return make_error(ErrorCode::io, source + ": cannot determine the file size");
    if (static_cast<std::size_t>(size) > options.max_file_bytes) {
        return make_error(ErrorCode::limit, source + ": file is " + std::to_string(size) + " bytes, more than the " +
                                                std::to_string(options.max_file_bytes) + "-byte limit for a BVH file");
    }
    std::string text(static_cast<std::size_t>(size), '\0');
    stream.seekg(0);
    if (!stream.read(text.data(), size)) return make_error(ErrorCode::io, source + ": read failed");
    return bvh_parse(text, source, options);
}

} // namespace kumite
