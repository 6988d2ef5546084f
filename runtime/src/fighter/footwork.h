#pragma once
// Where the fighter stands (fighter.h): two distance bands to the user, pelvis to head on the floor — where its
// strikes reach (the strike band: it steps in there for an order) and the fighting distance it keeps between
// strikes (the rest band: just out of its reach, where its strikes and the user's need a step to land) — and between
// strikes the next clip: the guard, or a step (forward or back, shortened to land in the band). Owns: the database's
// guard and step clips, the bands' settings. Reads: the body (its reach, its leg length) and the user (the head),
// given. Footwork that follows or circles a user goes here.

#include "fighter/character_body.h"
#include "fighter/tracked_user.h"

#include "kumite/runtime/fighter_settings.h"

#include <array>

namespace kumite {

class Footwork {
public:
    Footwork(const MotionDatabaseView& db, const FighterSettings& settings);

    int guard_clip() const { return m_guard_clip; }
    int step_forward_clip() const { return m_step_clips[0]; }
    int step_back_clip() const { return m_step_clips[1]; }
    // How far a clip moves the hips, on a character of `leg_length`, and how long it plays.
    double stride_m(int clip, double leg_length) const;
    double duration_s(int clip) const;

    // The band where strikes reach: from near_legs leg lengths to the arms' reach (strike_aim.h), at most far_legs;
    // a quarter leg wide at least, so a shortened step lands inside it. Without a tracked user, the settings' band.
    // The near end: near_legs, or close_near_m when the arms reach the user's head from nowhere (a chibi before an
    // adult: its strikes go lower, from closer in) or for a `short_strike` (one that reached from nowhere in the band).
    double near_m(const CharacterBody& body, const TrackedUser& user, bool short_strike = false) const;
    // The near end for a strike that does not reach from the band (a short one: an elbow, a knee).
    double close_near_m(double leg_length) const { return m_close_near_legs * leg_length; }
    double far_m(const CharacterBody& body, const TrackedUser& user) const;

    // A band and where in it a step lands (0 near, 1 far).
    struct Band {
        double near_m = 0.0, far_m = 0.0, landing = 0.5;
    };
    // With `closer_than_m` >= 0 (the user's distance, when no strike reached from in the band), its near end is
    // close_near_m and its far end comes a band's least width nearer than that, down to the least width from the near
    // end: a step at a time closer.
    Band strike_band(const CharacterBody& body, const TrackedUser& user, double closer_than_m = -1.0) const;
    // The least width of a band (leg lengths): a shortened step lands inside it.
    static constexpr double k_min_band_legs = 0.25;
    // The fighting distance between strikes: from rest_near_legs, and at least the strike band's far end, to
    // rest_far_legs (a quarter leg wide at least); landing in its middle. With keep_distance off, the strike band.
    Band rest_band(const CharacterBody& body, const TrackedUser& user) const;

    // The user's head from the fighter on the floor: `distance_m` now, and how fast it moves away (`receding_mps`,
    // its horizontal velocity along the line between them; negative: coming closer).
    struct UserRange {
        double distance_m = 0.0;
        double receding_mps = 0.0;
        double course_mps = 0.0; // the head's horizontal speed on a settled course (0: not settled)
    };
    // The user's range from the body; receding only on a settled course (a boxer's bob back and forth, the drift of a
    // guard, are not followed ahead).
    static UserRange range_of(const CharacterBody& body, const TrackedUser& user);
    // Where the user will be when a step of `clip` lands (with steps_lead_user, for a user on a settled course at
    // lead_walk_mps or more), else where the user is.
    double distance_at_landing(int clip, const UserRange& user) const;
    // Whether a step forward or back is due: the user will be beyond the band's far end when a step forward lands,
    // or inside its near end when a step back does.
    bool out_of_band(const UserRange& user, const Band& band) const;
    // The clip after the one that ended (or when the fighter rests out of the band): a step into `band`, shortened
    // to land where the band says for where the user will be then, when the fighter rests with a user tracked out
    // of the band; else the guard.
    struct Next {
        int clip = -1;
        double step_scale = 1.0;
        bool is_step = false; // a step (the fighter approaches), not the guard
    };
    Next next_clip(bool resting_with_user, const UserRange& user, const Band& band, double leg_length) const;

private:
    // Both ends of the strike band from one look at the arms' reach (strike_reach_m); the settings' without a user.
    Band reach_band(const CharacterBody& body, const TrackedUser& user) const;

    const MotionDatabaseView& m_db;
    int m_guard_clip = -1;
    std::array<int, 4> m_step_clips{-1, -1, -1, -1}; // forward, back, left, right
    double m_near_legs, m_close_near_legs, m_far_legs, m_landing_in_band, m_min_step_scale;
    bool m_keep_distance;
    double m_rest_near_legs, m_rest_far_legs;
    bool m_reach_fallback;
    bool m_lead_user; // steps sized for where the user will be when they land
    double m_lead_walk_mps; // ... for a user on a settled course at this speed or more
};

} // namespace kumite
