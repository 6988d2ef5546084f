#include "fighter/motion_player.h"

#include "kumite/core/smoothstep.h"

#include <algorithm>
#include <cmath>

namespace kumite {

MotionPlayer::MotionPlayer(const MotionDatabaseView& db, int guard_clip) : m_db(db) {
    db_mir_frame_load(m_guard_frame, m_db.mir_frames[m_db.clips[guard_clip].first_pose]);
}

void MotionPlayer::start(int clip, double t_s, const MirFrame& from, const HeadingFrame& align_on, double leg_length, double step_scale,
                         bool guard_arms) {
    m_guard_arms = guard_arms;
    m_blend_from = from;
    m_blend_start_s = t_s;
    m_clip = clip;
    m_clip_start_s = t_s;
    m_clip_scale = step_scale;
    MirFrame& first = m_next_frame; // scratch
    db_mir_frame_load(first, m_db.mir_frames[m_db.clips[clip].first_pose]);
    m_clip_hip_start = first.hip_centre;
    m_foot_pinned = {false, false};
    m_foot_release_s = {-1e9, -1e9};
    m_clip_to_world = clip_alignment(m_db, clip, 0, leg_length, align_on);
}

bool MotionPlayer::over(double t_s) const {
    return t_s - m_clip_start_s >= (m_db.clips[m_clip].frame_count - 1) * double(m_db.meta.frame_time_s);
}

void MotionPlayer::play(double t_s, CharacterBody& body, double blend_s) {
    const DbClip& clip = m_db.clips[m_clip];
    const double index = std::min((t_s - m_clip_start_s) / m_db.meta.frame_time_s, double(clip.frame_count - 1));
    const int whole = static_cast<int>(index);
    const double leg = body.leg_length();
    MirFrame& mir = body.mir();
    db_mir_frame_load(m_clip_frame, m_db.mir_frames[clip.first_pose + whole]);
    if (index - whole > 1e-9) {
        db_mir_frame_load(m_next_frame, m_db.mir_frames[clip.first_pose + std::min<int>(whole + 1, clip.frame_count - 1)]);
        mir_frame_blend(mir, m_clip_frame, m_next_frame, index - whole);
        m_clip_frame = mir;
    }
    if (m_clip_scale < 0.999) { // a shortened step: the hips travel less, the feet stay locked while planted
        m_clip_frame.hip_centre.x() = m_clip_hip_start.x() + m_clip_scale * (m_clip_frame.hip_centre.x() - m_clip_hip_start.x());
        m_clip_frame.hip_centre.z() = m_clip_hip_start.z() + m_clip_scale * (m_clip_frame.hip_centre.z() - m_clip_hip_start.z());
    }
    if (m_guard_arms) mir_frame_take_arms(m_clip_frame, m_guard_frame);
    mir_frame_move_on_floor(m_clip_frame, m_clip_to_world, leg);
    const double blend = blend_s > 0.0 ? smoothstep((t_s - m_blend_start_s) / blend_s) : 1.0;
    if (blend < 1.0) {
        mir_frame_blend(mir, m_blend_from, m_clip_frame, blend);
    } else {
        mir = m_clip_frame;
    }
    body.decode(mir);
    if (m_clip_scale < 0.999) lock_feet(t_s, clip.first_pose + whole, body);
    else m_pins = {};
}

void MotionPlayer::lock_feet(double t_s, int pose, CharacterBody& body) {
    // A planted foot is pinned where it was when it landed; a foot that lifts carries the difference between its
    // pin and the shortened step's path and sheds it over 0.3 s, so nothing jumps.
    const RestAnatomy& anatomy = body.anatomy();
    const auto positions = body.current().decoder.model_positions();
    const std::uint32_t flags = m_db.poses[pose].flags;
    const bool planted[2] = {(flags & db_pose_left_foot_planted) != 0, (flags & db_pose_right_foot_planted) != 0};
    const int legs[2] = {int(Limb::leg_l), int(Limb::leg_r)};
    m_pins = {};
    for (int foot = 0; foot < 2; ++foot) {
        const Eigen::Vector3d free_position = positions[anatomy.limbs[legs[foot]].extremity];
        const double fade = 1.0 - smoothstep((t_s - m_foot_release_s[foot]) / 0.3);
        const Eigen::Vector3d shown = free_position + fade * m_foot_release_offset[foot];
        if (planted[foot] && !m_foot_pinned[foot]) {
            m_foot_pinned[foot] = true;
            m_foot_pin[foot] = shown;
        } else if (!planted[foot] && m_foot_pinned[foot]) {
            m_foot_pinned[foot] = false;
            m_foot_release_offset[foot] = m_foot_pin[foot] - free_position;
            m_foot_release_s[foot] = t_s;
        }
        if (m_foot_pinned[foot]) {
            m_pins.pinned[legs[foot]] = true;
            m_pins.extremity_world[legs[foot]] = m_foot_pin[foot];
        } else {
            m_pins.extremity_offset_world[legs[foot]] = (1.0 - smoothstep((t_s - m_foot_release_s[foot]) / 0.3)) * m_foot_release_offset[foot];
        }
    }
    body.decode(body.mir(), m_pins);
    body.encode(body.mir()); // the next blend starts from what is shown
}

} // namespace kumite
