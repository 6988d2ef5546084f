#include "kumite/formats/bvh_writer.h"

#include "kumite/formats/atomic_file.h"

#include <cassert>
#include <charconv>
#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_radians_to_degrees = 180.0 / 3.14159265358979323846;

void append_number(std::string& out, double value) {
    if (std::abs(value) < 1e-12) value = 0.0; // no "-0" or "1e-17" noise in lengths and angles
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 10);
    assert(error == std::errc());
    out.append(buffer, end);
}

// Writes the HIERARCHY and returns the joints in the order it wrote them: the order the MOTION lines must follow.
// A skeleton's indices are parents-first, not necessarily depth-first (a glTF character's are by depth).
std::vector<int> write_hierarchy(std::string& out, const Skeleton& skeleton, const BvhLayout& layout, double to_unit) {
    // Children in index order, End Sites after a joint's children; depth-first with an explicit stack.
    std::vector<std::vector<int>> children(skeleton.joint_count());
    for (int joint = 1; joint < skeleton.joint_count(); ++joint) children[skeleton.parents[joint]].push_back(joint);
    std::vector<std::vector<const EndSite*>> end_sites(skeleton.joint_count());
    for (const EndSite& end_site : skeleton.end_sites) end_sites[end_site.joint].push_back(&end_site);

    auto write_offset = [&](const Eigen::Vector3d& offset, int depth) {
        out.append(std::min(depth, 33), '\t').append("OFFSET");
        for (int axis = 0; axis < 3; ++axis) {
            out += ' ';
            append_number(out, offset[axis] * to_unit);
        }
        out += '\n';
    };

    out += "HIERARCHY\n";
    std::vector<int> written;
    written.reserve(std::size_t(skeleton.joint_count()));
    struct Item { int joint; int depth; bool closing; };
    std::vector<Item> stack{{0, 0, false}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        // Indentation stops growing at 32 levels: a deep chain must not make the file quadratic in its depth.
        const std::string indent(std::min(item.depth, 32), '\t');
        if (item.closing) {
            for (const EndSite* end_site : end_sites[item.joint]) {
                out += indent + "\tEnd Site\n" + indent + "\t{\n";
                write_offset(end_site->offset_in_joint, item.depth + 2);
                out += indent + "\t}\n";
            }
            out += indent + "}\n";
            continue;
        }
        written.push_back(item.joint);
        out += indent + (item.joint == 0 ? "ROOT " : "JOINT ") + skeleton.names[item.joint] + "\n" + indent + "{\n";
        write_offset(skeleton.rest_offsets[item.joint], item.depth + 1);
        const BvhJointChannels& channels = layout.joints[item.joint];
        out += indent + "\tCHANNELS " + std::to_string(channels.count);
        for (int i = 0; i < channels.count; ++i) out += " " + std::string(bvh_channel_name(channels.channels[i]));
        out += '\n';
        stack.push_back({item.joint, item.depth, true});
        for (auto child = children[item.joint].rbegin(); child != children[item.joint].rend(); ++child) {
            stack.push_back({*child, item.depth + 1, false});
        }
    }
    return written;
}

} // namespace

BvhLayout bvh_default_layout(const Clip& clip, EulerOrder order) {
    BvhLayout layout;
    layout.joints.resize(clip.skeleton.joint_count());
    for (int joint = 0; joint < clip.skeleton.joint_count(); ++joint) {
        BvhJointChannels& channels = layout.joints[joint];
        if (joint == 0 || clip.has_local_translations()) {
            for (int axis = 0; axis < 3; ++axis) channels.channels[channels.count++] = static_cast<BvhChannel>(axis);
        }
        for (int axis : order.axes) channels.channels[channels.count++] = static_cast<BvhChannel>(3 + axis);
        channels.rotation_order = order;
    }
    return layout;
}

std::string bvh_write_string(const Clip& clip, const BvhLayout& layout, const LengthUnit& unit) {
    const Skeleton& skeleton = clip.skeleton;
    assert(static_cast<int>(layout.joints.size()) == skeleton.joint_count());
    const double to_unit = 1.0 / unit.metres;
    std::string out;
    out.reserve(static_cast<std::size_t>(clip.frame_count()) * layout.channel_count() * 11 + 4096);
    const std::vector<int> written = write_hierarchy(out, skeleton, layout, to_unit);

    out += "MOTION\nFrames: " + std::to_string(clip.frame_count()) + "\nFrame Time: ";
    char frame_time[32];
    const auto frame_time_end = std::to_chars(frame_time, frame_time + sizeof frame_time, clip.frame_time_s).ptr; // exact
    out.append(frame_time, frame_time_end);
    out += '\n';

    for (int frame = 0; frame < clip.frame_count(); ++frame) {
        const PoseView pose = clip.pose(frame);
        bool first_value = true;
        for (const int joint : written) {
            const BvhJointChannels& channels = layout.joints[joint];
            const Eigen::Vector3d translation = joint == 0 ? pose.root_translation
                                                : clip.has_local_translations() ? pose.local_translations[joint]
                                                                                : skeleton.rest_offsets[joint];
            const Eigen::Vector3d angles = channels.has_rotation()
                                               ? euler_from_quaternion(pose.local_rotations[joint], channels.rotation_order)
                                               : Eigen::Vector3d::Zero();
            for (int i = 0; i < channels.count; ++i) {
                if (!first_value) out += ' ';
                first_value = false;
                const int channel = static_cast<int>(channels.channels[i]);
                if (channel < 3) {
                    append_number(out, translation[channel] * to_unit);
                } else {
                    int k = 0;
                    while (channels.rotation_order.axes[k] != channel - 3) ++k;
                    append_number(out, angles[k] * k_radians_to_degrees);
                }
            }
        }
        out += '\n';
    }
    return out;
}

Result<void> bvh_write_file(const std::filesystem::path& path, const Clip& clip, const BvhLayout& layout,
                            const LengthUnit& unit) {
    return write_file_atomically(path, bvh_write_string(clip, layout, unit));
}

} // namespace kumite
