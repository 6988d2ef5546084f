#include "bvh_raw.h"

#include <cmath>

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

} // namespace

Result<void> bvh_parse_frames(TextCursor& cursor, std::string_view source, const RawBvh& raw, Clip& clip) {
    const Skeleton& skeleton = raw.skeleton;
    const int joints = skeleton.joint_count();
    const int values_per_frame = raw.layout.channel_count();
    const std::size_t frames = static_cast<std::size_t>(raw.frame_count);
    auto where = [&] { return std::string(source) + ":" + std::to_string(cursor.line()) + ": "; };

    // Bound memory by the input: every value needs at least two bytes, and the clip stores one rotation per joint
    // per frame, so refuse frame counts the remaining bytes cannot hold.
    const std::size_t bytes = cursor.remaining_bytes();
    if ((values_per_frame > 0 && frames * values_per_frame > bytes / 2 + 1) ||
        frames * static_cast<std::size_t>(joints) > bytes + 100000) {
        return make_error(ErrorCode::parse, where() + "'Frames: " + std::to_string(frames) + "' needs " +
                                                std::to_string(frames * values_per_frame) + " values but only " +
                                                std::to_string(bytes) + " bytes follow; the file is truncated or the frame count is wrong");
    }
    if (values_per_frame == 0 && frames > 0) {
        return make_error(ErrorCode::unsupported, where() + "the hierarchy has no channels, so frames cannot be read");
    }

    const std::vector<JointSlots> slots = joint_slots(raw.layout);
    bool animated_translations = false;
    for (int joint = 1; joint < joints; ++joint) animated_translations |= slots[joint].has_position;

    clip.root_translations.resize(frames);
    clip.local_rotations.resize(frames * joints);
    if (animated_translations) clip.local_translations.resize(frames * joints);

    std::vector<double> values(values_per_frame);
    for (std::size_t frame = 0; frame < frames; ++frame) {
        cursor.skip_whitespace();
        if (cursor.at_end()) {
            return make_error(ErrorCode::parse, where() + "the file ends after " + std::to_string(frame) +
                                                    " frames, but 'Frames:' declares " + std::to_string(frames));
        }
        for (int i = 0; i < values_per_frame; ++i) {
            if (cursor.parse_number(values[i])) continue;
            if (cursor.at_line_end()) {
                return make_error(ErrorCode::parse, where() + "frame " + std::to_string(frame) + " has " + std::to_string(i) +
                                                        " values, expected " + std::to_string(values_per_frame) + " (the channels of " +
                                                        std::to_string(joints) + " joints)");
            }
            return make_error(ErrorCode::parse, where() + "frame " + std::to_string(frame) + ", value " + std::to_string(i + 1) +
                                                    ": expected a finite number, found " + cursor.peek_for_message());
        }
        cursor.skip_blanks();
        if (!cursor.at_line_end()) {
            return make_error(ErrorCode::parse, where() + "frame " + std::to_string(frame) + " has more than " +
                                                    std::to_string(values_per_frame) + " values (the channels of " +
                                                    std::to_string(joints) + " joints), found " + cursor.peek_for_message());
        }

        const std::size_t first = frame * joints;
        for (int joint = 0; joint < joints; ++joint) {
            clip.local_rotations[first + joint] = rotation_from_degrees(values.data(), slots[joint]);
            if (animated_translations) {
                clip.local_translations[first + joint] =
                    translation_from_values(values.data(), slots[joint], skeleton.rest_offsets[joint]);
            }
        }
        clip.root_translations[frame] = translation_from_values(values.data(), slots[0], skeleton.rest_offsets[0]);
    }
    cursor.skip_whitespace();
    if (!cursor.at_end()) {
        return make_error(ErrorCode::parse, where() + "more data after the " + std::to_string(frames) +
                                                " frames that 'Frames:' declares, found " + cursor.peek_for_message());
    }
    return {};
}

} // namespace kumite
