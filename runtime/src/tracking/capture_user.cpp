#include "kumite/runtime/capture_user.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/root_from_feet.h"
#include "kumite/formats/capture_file.h"
#include "kumite/runtime/user_guard.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kumite {
namespace {

constexpr double k_skull_above_head_joint_m = 0.10;

// The End Site hanging from `joint`, or -1.
int end_site_of(const Skeleton& skeleton, int joint) {
    for (int site = 0; site < static_cast<int>(skeleton.end_sites.size()); ++site) {
        if (skeleton.end_sites[site].joint == joint) return site;
    }
    return -1;
}

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    const std::size_t at = std::min(values.size() - 1, static_cast<std::size_t>(fraction * static_cast<double>(values.size())));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
    return values[at];
}

Result<double> number_field(std::string_view text, std::string_view what, std::string_view spec) {
    const std::string copy(text);
    char* end = nullptr;
    const double value = std::strtod(copy.c_str(), &end);
    if (copy.empty() || end != copy.c_str() + copy.size() || !std::isfinite(value)) {
        return make_error(ErrorCode::invalid, "--tracker capture:FILE.bvh[:DISTANCE[:START_S]]: " + std::string(what) + " must be a number, not '" +
                                                  copy + "' in '" + std::string(spec) + "'");
    }
    return value;
}

} // namespace

Result<CaptureUser> CaptureUser::open(std::string_view spec) {
    // FILE may hold ':' itself (a path); the numbers are the trailing fields that parse as numbers.
    std::string_view file = spec;
    CapturePlacement placement;
    std::vector<std::string_view> numbers;
    for (int field = 0; field < 2; ++field) {
        const std::size_t colon = file.rfind(':');
        if (colon == std::string_view::npos) break;
        const std::string_view tail = file.substr(colon + 1);
        if (tail.empty() || tail.find_first_not_of("0123456789.+-eE") != std::string_view::npos) break;
        numbers.insert(numbers.begin(), tail);
        file = file.substr(0, colon);
    }
    if (file.empty()) return make_error(ErrorCode::invalid, "--tracker capture:FILE.bvh[:DISTANCE[:START_S]]: no file given");
    if (!numbers.empty()) {
        Result<double> distance = number_field(numbers[0], "DISTANCE (metres)", spec);
        if (!distance) return distance.error();
        if (*distance < 0.3 || *distance > 10.0) {
            return make_error(ErrorCode::invalid, "--tracker capture: DISTANCE must be 0.3 to 10 metres, not " + std::string(numbers[0]));
        }
        placement.distance_m = *distance;
    }
    if (numbers.size() > 1) {
        Result<double> start = number_field(numbers[1], "START_S (seconds)", spec);
        if (!start) return start.error();
        if (*start < 0.0) return make_error(ErrorCode::invalid, "--tracker capture: START_S must be 0 or more seconds, not " + std::string(numbers[1]));
        placement.start_s = *start;
    }
    return read(std::string(file), placement);
}

Result<CaptureUser> CaptureUser::read(const std::string& path, const CapturePlacement& placement) {
    Result<BvhFile> file = capture_read_file(path);
    if (!file) return file.error();
    Clip& clip = file->clip;
    const BodyMap& map = file->body_map;
    if (!clip.has_frame_rate()) {
        return make_error(ErrorCode::invalid, path + ": the capture does not say its frame rate ('Frame Time' is 0 or missing); a tracked user "
                                                     "needs one: give a capture that states it (e.g. re-export it, or set its 'Frame Time:' line)");
    }
    if (clip.frame_count() < 2) return make_error(ErrorCode::invalid, path + ": a tracked user needs at least two frames");
    for (BodyPart part : {BodyPart::head, BodyPart::hand_l, BodyPart::hand_r, BodyPart::forearm_l, BodyPart::forearm_r, BodyPart::upper_arm_l, BodyPart::upper_arm_r}) {
        if (!map.has(part)) {
            return make_error(ErrorCode::invalid, path + ": no joint found for " + std::string(body_part_name(part)) +
                                                      " (a tracked user needs the head, both arms and hands); give a NAME.bodymap.json beside it");
        }
    }
    if (root_is_pinned(clip) && map.has(BodyPart::foot_l) && map.has(BodyPart::foot_r)) {
        root_motion_from_feet(clip, map.joint(BodyPart::foot_l), map.joint(BodyPart::foot_r));
    }
    const Skeleton& skeleton = clip.skeleton;
    const int head = map.joint(BodyPart::head);
    const int head_site = end_site_of(skeleton, head);
    const int neck = map.has(BodyPart::neck) ? map.joint(BodyPart::neck) : skeleton.parents[head];
    const int frames = clip.frame_count();

    std::vector<Eigen::Vector3d> positions(skeleton.joint_count()), sites(skeleton.end_sites.size());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    std::vector<Eigen::Vector3d> heads(frames);
    std::vector<std::array<Eigen::Vector3d, 2>> hands(frames), elbow_positions(frames);
    std::vector<double> lowest(frames);
    Eigen::Vector2d facing_sum = Eigen::Vector2d::Zero(); // (x, z)
    for (int frame = 0; frame < frames; ++frame) {
        forward_kinematics(positions, rotations, skeleton, clip.pose(frame));
        end_site_positions(sites, skeleton, positions, rotations);
        if (head_site >= 0) {
            heads[frame] = 0.5 * (positions[head] + sites[head_site]);
        } else {
            const Eigen::Vector3d up = neck >= 0 ? (positions[head] - positions[neck]).normalized() : Eigen::Vector3d::UnitY();
            heads[frame] = positions[head] + k_skull_above_head_joint_m * up;
        }
        const std::array<BodyPart, 2> wrists{BodyPart::hand_l, BodyPart::hand_r}, elbows{BodyPart::forearm_l, BodyPart::forearm_r};
        for (int side = 0; side < 2; ++side) {
            const Eigen::Vector3d wrist = positions[map.joint(wrists[side])], elbow = positions[map.joint(elbows[side])];
            const Eigen::Vector3d along = wrist - elbow;
            hands[frame][side] = along.norm() > 1e-9 ? Eigen::Vector3d(wrist + along.normalized() * k_fist_centre_past_wrist_m) : wrist;
            elbow_positions[frame][side] = elbow;
        }
        double low = positions[0].y();
        for (const Eigen::Vector3d& p : positions) low = std::min(low, p.y());
        for (const Eigen::Vector3d& p : sites) low = std::min(low, p.y());
        lowest[frame] = low;
        // Facing from the shoulders: forward = left x up.
        const Eigen::Vector3d left = positions[map.joint(BodyPart::upper_arm_l)] - positions[map.joint(BodyPart::upper_arm_r)];
        const Eigen::Vector3d forward = left.cross(Eigen::Vector3d::UnitY());
        const Eigen::Vector2d flat(forward.x(), forward.z());
        if (flat.norm() > 1e-9) facing_sum += flat.normalized();
    }
    if (!heads[0].allFinite() || facing_sum.norm() < 1e-9) {
        return make_error(ErrorCode::invalid, path + ": the performer has no mean facing (the shoulders turn all the way round, evenly)");
    }
    // Turn the mean facing onto -Z (towards the fighter), then put the mean head at (0, ., distance) and the floor
    // (the lowest point of most frames) at y = 0.
    const double facing_angle = std::atan2(facing_sum.x(), facing_sum.y()); // 0 when facing +Z
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(3.14159265358979323846 - facing_angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
    Eigen::Vector3d mean_head = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& h : heads) mean_head += turn * h;
    mean_head /= static_cast<double>(frames);
    const double floor_y = percentile(lowest, 0.02);
    const Eigen::Vector3d shift(-mean_head.x(), -floor_y, placement.distance_m - mean_head.z());

    CaptureUser user;
    user.m_path = path;
    user.m_placement = placement;
    user.m_frame_time_s = clip.frame_time_s;
    user.m_height_m = file->height_m;
    user.m_heads.resize(frames);
    user.m_hands.resize(frames);
    user.m_elbows.resize(frames);
    for (int frame = 0; frame < frames; ++frame) {
        user.m_heads[frame] = turn * heads[frame] + shift;
        for (int side = 0; side < 2; ++side) {
            user.m_hands[frame][side] = turn * hands[frame][side] + shift;
            user.m_elbows[frame][side] = turn * elbow_positions[frame][side] + shift;
        }
    }
    user.m_mean_head = mean_head + shift;
    return user;
}

Eigen::Vector3d CaptureUser::head(double t_s, UserHands& hands) {
    // One loop lasts the frames' count of frame times: the last frame is held for one frame time, then the first
    // comes back (no interpolation across the jump).
    const double period = m_frame_time_s * static_cast<double>(frame_count());
    const double at = placement().start_s + std::max(0.0, t_s);
    m_loops = static_cast<int>(std::floor(at / period)) - static_cast<int>(std::floor(placement().start_s / period));
    m_capture_s = at - period * std::floor(at / period);
    const double position = m_capture_s / m_frame_time_s;
    const int frame = std::clamp(static_cast<int>(std::floor(position)), 0, frame_count() - 1);
    const int next = std::min(frame + 1, frame_count() - 1);
    const double blend = std::clamp(position - frame, 0.0, 1.0);
    for (int side = 0; side < 2; ++side) {
        hands.present[side] = true;
        hands.world[side] = (1.0 - blend) * m_hands[frame][side] + blend * m_hands[next][side];
    }
    return (1.0 - blend) * m_heads[frame] + blend * m_heads[next];
}

} // namespace kumite
