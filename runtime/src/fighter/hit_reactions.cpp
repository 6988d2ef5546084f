#include "fighter/hit_reactions.h"

#include "kumite/core/hit_trajectory.h"
#include "kumite/core/mir.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace kumite {
namespace {

constexpr double k_course_window_s = 0.8; // the reaction's first movement: the largest displacement comes within this
constexpr double k_variety_margin = 0.15; // a clip fitting this much less than the last one chosen is taken instead

} // namespace

HitReactions::HitReactions(const MotionDatabaseView& db, const CharacterRig& measured_on) {
    const Skeleton& skeleton = measured_on.skeleton();
    const RestAnatomy& anatomy = measured_on.anatomy();
    const int head = anatomy.body_map.joint(BodyPart::head), pelvis = anatomy.body_map.joint(BodyPart::pelvis);
    if (head < 0 || pelvis < 0) return;
    MirDecoder decoder(skeleton, anatomy, {});
    Pose pose;
    MirFrame frame;
    const int window = std::max(2, int(std::lround(k_course_window_s / db.meta.frame_time_s)));
    for (int c = 0; c < int(db.clips.size()); ++c) {
        const DbClip& record = db.clips[c];
        if (db.string(record.semantics) != std::string_view("hit_reaction") || record.frame_count < 2) continue;
        Eigen::Vector3d start = Eigen::Vector3d::Zero(), largest = Eigen::Vector3d::Zero();
        HeadingFrame heading;
        for (int f = 0; f < std::min<int>(window, int(record.frame_count)); ++f) {
            db_mir_frame_load(frame, db.mir_frames[record.first_pose + f]);
            decoder.decode(pose, frame);
            const auto positions = decoder.model_positions();
            if (f == 0) heading = pose_heading(skeleton, anatomy, positions, decoder.model_rotations());
            // The head relative to the hips, in the heading's axes at the impact.
            const Eigen::Vector3d head_on_hips = heading.direction_to_heading(positions[head] - positions[pelvis]);
            if (f == 0) start = head_on_hips;
            if ((head_on_hips - start).norm() > largest.norm()) largest = head_on_hips - start;
        }
        if (largest.norm() < 1e-3) continue; // a clip whose head does not move answers nothing
        m_clips.push_back({c, largest.normalized(), largest.norm() / anatomy.leg_length});
    }
}

Eigen::Vector3d HitReactions::wanted_course(const Eigen::Vector3d& push_in_heading, bool at_head) {
    Eigen::Vector3d course(push_in_heading.x(), 0.0, push_in_heading.z());
    if (course.norm() < 1e-6) course = Eigen::Vector3d(0.0, 0.0, -1.0); // a blow with no direction: straight back
    course.normalize();
    // Folding over a blow to the body: the head forward and down, a little to the side the blow pushes.
    if (!at_head) return Eigen::Vector3d(0.5 * course.x(), -0.6, 0.8).normalized();
    course.y() = -0.25; // a blow to the head also lowers it a little
    return course.normalized();
}

HitReactions::Choice HitReactions::choose(const Eigen::Vector3d& push_in_heading, bool at_head) {
    const Eigen::Vector3d wanted = wanted_course(push_in_heading, at_head);
    // The best fit, unless it was played lately and one that was not fits nearly as well.
    auto recent = [&](int clip) { return std::find(m_recent.begin(), m_recent.end(), clip) != m_recent.end(); };
    Choice best, fresh;
    for (const Clip& clip : m_clips) {
        const double fit = clip.head_course.dot(wanted);
        if (best.clip < 0 || fit > best.fit) best = {clip.clip, fit};
        if (!recent(clip.clip) && (fresh.clip < 0 || fit > fresh.fit)) fresh = {clip.clip, fit};
    }
    if (recent(best.clip) && fresh.clip >= 0 && fresh.fit > best.fit - k_variety_margin) best = fresh;
    if (best.clip >= 0) {
        std::rotate(m_recent.rbegin(), m_recent.rbegin() + 1, m_recent.rend());
        m_recent[0] = best.clip;
    }
    return best;
}

} // namespace kumite
