#pragma once
// Captured blocks for the defence (defence.h): the database's `block` clips (age-uke, gedan-barai, ...), chosen
// for a user's strike and played on the fighter's blocking arm over whatever the rest of the body is doing.
//
// Choice. A candidate is a meeting frame of a block clip of the blocking arm's side (and of the wanted kind when
// the database holds one: rising against the head; either below it) and a start frame before it whose lead fits
// in the time the fist leaves (played at most at the captured speed, at least at 0.4 of it). The meeting frame is
// any frame of the clip's last sweep, from a third of the way in to its annotated hit: a block meets the fist where
// its sweep crosses the course (a gedan-barai's sweep crosses the chest on its way down, an age-uke's the face on
// its way up), and holds there. A meeting whose contact is further than `max_contact_error` arm lengths from
// where the forearm must meet the course is not a candidate (the forearm would have to be carried there: another
// movement). The score is
//     d = |wrist at the start - wrist now| / arm + 3 |contact at the meeting - where the forearm meets the course| / arm
// over the query's course points (where on the course the forearm meets it is part of the choice: a fist is met where
// the clip's forearm passes, from just outside the hit radius to 15 cm further out; each point has its time).
// The contact's distance counts three times: the wrist's start is blended in over the whole time the fist leaves,
// the contact's offset has to carry the forearm onto the fist's course, the larger move. Weighted equally, 31% of
// the blocks against recorded boxers fell back to synthesized ones (the best-scored clip's contact too far);
// weighted 2, 3 or 4 times, 15-17%, with the punches defended within 2 of each other (docs/design.md, "Blocks").
// Both clip points are placed on the fighter's arm as it is now: the clip's arm as captured relative to its
// shoulder, turned from the clip's heading to the fighter's and scaled by arm length (MIR, mir.h), the elbow by
// two-bone IK with the clip's swivel; the contact is a third of the way from the wrist to the elbow
// (contact_point.h). Headings, not the trunk's part frames, carry the arm over: they mean the same on every
// skeleton, where a clavicle's frame may be rolled differently on another. The clips' points are placed once, at
// construction, on an arm of unit length (upper and lower arm alike): a choice compares vectors, nothing else.
//
// Playback. The arm's extremity, swivel and the upper arm's, forearm's and hand's frames are the clip's at the
// played frame, turned onto the fighter's heading, blended over the shown pose by the defence's weight; the wrist is
// offset so that the contact meets the course at the hit frame (the offset grows with the clip's progress, like a
// strike's d(t)). Nothing here allocates after construction.

#include "kumite/core/mir.h"
#include "kumite/core/motion_database.h"

#include <array>
#include <vector>

namespace kumite {

// A point of the fist's course where a forearm may meet it, and when the fist gets there.
struct CoursePoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero(); // world
    double time_s = 0.2;                              // from now
    double before_m = 0.0;                            // how far before the target, along the course
};

struct BlockClipQuery {
    int limb = 0;                          // Limb::arm_l or Limb::arm_r: the blocking arm
    StrikeKind kind = StrikeKind::none;    // wanted (rising, downward); none or absent from the database: any
    // Where the forearm may meet the course (its first `course_count`): the choice takes the one its clip's forearm
    // passes nearest, so that the arm is carried least.
    std::array<CoursePoint, 4> course{};
    int course_count = 1;
    double max_contact_error = 0.5;        // arm lengths: meetings whose contact is further from the course point are not candidates
    double heading_yaw_rad = 0.0;          // the fighter's heading (heading_frame.h)
    Eigen::Vector3d shoulder = Eigen::Vector3d::Zero(), wrist = Eigen::Vector3d::Zero(); // world, now
    double upper_length = 0.3, lower_length = 0.3;
};

struct BlockClipChoice {
    int clip = -1;
    int start_frame = 0;
    int meet_frame = 0;       // where the forearm meets the course (a frame of the clip's last sweep), held after
    double rate = 1.0;        // clip seconds per second (<= 1: never faster than captured)
    double score = 0.0;
    int course_point = 0;     // the query's course point met
    double contact_error_m = 0.0;   // the clip's contact at the meeting frame, on the fighter, to the target (before the offset)
    double clip_arm_from_shoulder_mps = 0.0; // the fastest the clip moves the wrist or elbow relative to the shoulder, as played
};

class BlockClips {
public:
    explicit BlockClips(const MotionDatabaseView& database);
    bool empty() const { return m_clips.empty(); }
    int count() const { return static_cast<int>(m_clips.size()); }

    bool choose(const BlockClipQuery& query, const RestAnatomy& anatomy, BlockClipChoice& choice) const;

    // The clip's arm at (fractional) clip frame `frame` written into `out` (a copy of the shown frame, whose
    // shoulder is at `shoulder` and heading `heading_yaw_rad`), blended by `weight`.
    void apply(MirFrame& out, const RestAnatomy& anatomy, int limb, int clip, double frame, double weight, const Eigen::Vector3d& shoulder,
               double heading_yaw_rad) const;

    // The clip's wrist, elbow and contact point at `frame`, placed on the fighter's shoulder and heading (world),
    // with the wrist moved by `wrist_offset`.
    struct ArmPoints {
        Eigen::Vector3d wrist, elbow, contact;
    };
    ArmPoints arm_points(const RestAnatomy& anatomy, int limb, int clip, double frame, const Eigen::Vector3d& shoulder, double heading_yaw_rad,
                         const Eigen::Vector3d& wrist_offset) const;

    double frame_time_s() const { return m_frame_time_s; }

private:
    struct ArmFrame {
        Eigen::Vector3d extremity = Eigen::Vector3d::Zero(); // in the parent part's frame / arm length
        double swivel = 0.0;
        std::array<Eigen::Quaterniond, 4> parts;             // parent part, upper arm, forearm, hand (world, clip)
        Eigen::Quaterniond chest = Eigen::Quaterniond::Identity();
        double yaw_rad = 0.0;                                // the clip pose's heading
    };
    ArmFrame arm_frame(int clip, double frame, int limb, int parent_part) const;

    // A block clip's arm placed once on a unit arm at the origin, in the clip's heading frame, every frame, for
    // either parent part of the extremity (0: the clavicle, 1: the chest: skeletons without clavicles).
    struct Placed {
        Eigen::Vector3f wrist, contact;
    };
    struct Clip {
        int index = 0;         // in the database
        int first_placed = 0;  // into m_placed: frame f, parent k at first_placed + 2 * f + k
        int meet_from = 0;     // the first frame a meeting may be at (a third into the last sweep)
        std::array<double, 2> arm_speed_per_m{}; // the clip's fastest wrist or elbow move per second, per metre of arm
    };
    const Placed& placed(const Clip& clip, int frame, int parent) const { return m_placed[clip.first_placed + 2 * frame + parent]; }

    const MotionDatabaseView& m_db;
    std::vector<Clip> m_clips;
    std::vector<Placed> m_placed;
    double m_frame_time_s = 1.0 / 30.0;
};

} // namespace kumite
