#include "kumite/core/retarget_clip.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <array>
#include <chrono>

namespace kumite {
namespace {

constexpr double k_release_s = 0.1;

// The hip shift from which both legs come nearest to reaching their pins at their source extensions, staying near
// `mean_shift`: with `to_pin` the pins less the free decode's hips, the shift s that minimises
// sum_legs (|to_pin - s| - reach)^2 + k_shift_weight |s - mean_shift|^2 (Gauss-Newton from the mean shift). The
// weight keeps the hips where the mean puts them when the legs cannot both be suited, so the shift varies smoothly
// from frame to frame (an exact two-sphere solution jumps where the spheres stop meeting).
constexpr double k_shift_weight = 0.2; // 0.05 let the pelvis jerk on CMU 02 (root acceleration 15 -> 19 mm/frame^2)
Eigen::Vector3d hip_shift_for_both_legs(const std::array<Eigen::Vector3d, 2>& to_pin, const std::array<double, 2>& reach, const Eigen::Vector3d& mean_shift) {
    Eigen::Vector3d shift = mean_shift;
    for (int iteration = 0; iteration < 8; ++iteration) {
        Eigen::Matrix3d normal = k_shift_weight * Eigen::Matrix3d::Identity();
        Eigen::Vector3d gradient = k_shift_weight * (shift - mean_shift);
        for (int leg = 0; leg < 2; ++leg) {
            const Eigen::Vector3d from_hip = to_pin[leg] - shift;
            const double distance = from_hip.norm();
            if (distance < 1e-9) continue;
            const Eigen::Vector3d jacobian = -from_hip / distance; // d|to_pin - s| / ds
            normal += jacobian * jacobian.transpose();
            gradient += jacobian * (distance - reach[leg]);
        }
        const Eigen::Vector3d step = normal.ldlt().solve(-gradient);
        shift += step;
        if (step.norm() < 1e-7) break;
    }
    return shift;
}

double microseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
}

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    const size_t rank = std::min(values.size() - 1, static_cast<size_t>(q * (values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    return values[rank];
}

// [joint] true for the joints of both feet (ankle and below).
std::vector<bool> feet_joints(const Skeleton& skeleton, const BodyMap& map) {
    std::vector<bool> feet(skeleton.joint_count(), false);
    for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
        const int parent = skeleton.parents[joint];
        feet[joint] = joint == map.joint(BodyPart::foot_l) || joint == map.joint(BodyPart::foot_r) || (parent >= 0 && feet[parent]);
    }
    return feet;
}

// Which contact (index into `contacts`) holds `frame`, or the contact released less than `release_frames` ago
// (with how far into the release), or none.
struct ContactState {
    int contact = -1;
    double release = 0.0; // 0 planted, (0, 1) releasing
};
ContactState contact_state(const std::vector<ContactInterval>& contacts, int frame, int release_frames) {
    // A contact that holds the frame wins over the release of an earlier one.
    for (int i = 0; i < static_cast<int>(contacts.size()); ++i) {
        if (frame >= contacts[i].first_frame && frame <= contacts[i].last_frame) return {i, 0.0};
    }
    for (int i = static_cast<int>(contacts.size()) - 1; i >= 0; --i) {
        const int after = frame - contacts[i].last_frame;
        if (after > 0 && after <= release_frames) return {i, double(after) / (release_frames + 1)};
    }
    return {};
}

void measure_output(RetargetReport& report, const Clip& output, const RestAnatomy& target_anatomy,
                    const std::vector<std::vector<ContactInterval>>& contacts, const std::vector<std::array<double, k_limb_count>>& source_extension) {
    const Skeleton& skeleton = output.skeleton;
    const int joints = skeleton.joint_count();
    const std::vector<bool> feet = feet_joints(skeleton, target_anatomy.body_map);
    // The pelvis and the joints above it carry the root motion, not a bone.
    std::vector<bool> moved_by_root(joints, false);
    const int pelvis = target_anatomy.body_map.joint(BodyPart::pelvis);
    for (int joint = pelvis; joint >= 0; joint = skeleton.parents[joint]) moved_by_root[joint] = true;
    std::vector<Eigen::Vector3d> positions(joints), end_sites(skeleton.end_sites.size());
    std::vector<Eigen::Quaterniond> rotations(joints);
    std::vector<std::vector<Eigen::Vector3d>> ankles(2, std::vector<Eigen::Vector3d>(output.frame_count()));
    for (int frame = 0; frame < output.frame_count(); ++frame) {
        forward_kinematics(positions, rotations, skeleton, output.pose(frame));
        end_site_positions(end_sites, skeleton, positions, rotations);
        for (int joint = 1; joint < joints; ++joint) {
            const double length = (positions[joint] - positions[skeleton.parents[joint]]).norm();
            if (!moved_by_root[joint]) {
                report.bone_length_error_m = std::max(report.bone_length_error_m, std::abs(length - skeleton.rest_offsets[joint].norm()));
            }
            if (feet[joint]) report.floor_penetration_m = std::max(report.floor_penetration_m, -positions[joint].y());
        }
        for (size_t i = 0; i < end_sites.size(); ++i) {
            if (feet[skeleton.end_sites[i].joint]) report.floor_penetration_m = std::max(report.floor_penetration_m, -end_sites[i].y());
        }
        for (int limb = 0; limb < k_limb_count; ++limb) {
            const LimbChain& chain = target_anatomy.limbs[limb];
            const double extension = (positions[chain.extremity] - positions[chain.root]).norm() / chain.length();
            report.limb_extension_error = std::max(report.limb_extension_error, std::abs(extension - source_extension[frame][limb]));
        }
        ankles[0][frame] = positions[target_anatomy.limbs[2].extremity];
        ankles[1][frame] = positions[target_anatomy.limbs[3].extremity];
    }
    for (int foot = 0; foot < 2; ++foot) {
        for (const ContactInterval& contact : contacts[foot]) {
            for (int frame = contact.first_frame; frame <= contact.last_frame; ++frame) {
                Eigen::Vector3d slide = ankles[foot][frame] - ankles[foot][contact.first_frame];
                slide.y() = 0.0; // a heel rising is not skating
                report.foot_drift_m = std::max(report.foot_drift_m, slide.norm());
            }
        }
    }
}

} // namespace

Clip retarget_clip(RetargetReport& report, const Clip& source, const RestAnatomy& source_anatomy, const Skeleton& target,
                   const RestAnatomy& target_anatomy) {
    report = RetargetReport{};
    const int frames = source.frame_count();
    report.frames = frames;
    std::vector<double> frame_cost_us(frames, 0.0), foot_lock_us(frames, 0.0);

    // Encode, keeping what contact detection and the report need from the source.
    MirEncoder encoder(source.skeleton, source_anatomy);
    std::vector<MirFrame> encoded(frames);
    for (MirFrame& frame : encoded) frame.source_local_rotations.resize(source.skeleton.joint_count()); // not timed
    std::vector<std::vector<Eigen::Vector3d>> source_ankles(2, std::vector<Eigen::Vector3d>(frames));
    std::vector<std::array<double, k_limb_count>> source_extension(frames);
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        encoder.encode(encoded[frame], source.pose(frame));
        frame_cost_us[frame] += microseconds_since(start);
        const auto positions = encoder.model_positions();
        for (int limb = 0; limb < k_limb_count; ++limb) {
            const LimbChain& chain = source_anatomy.limbs[limb];
            source_extension[frame][limb] = (positions[chain.extremity] - positions[chain.root]).norm() / chain.length();
        }
        source_ankles[0][frame] = positions[source_anatomy.limbs[2].extremity];
        source_ankles[1][frame] = positions[source_anatomy.limbs[3].extremity];
    }
    std::vector<std::vector<ContactInterval>> contacts(2);
    for (int foot = 0; foot < 2; ++foot) {
        contacts[foot] = foot_contacts_detect(source_ankles[foot], source.frame_time_s, source_anatomy.leg_length,
                                              source_anatomy.floor_y + source_anatomy.ankle_height);
        report.contacts += static_cast<int>(contacts[foot].size());
    }

    // Decode; a planted foot is pinned where its contact began, then let go over k_release_s.
    Clip output;
    output.skeleton = target;
    output.frame_time_s = source.frame_time_s;
    output.root_translations.resize(frames);
    output.local_rotations.resize(static_cast<size_t>(frames) * target.joint_count());
    MirDecoder decoder(target, target_anatomy, source.skeleton.names);
    Pose pose;
    std::vector<std::vector<Eigen::Vector3d>> pinned_at(2);
    for (int foot = 0; foot < 2; ++foot) pinned_at[foot].resize(contacts[foot].size());
    const int release_frames = source.has_frame_rate() ? std::max(1, static_cast<int>(k_release_s / source.frame_time_s + 0.5)) : 1;
    const double length_ratio = target_anatomy.leg_length / source_anatomy.leg_length;
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        decoder.decode(pose, encoded[frame]);
        frame_cost_us[frame] += microseconds_since(start);
        const auto lock_start = std::chrono::steady_clock::now();
        LimbPins pins;
        for (int foot = 0; foot < 2; ++foot) {
            const int limb = 2 + foot;
            const Eigen::Vector3d free_ankle = decoder.model_positions()[target_anatomy.limbs[limb].extremity];
            const ContactState state = contact_state(contacts[foot], frame, release_frames);
            if (state.contact < 0) continue;
            const int first = contacts[foot][state.contact].first_frame;
            if (frame == first) pinned_at[foot][state.contact] = free_ankle;
            // The pinned ankle follows what the source ankle did since the contact began, scaled: a planted
            // source foot stays put, and the target foot no longer slides with the hips' different geometry.
            const Eigen::Vector3d pin = pinned_at[foot][state.contact] +
                                        (source_ankles[foot][frame] - source_ankles[foot][first]) * length_ratio;
            pins.pinned[limb] = true;
            pins.extremity_world[limb] = pin + state.release * (free_ankle - pin);
        }
        if (pins.pinned[2] || pins.pinned[3]) {
            // Move the hips by the mean of the pinned feet's offsets from where the free decode put them, so the
            // legs reach their pins with (nearly) the source's extension instead of bending or stretching.
            int count = 0;
            for (int limb = 2; limb < 4; ++limb) {
                if (!pins.pinned[limb]) continue;
                pins.hip_shift_world += pins.extremity_world[limb] - decoder.model_positions()[target_anatomy.limbs[limb].extremity];
                ++count;
            }
            pins.hip_shift_world /= count;
            // With both feet down the mean shift leaves each leg half the other's difference: the shift near it
            // from which both come nearest to their source's extension (the limbs stay true as the feet
            // stay planted).
            if (count == 2) {
                std::array<Eigen::Vector3d, 2> to_pin;
                std::array<double, 2> reach{};
                for (int foot = 0; foot < 2; ++foot) {
                    const LimbChain& leg = target_anatomy.limbs[2 + foot];
                    to_pin[foot] = pins.extremity_world[2 + foot] - decoder.model_positions()[leg.root];
                    reach[foot] = std::min(source_extension[frame][2 + foot], 0.999) * leg.length();
                }
                pins.hip_shift_world = hip_shift_for_both_legs(to_pin, reach, pins.hip_shift_world);
            }
            // A pin moves only when its leg could not reach it from the shifted hip (it is drawn in to the leg's
            // reach).
            for (int limb = 2; limb < 4 && count == 2; ++limb) {
                const LimbChain& leg = target_anatomy.limbs[limb];
                const Eigen::Vector3d hip = decoder.model_positions()[leg.root] + pins.hip_shift_world;
                const Eigen::Vector3d reach = pins.extremity_world[limb] - hip;
                const double longest = 0.999 * leg.length();
                if (reach.norm() > longest) pins.extremity_world[limb] = hip + reach * (longest / reach.norm());
            }
            decoder.decode(pose, encoded[frame], pins);
        }
        foot_lock_us[frame] = microseconds_since(lock_start);

        output.root_translations[frame] = pose.root_translation;
        std::copy(pose.local_rotations.begin(), pose.local_rotations.end(),
                  output.local_rotations.begin() + static_cast<size_t>(frame) * target.joint_count());
        if (!pose.local_translations.empty()) {
            output.local_translations.resize(output.local_rotations.size());
            std::copy(pose.local_translations.begin(), pose.local_translations.end(),
                      output.local_translations.begin() + static_cast<size_t>(frame) * target.joint_count());
        }
    }
    report.encode_decode_us_median = percentile(frame_cost_us, 0.5);
    report.encode_decode_us_p99 = percentile(frame_cost_us, 0.99);
    report.foot_lock_us_median = percentile(foot_lock_us, 0.5);
    report.foot_lock_us_p99 = percentile(foot_lock_us, 0.99);
    measure_output(report, output, target_anatomy, contacts, source_extension);
    return output;
}

} // namespace kumite
