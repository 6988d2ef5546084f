#pragma once
// A character as the runtime drives it from a motion database: its skeleton and anatomy, its sizes, a MIR
// decoder for database frames, and the model transforms of its last pose. Everything is sized at construction;
// decode() and measure() do not allocate.

#include "kumite/core/motion_database.h"
#include "kumite/core/pose_distance.h"
#include "kumite/core/retrieval.h"

namespace kumite {

class CharacterRig {
public:
    // Both must outlive the rig.
    CharacterRig(const Skeleton& skeleton, const RestAnatomy& anatomy);
    CharacterRig(const CharacterRig&) = delete;
    CharacterRig& operator=(const CharacterRig&) = delete;

    const Skeleton& skeleton() const { return m_skeleton; }
    const RestAnatomy& anatomy() const { return m_anatomy; }
    CharacterSize size() const;

    // Database pose `pose_index` decoded onto the character, then moved by `clip_to_world` (see RetrievalResult).
    void decode(Pose& out, const MotionDatabaseView& database, std::uint32_t pose_index, const FloorAlignment& clip_to_world = {});

    // The character standing at the world origin facing +Z: in the first frame of the database's first `rest`
    // clip (the guard), or in the skeleton's rest pose when the database has none. Leaves it measured.
    void stand_at_origin(Pose& out, const MotionDatabaseView& database);

    // Forward kinematics of `pose`; the results stay in positions()/rotations() until the next call.
    void measure(const PoseView& pose);
    std::span<const Eigen::Vector3d> positions() const { return m_positions; }
    std::span<const Eigen::Quaterniond> rotations() const { return m_rotations; }
    HeadingFrame heading() const; // of the measured pose
    // The measured pose's feature points (k_feature_point_count), world.
    void feature_points(std::span<Eigen::Vector3d> out) const;
    // The feature of the measured pose held still over the whole window (a character standing in a pose).
    void still_feature(std::span<float> out) const;

private:
    const Skeleton& m_skeleton;
    const RestAnatomy& m_anatomy;
    MirDecoder m_decoder;
    MirFrame m_frame;
    std::vector<Eigen::Vector3d> m_positions;
    std::vector<Eigen::Quaterniond> m_rotations;
};

// Applies a floor motion (rotation about Y, then translation) to a whole pose: root translation and rotation.
void pose_move_on_floor(Pose& pose, const FloorAlignment& motion);

} // namespace kumite
