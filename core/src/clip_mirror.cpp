#include "kumite/core/clip_mirror.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <string>

namespace kumite {

namespace {

Eigen::Matrix3d householder(const Eigen::Vector3d& normal) {
    const Eigen::Vector3d n = normal.normalized();
    return Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
}

std::string without_digits(const std::string& name) {
    std::string kept;
    for (char c : name) {
        if (c < '0' || c > '9') kept += c;
    }
    return kept;
}

// Offsets below `joint` paired with their partners' (children, then the first End Sites).
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> child_offset_pairs(const Skeleton& skeleton, const std::vector<int>& partner,
                                                                            int joint, const std::vector<bool>& animated) {
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs;
    auto is_animated = [&](int j) { return j < static_cast<int>(animated.size()) && animated[j]; };
    for (int child = joint + 1; child < skeleton.joint_count(); ++child) {
        if (skeleton.parents[child] != joint || is_animated(child) || is_animated(partner[child])) continue;
        pairs.emplace_back(skeleton.rest_offsets[child], skeleton.rest_offsets[partner[child]]);
    }
    const EndSite* own = nullptr;
    const EndSite* theirs = nullptr;
    for (const EndSite& end_site : skeleton.end_sites) {
        if (end_site.joint == joint && !own) own = &end_site;
        if (end_site.joint == partner[joint] && !theirs) theirs = &end_site;
    }
    if (own && theirs) pairs.emplace_back(own->offset_in_joint, theirs->offset_in_joint);
    return pairs;
}


// The reflection in `joint`'s rest frame that best maps its child offsets onto their partners', if one fits.
// Real bodies are not exactly symmetric: offsets pair up by direction; their lengths may differ. A candidate's
// misfit is its worst direction error (infinite when a short offset meets a long one). The best fit wins (a
// bone on the mirror plane fits several reflections loosely, the right one closely); exact ties go to the
// earlier candidate, the parent's reflection before the axes.
std::optional<Eigen::Matrix3d> best_reflection(const Skeleton& skeleton, const MirrorSymmetry& symmetry, int joint,
                                               const std::vector<bool>& skip_animated, double tolerance_m, double direction_tolerance) {
    const auto pairs = child_offset_pairs(skeleton, symmetry.partner, joint, skip_animated);
    auto misfit = [&](const Eigen::Matrix3d& candidate) {
        double worst = 0.0;
        for (const auto& [own, theirs] : pairs) {
            const bool own_short = own.norm() <= tolerance_m, theirs_short = theirs.norm() <= tolerance_m;
            if (own_short != theirs_short) return std::numeric_limits<double>::infinity();
            if (!own_short) worst = std::max(worst, (candidate * own.normalized() - theirs.normalized()).norm());
        }
        return worst;
    };
    std::vector<Eigen::Matrix3d> candidates;
    for (const auto& [own, theirs] : pairs) {
        if (own.norm() <= tolerance_m || theirs.norm() <= tolerance_m) continue;
        const Eigen::Vector3d normal = own.normalized() - theirs.normalized();
        if (normal.norm() > direction_tolerance) candidates.push_back(householder(normal)); // else the parent's may do
    }
    candidates.push_back(joint > 0 ? symmetry.local_reflections[skeleton.parents[joint]] : symmetry.reflection);
    for (int axis = 0; axis < 3; ++axis) candidates.push_back(householder(Eigen::Vector3d::Unit(axis)));
    std::optional<Eigen::Matrix3d> found;
    double best = direction_tolerance;
    for (const Eigen::Matrix3d& candidate : candidates) {
        const double error = misfit(candidate);
        if (error < best - 1e-12 || (!found && error <= best)) {
            best = error;
            found = candidate;
        }
    }
    return found;
}

} // namespace

Eigen::Quaterniond MirrorSymmetry::mirror_local_rotation(int joint, const Eigen::Quaterniond& partner_rotation, int parent) const {
    const Eigen::Matrix3d& before = parent >= 0 ? local_reflections[parent] : reflection;
    return Eigen::Quaterniond(Eigen::Matrix3d(before * partner_rotation.toRotationMatrix() * local_reflections[joint])).normalized();
}

Result<MirrorSymmetry> mirror_symmetry_find(const Skeleton& skeleton, double tolerance_m, double direction_tolerance,
                                            const std::vector<bool>& translation_animated) {
    const int joints = skeleton.joint_count();
    MirrorSymmetry symmetry;
    symmetry.partner.assign(joints, -1);
    std::vector<JointNameParts> names(joints);
    for (int joint = 0; joint < joints; ++joint) names[joint] = split_joint_name(skeleton.names[joint]);
    for (int joint = 0; joint < joints; ++joint) {
        if (names[joint].side == Side::none) {
            symmetry.partner[joint] = joint;
            continue;
        }
        const Side other = names[joint].side == Side::left ? Side::right : Side::left;
        for (int candidate = 0; candidate < joints; ++candidate) {
            if (names[candidate].side == other && names[candidate].base == names[joint].base) symmetry.partner[joint] = candidate;
        }
        if (symmetry.partner[joint] < 0) {
            // Exporters number one side's joints and not the other's (SNU's LeftShoulder1 beside RightShoulder): the
            // one joint of the other side whose name is the same without its digits.
            int found = -1, count = 0;
            for (int candidate = 0; candidate < joints; ++candidate) {
                if (names[candidate].side == other && without_digits(names[candidate].base) == without_digits(names[joint].base)) {
                    found = candidate;
                    ++count;
                }
            }
            if (count == 1) symmetry.partner[joint] = found;
        }
        if (symmetry.partner[joint] < 0) {
            return make_error(ErrorCode::invalid, "joint " + skeleton.names[joint] + " has no mirror partner");
        }
    }
    for (int joint = 1; joint < joints; ++joint) {
        if (symmetry.partner[skeleton.parents[joint]] != skeleton.parents[symmetry.partner[joint]]) {
            return make_error(ErrorCode::invalid, "joints " + skeleton.names[joint] + " and " + skeleton.names[symmetry.partner[joint]] +
                                                      " hang from parents that are not partners");
        }
    }

    symmetry.local_reflections.assign(joints, symmetry.reflection);
    for (int joint = 0; joint < joints; ++joint) {
        // First with every child offset; when they do not fit, without the offsets the motion replaces.
        std::optional<Eigen::Matrix3d> found = best_reflection(skeleton, symmetry, joint, {}, tolerance_m, direction_tolerance);
        if (!found && !translation_animated.empty()) {
            found = best_reflection(skeleton, symmetry, joint, translation_animated, tolerance_m, direction_tolerance);
        }
        if (!found) {
            return make_error(ErrorCode::invalid, "the joints below " + skeleton.names[joint] + " and " +
                                                      skeleton.names[symmetry.partner[joint]] + " are not mirror images");
        }
        symmetry.local_reflections[joint] = *found;
    }
    return symmetry;
}

Clip clip_mirror(const Clip& clip, const MirrorSymmetry& symmetry) {
    const Skeleton& skeleton = clip.skeleton;
    const int joints = skeleton.joint_count();
    Clip mirrored = clip;
    for (int frame = 0; frame < clip.frame_count(); ++frame) {
        const size_t first = static_cast<size_t>(frame) * joints;
        mirrored.root_translations[frame] = symmetry.reflection * clip.root_translations[frame];
        for (int joint = 0; joint < joints; ++joint) {
            const int partner = symmetry.partner[joint];
            const int parent = skeleton.parents[joint];
            mirrored.local_rotations[first + joint] = symmetry.mirror_local_rotation(joint, clip.local_rotations[first + partner], parent);
            if (clip.has_local_translations()) {
                const Eigen::Matrix3d& before = parent >= 0 ? symmetry.local_reflections[parent] : symmetry.reflection;
                mirrored.local_translations[first + joint] = before * clip.local_translations[first + partner];
            }
        }
    }
    return mirrored;
}

} // namespace kumite
