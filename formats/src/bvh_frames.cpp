#include "bvh_raw.h"

#include <cmath>
#include <optional>
#include <system_error>
#include <thread>

namespace kumite {
namespace {

constexpr double k_half_degree_in_radians = 3.14159265358979323846 / 360.0;

// Where a joint's values sit in a frame line.
struct JointSlots {
    std::array<int, 3> position{-1, -1, -1}; // [axis] value index, -1 when the axis keeps the rest offset
    std::array<int, 3> rotation{-1, -1, -1}; // [k] value index of the k-th axis of the rotation order, -1: zero
    EulerOrder order;
    bool has_position = false;
};

std::vector<JointSlots> joint_slots(const BvhLayout& layout) {
    std::vector<JointSlots> slots(layout.joints.size());
    int value_index = 0;
    for (size_t joint = 0; joint < layout.joints.size(); ++joint) {
        const BvhJointChannels& channels = layout.joints[joint];
        JointSlots& slot = slots[joint];
        slot.order = channels.rotation_order;
        for (int i = 0; i < channels.count; ++i, ++value_index) {
            const int channel = static_cast<int>(channels.channels[i]);
            if (channel < 3) {
                slot.position[channel] = value_index;
                slot.has_position = true;
            } else {
                for (int k = 0; k < 3; ++k) {
                    if (slot.order.axes[k] == channel - 3) slot.rotation[k] = value_index;
                }
            }
        }
    }
    return slots;
}

// R = R(axis0) R(axis1) R(axis2) from half-angle sines and cosines, without building matrices.
Eigen::Quaterniond rotation_from_degrees(const double* values, const JointSlots& slot) {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    for (int k = 0; k < 3; ++k) {
        if (slot.rotation[k] < 0) continue;
        const double half_angle = values[slot.rotation[k]] * k_half_degree_in_radians;
        Eigen::Quaterniond axis_rotation(std::cos(half_angle), 0.0, 0.0, 0.0);
        axis_rotation.vec()[slot.order.axes[k]] = std::sin(half_angle);
        rotation = rotation * axis_rotation;
    }
    return rotation;
}

Eigen::Vector3d translation_from_values(const double* values, const JointSlots& slot, const Eigen::Vector3d& offset) {
    Eigen::Vector3d translation = offset;
    for (int axis = 0; axis < 3; ++axis) {
        if (slot.position[axis] >= 0) translation[axis] = values[slot.position[axis]];
    }
    return translation;
}

struct FrameDecoder {
    const Skeleton& skeleton;
    std::vector<JointSlots> slots;
    bool animated_translations = false;
    int values_per_frame = 0;
    std::size_t frames = 0;
    std::string_view source;

    std::string where(const TextCursor& cursor) const {
        return std::string(source) + ":" + std::to_string(cursor.line()) + ": ";
    }
    Result<void> parse_range(TextCursor& cursor, std::size_t first_frame, std::size_t end_frame, Clip& clip) const;
    // All frames as one stream of values, whatever the line ends; `first_off_line` gets the line of the first
    // frame that does not start and end a line of its own (0 when all do).
    Result<void> parse_stream(TextCursor& cursor, Clip& clip, int& first_off_line) const;
    void store(const double* values, std::size_t frame, Clip& clip) const;
};

void FrameDecoder::store(const double* values, std::size_t frame, Clip& clip) const {
    const int joints = skeleton.joint_count();
    const std::size_t first = frame * joints;
    for (int joint = 0; joint < joints; ++joint) {
        clip.local_rotations[first + joint] = rotation_from_degrees(values, slots[joint]);
        if (animated_translations) clip.local_translations[first + joint] = translation_from_values(values, slots[joint], skeleton.rest_offsets[joint]);
    }
    clip.root_translations[frame] = translation_from_values(values, slots[0], skeleton.rest_offsets[0]);
}

Result<void> FrameDecoder::parse_stream(TextCursor& cursor, Clip& clip, int& first_off_line) const {
    std::vector<double> values(values_per_frame);
    first_off_line = 0;
    for (std::size_t frame = 0; frame < frames; ++frame) {
        // A frame on a line of its own starts after a line end (or the header's) and ends at one.
        const bool starts_line = cursor.at_line_end();
        for (int i = 0; i < values_per_frame; ++i) {
            cursor.skip_whitespace();
            if (cursor.at_end()) {
                return make_error(ErrorCode::parse, where(cursor) + "the file ends after " + std::to_string(frame) + " frames and " +
                                                        std::to_string(i) + " values, but 'Frames:' declares " + std::to_string(frames) +
                                                        " frames of " + std::to_string(values_per_frame) + " values");
            }
            if (i == 0 && first_off_line == 0 && !starts_line) first_off_line = cursor.line();
            if (!cursor.parse_number(values[i])) {
                return make_error(ErrorCode::parse, where(cursor) + "frame " + std::to_string(frame) + ", value " + std::to_string(i + 1) +
                                                        ": expected a finite number, found " + cursor.peek_for_message());
            }
        }
        cursor.skip_blanks();
        if (first_off_line == 0 && !cursor.at_line_end()) first_off_line = cursor.line();
        store(values.data(), frame, clip);
    }
    return {};
}

// Parses frames [first_frame, end_frame), one per non-blank line, into the clip's preallocated arrays.
Result<void> FrameDecoder::parse_range(TextCursor& cursor, std::size_t first_frame, std::size_t end_frame, Clip& clip) const {
    const int joints = skeleton.joint_count();
    std::vector<double> values(values_per_frame);
    for (std::size_t frame = first_frame; frame < end_frame; ++frame) {
        cursor.skip_whitespace();
        if (cursor.at_end()) {
            return make_error(ErrorCode::parse, where(cursor) + "the file ends after " + std::to_string(frame) +
                                                    " frames, but 'Frames:' declares " + std::to_string(frames));
        }
        for (int i = 0; i < values_per_frame; ++i) {
            if (cursor.parse_number(values[i])) continue;
            if (cursor.at_line_end()) {
                return make_error(ErrorCode::parse, where(cursor) + "frame " + std::to_string(frame) + " has " + std::to_string(i) +
                                                        " values, expected " + std::to_string(values_per_frame) + " (the channels of " +
                                                        std::to_string(joints) + " joints)");
            }
            return make_error(ErrorCode::parse, where(cursor) + "frame " + std::to_string(frame) + ", value " + std::to_string(i + 1) +
                                                    ": expected a finite number, found " + cursor.peek_for_message());
        }
        cursor.skip_blanks();
        if (!cursor.at_line_end()) {
            return make_error(ErrorCode::parse, where(cursor) + "frame " + std::to_string(frame) + " has more than " +
                                                    std::to_string(values_per_frame) + " values (the channels of " +
                                                    std::to_string(joints) + " joints), found " + cursor.peek_for_message());
        }

        store(values.data(), frame, clip);
    }
    return {};
}

// Where a second thread can start: the line start nearest the middle of the frame text, with the frame index
// and line number there. Frames are non-blank lines, so counting them needs one pass over line starts.
struct FrameSplit {
    std::size_t offset = 0;
    std::size_t frame = 0;
    int line = 0;
};

std::optional<FrameSplit> find_frame_split(const TextCursor& cursor, std::size_t frames) {
    const std::string_view text = cursor.text();
    const std::size_t middle = text.find('\n', cursor.offset() + cursor.remaining_bytes() / 2);
    if (middle == std::string_view::npos) return std::nullopt;
    FrameSplit split{middle + 1, 0, cursor.line()};
    for (std::size_t line_start = cursor.offset(); line_start < split.offset;) {
        const std::size_t line_end = text.find('\n', line_start);
        bool blank = true;
        for (std::size_t i = line_start; i < line_end && blank; ++i) blank = TextCursor::is_blank(text[i]);
        if (!blank) ++split.frame;
        ++split.line;
        line_start = line_end + 1;
    }
    if (split.frame == 0 || split.frame >= frames) return std::nullopt;
    return split;
}

// The values after the declared frames, up to the end of the text; an error at the first thing that is not one.
Result<std::size_t> count_trailing_values(TextCursor& cursor, const FrameDecoder& decoder, std::size_t frames) {
    std::size_t trailing = 0;
    double value = 0.0;
    for (cursor.skip_whitespace(); !cursor.at_end(); cursor.skip_whitespace()) {
        if (!cursor.parse_number(value)) {
            return make_error(ErrorCode::parse, decoder.where(cursor) + "more data after the " + std::to_string(frames) +
                                                    " frames that 'Frames:' declares, found " + cursor.peek_for_message());
        }
        ++trailing;
    }
    return trailing;
}

std::string trailing_message(std::size_t trailing, std::size_t per_frame, std::size_t frames) {
    const std::size_t whole = trailing / per_frame;
    return std::to_string(trailing) + " values (" + std::to_string(whole) + (whole == 1 ? " frame" : " frames") +
           (trailing % per_frame ? " and a part" : "") + ") after the " + std::to_string(frames) + " frames that 'Frames:' declares";
}

} // namespace

Result<void> bvh_parse_frames(TextCursor& cursor, std::string_view source, const RawBvh& raw, Clip& clip, int threads, bool strict,
                              std::vector<std::string>& warnings) {
    const Skeleton& skeleton = raw.skeleton;
    const int joints = skeleton.joint_count();
    FrameDecoder decoder{skeleton, joint_slots(raw.layout), false, raw.layout.channel_count(),
                         static_cast<std::size_t>(raw.frame_count), source};
    const std::size_t frames = decoder.frames;
    const int values_per_frame = decoder.values_per_frame;

    // Bound memory by the input: every value needs at least two bytes ("0" and a separator), so refuse frame
    // counts the remaining bytes cannot hold before allocating anything; joints without channels cost memory
    // but no bytes, so their product with the frames has a fixed cap.
    const std::size_t bytes = cursor.remaining_bytes();
    if (values_per_frame > 0 && frames * values_per_frame > bytes / 2 + 1) {
        return make_error(ErrorCode::parse, decoder.where(cursor) + "'Frames: " + std::to_string(frames) + "' needs " +
                                                std::to_string(frames * values_per_frame) + " values, more than the " +
                                                std::to_string(bytes) + " bytes that follow can hold; the file is truncated or the frame count is wrong");
    }
    if (frames * static_cast<std::size_t>(joints) > k_bvh_max_joint_frames) {
        return make_error(ErrorCode::limit, decoder.where(cursor) + std::to_string(frames) + " frames of " + std::to_string(joints) +
                                                " joints exceed the reader's limit of " + std::to_string(k_bvh_max_joint_frames) +
                                                " joint-frames; split the capture");
    }
    if (values_per_frame == 0 && frames > 0) {
        return make_error(ErrorCode::unsupported, decoder.where(cursor) + "the hierarchy has no channels, so frames cannot be read");
    }

    for (int joint = 1; joint < joints; ++joint) decoder.animated_translations |= decoder.slots[joint].has_position;
    clip.root_translations.resize(frames);
    clip.local_rotations.resize(frames * joints);
    if (decoder.animated_translations) clip.local_translations.resize(frames * joints);

    // Large captures are parsed in two halves at once; the halves write disjoint frames of the clip.
    const TextCursor frames_start = cursor;
    Result<void> by_line = {};
    std::optional<FrameSplit> split;
    if (threads >= 2 && bytes >= k_bvh_parallel_min_bytes) split = find_frame_split(cursor, frames);
    if (split) {
        TextCursor second_cursor = cursor.at(split->offset, split->line);
        Result<void> second_result;
        try {
            std::thread second([&] { second_result = decoder.parse_range(second_cursor, split->frame, frames, clip); });
            Result<void> first_result = decoder.parse_range(cursor, 0, split->frame, clip);
            second.join();
            // The earlier error in file order.
            by_line = !first_result ? first_result : second_result;
            if (by_line) cursor = second_cursor;
        } catch (const std::system_error&) {
            split.reset(); // no thread to be had: parse serially below
        }
    }
    if (!split) by_line = decoder.parse_range(cursor, 0, frames, clip);
    const std::size_t per_frame = std::size_t(std::max(1, values_per_frame));
    if (!by_line) {
        // Frames not one per line: read the values as one stream, as other readers do. It stands only when the
        // values then make whole frames (a channel count that does not match the data would leave a part
        // over); otherwise the line-by-line error says best what is wrong.
        if (strict) return by_line;
        auto also = [&](const std::string& stream_message) {
            std::string what = stream_message;
            if (what.starts_with(source)) what = what.substr(what.find(' ') + 1); // "file:line: " once is enough
            return make_error(by_line.error().code, by_line.error().message + "; read as one stream of values instead: " + what);
        };
        cursor = frames_start;
        int off_line = 0;
        if (Result<void> streamed = decoder.parse_stream(cursor, clip, off_line); !streamed) return also(streamed.error().message);
        const int trailing_line = (cursor.skip_whitespace(), cursor.line());
        Result<std::size_t> trailing = count_trailing_values(cursor, decoder, frames);
        if (!trailing) return also(trailing.error().message);
        if (*trailing % per_frame != 0) {
            return also(std::to_string(*trailing) + " values are left after " + std::to_string(frames) + " frames, not a whole frame");
        }
        warnings.push_back(std::string(source) + ":" + std::to_string(off_line > 0 ? off_line : frames_start.line()) +
                           ": frames are not one per line; the values are read as one stream, " + std::to_string(values_per_frame) +
                           " to a frame (" + std::to_string(frames) + " frames)");
        if (*trailing > 0) warnings.push_back(std::string(source) + ":" + std::to_string(trailing_line) + ": " + trailing_message(*trailing, per_frame, frames) + ": ignored");
        return {};
    }
    // Whole frames of values after the declared frames are ignored (with a warning); anything else is refused.
    cursor.skip_whitespace();
    const int trailing_line = cursor.line();
    const TextCursor after_frames = cursor;
    Result<std::size_t> trailing = count_trailing_values(cursor, decoder, frames);
    if (!trailing) return trailing.error();
    if (*trailing == 0) return {};
    if (*trailing % per_frame != 0 || strict) {
        TextCursor at = after_frames;
        return make_error(ErrorCode::parse, decoder.where(at) + "more data after the " + std::to_string(frames) + " frames that 'Frames:' declares, found " +
                                                at.peek_for_message() + " (" + trailing_message(*trailing, per_frame, frames) + ")" +
                                                (strict ? " (refused: strict)" : ""));
    }
    warnings.push_back(std::string(source) + ":" + std::to_string(trailing_line) + ": " + trailing_message(*trailing, per_frame, frames) + ": ignored");
    return {};
}

} // namespace kumite
