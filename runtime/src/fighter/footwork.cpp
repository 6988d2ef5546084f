#include "fighter/footwork.h"

#include "fighter/strike_aim.h"

#include <algorithm>
#include <cmath>

namespace kumite {

Footwork::Footwork(const MotionDatabaseView& db, const FighterSettings& settings)
    : m_db(db), m_near_legs(settings.near_legs), m_close_near_legs(settings.close_near_legs), m_far_legs(settings.far_legs), m_landing_in_band(settings.landing_in_band),
      m_min_step_scale(settings.min_step_scale), m_keep_distance(settings.keep_distance), m_rest_near_legs(settings.rest_near_legs),
      m_rest_far_legs(settings.rest_far_legs), m_reach_fallback(settings.reach_fallback), m_lead_user(settings.steps_lead_user),
      m_lead_walk_mps(settings.lead_walk_mps) {
    m_guard_clip = db_first_clip_of(db, "rest");
    if (m_guard_clip < 0) m_guard_clip = 0; // a database without a guard: its first clip stands in
    const char* steps[] = {"step_forward", "step_back", "step_left", "step_right"};
    for (int i = 0; i < 4; ++i) m_step_clips[i] = db_first_clip_of(db, steps[i]);
}

double Footwork::stride_m(int clip, double leg_length) const {
    if (clip < 0) return 0.0;
    const DbClip& c = m_db.clips[clip];
    const DbMirFrame& first = m_db.mir_frames[c.first_pose];
    const DbMirFrame& last = m_db.mir_frames[c.first_pose + c.frame_count - 1];
    const double dx = last.hip_centre[0] - first.hip_centre[0], dz = last.hip_centre[2] - first.hip_centre[2];
    return std::hypot(dx, dz) * leg_length;
}

double Footwork::duration_s(int clip) const {
    return clip >= 0 ? (m_db.clips[clip].frame_count - 1) * double(m_db.meta.frame_time_s) : 0.0;
}

Footwork::UserRange Footwork::range_of(const CharacterBody& body, const TrackedUser& user) {
    Eigen::Vector3d to_user = user.head() - body.heading().origin;
    to_user.y() = 0.0;
    Eigen::Vector3d velocity = user.motion().velocity();
    velocity.y() = 0.0;
    const bool settled = user.motion().settled() && to_user.norm() > 1e-6;
    return {user.distance_from(body.heading().origin), settled ? velocity.dot(to_user.normalized()) : 0.0, settled ? velocity.norm() : 0.0};
}

double Footwork::distance_at_landing(int clip, const UserRange& user) const {
    const bool walking = m_lead_user && user.course_mps >= m_lead_walk_mps;
    return walking ? user.distance_m + user.receding_mps * duration_s(clip) : user.distance_m;
}

bool Footwork::out_of_band(const UserRange& user, const Band& band) const {
    return distance_at_landing(m_step_clips[0], user) > band.far_m || distance_at_landing(m_step_clips[1], user) < band.near_m;
}

Footwork::Band Footwork::reach_band(const CharacterBody& body, const TrackedUser& user) const {
    const double leg = body.leg_length();
    if (!user.tracking()) return {m_near_legs * leg, m_far_legs * leg, m_landing_in_band};
    const double reach = strike_reach_m(body, user.head(), m_reach_fallback);
    // Arms that reach the head from nowhere (a user much taller: strike_reach_m is 0) strike lower, from closer in.
    const double near = reach <= 0.0 ? std::min(m_near_legs * leg, close_near_m(leg)) : m_near_legs * leg;
    return {near, std::clamp(reach, near + k_min_band_legs * leg, m_far_legs * leg), m_landing_in_band};
}

double Footwork::near_m(const CharacterBody& body, const TrackedUser& user, bool short_strike) const {
    const double near = reach_band(body, user).near_m;
    return short_strike ? std::min(near, close_near_m(body.leg_length())) : near;
}

double Footwork::far_m(const CharacterBody& body, const TrackedUser& user) const { return reach_band(body, user).far_m; }

Footwork::Band Footwork::strike_band(const CharacterBody& body, const TrackedUser& user, double closer_than_m) const {
    // Land in the far part of the band: in reach, without crowding the user's face.
    const double leg = body.leg_length();
    Band band = reach_band(body, user);
    if (closer_than_m >= 0.0) band.near_m = std::min(band.near_m, close_near_m(leg));
    if (closer_than_m >= 0.0 && closer_than_m <= band.far_m) {
        band.far_m = std::max(band.near_m + k_min_band_legs * leg, closer_than_m - k_min_band_legs * leg);
    }
    return band;
}

Footwork::Band Footwork::rest_band(const CharacterBody& body, const TrackedUser& user) const {
    if (!m_keep_distance) return strike_band(body, user);
    const double leg = body.leg_length();
    const double near = std::max(m_rest_near_legs * leg, far_m(body, user));
    return {near, std::max(m_rest_far_legs * leg, near + k_min_band_legs * leg), 0.5};
}

Footwork::Next Footwork::next_clip(bool resting_with_user, const UserRange& user, const Band& band, double leg_length) const {
    Next next{m_guard_clip, 1.0, false};
    if (!resting_with_user) return next;
    const double near = band.near_m, far = band.far_m;
    const double middle = near + band.landing * (far - near);
    double distance = user.distance_m;
    if (const double ahead = distance_at_landing(m_step_clips[0], user); ahead > far && m_step_clips[0] >= 0) {
        next.clip = m_step_clips[0];
        distance = ahead;
    } else if (const double behind = distance_at_landing(m_step_clips[1], user); behind < near && m_step_clips[1] >= 0) {
        next.clip = m_step_clips[1];
        distance = behind;
    }
    if (next.clip != m_guard_clip) {
        const double stride = stride_m(next.clip, leg_length);
        if (stride > 1e-3) next.step_scale = std::clamp(std::abs(distance - middle) / stride, m_min_step_scale, 1.0);
        next.is_step = true;
    }
    return next;
}

} // namespace kumite
