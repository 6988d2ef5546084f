#pragma once
// The user as the fighter sees them (fighter.h): the head this frame and its filtered course, the hands, and
// whether the tracker still has them. Owns: the last head, when it came, the head's motion filter, this frame's
// hands, the tracking flag. Touches: the event log (tracker_lost, tracker_back). Reads nothing of the other parts;
// they read it.

#include "fighter/event_log.h"

#include "kumite/core/heading_frame.h"
#include "kumite/runtime/head_motion_filter.h"
#include "kumite/runtime/simulated_hands.h"
#include "kumite/runtime/user_guard.h"

#include <Eigen/Core>

namespace kumite {

class TrackedUser {
public:
    TrackedUser(const HeadMotionSettings& head_motion, const UserGuardSettings& guard) : m_head_motion(head_motion), m_guard(guard) {}

    // The hands of this frame (none: no hands tracked).
    void take_hands(const UserHands* hands) { m_hands = hands ? *hands : UserHands{}; }
    // The head of this frame, or null when the tracker has none: the head is lost after `timeout_s` without one,
    // and back at the first one after that (both as events).
    enum class Change { none, lost, back };
    Change take_head(double t_s, const Eigen::Vector3d* head, double timeout_s, EventLog& log);

    bool tracking() const { return m_tracking; }
    const Eigen::Vector3d& head() const { return m_head; } // the last one seen
    const HeadMotionFilter& motion() const { return m_head_motion; }
    const UserHands& hands() const { return m_hands; }
    // The user's guard this frame (user_guard.h), facing the fighter whose pelvis is over `fighter_origin`: set
    // once the head and hands of the frame are in, read by the strike.
    void update_guard(const Eigen::Vector3d& fighter_origin);
    const UserGuard& guard() const { return m_guard; }
    // From `origin` to the head, on the floor (metres).
    double distance_from(const Eigen::Vector3d& origin) const;
    // `heading` turned towards the head (at most 90 degrees), when the user is tracked; else as it is.
    HeadingFrame facing(const HeadingFrame& heading) const;

private:
    bool m_have_head = false; // a head came once
    bool m_tracking = false;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero();
    double m_last_head_s = -1e9;
    double m_last_sample_s = -1e9; // when the head last changed (or held still 0.1 s): the motion filter's last sample
    HeadMotionFilter m_head_motion;
    UserHands m_hands;
    UserGuard m_guard;
};

} // namespace kumite
