#pragma once
// A recorded person as the user (`--tracker capture:FILE.bvh[:DISTANCE[:START_S]]`): any BVH kumite reads, its
// performer's head and both hands each frame, placed in the room in front of the fighter (which starts at the
// origin facing +Z):
//   - turned to face the fighter: the performer's mean facing (from the shoulders, over the whole capture) points
//     along -Z;
//   - their mean head position put DISTANCE metres (default 1.2) in front of the fighter, at x = 0;
//   - at their own size (the file's unit converted to metres), their floor on the room's floor;
//   - from START_S seconds into the capture (default 0), looping: at the end the capture starts again from its
//     first frame (the last frame is held one frame time, then the head jumps back to where it was at the start;
//     the loop count says how often it did).
// The head is the centre of the skull (halfway from the head joint to its End Site, or 10 cm above the head joint
// along the neck when it has none); each hand is the fist's centre (8 cm past the wrist along the forearm), where
// a tracked controller or glove would be. Positions between frames are interpolated. A capture whose root never
// moves (root_from_feet.h) gets the motion its feet imply.

#include "kumite/core/result.h"
#include "kumite/runtime/simulated_hands.h"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace kumite {

struct CapturePlacement {
    double distance_m = 1.2;
    double start_s = 0.0;
};

class CaptureUser {
public:
    // Reads the capture (errors name the file: unreadable, no frame rate, no head or hands in its body map).
    static Result<CaptureUser> read(const std::string& path, const CapturePlacement& placement);
    // `capture:FILE[:DISTANCE[:START_S]]` without the `capture:` prefix; a bad number is ErrorCode::invalid.
    static Result<CaptureUser> open(std::string_view spec);

    // The head at bout time t (seconds, non-decreasing), world metres; the hands of the same moment into `hands`.
    Eigen::Vector3d head(double t_s, UserHands& hands);

    const std::string& path() const { return m_path; }
    const CapturePlacement& placement() const { return m_placement; }
    double duration_s() const { return m_frame_time_s * static_cast<double>(m_heads.size() - 1); }
    double frame_time_s() const { return m_frame_time_s; }
    int frame_count() const { return static_cast<int>(m_heads.size()); }
    int loops() const { return m_loops; }           // how many times the capture started again so far
    double capture_time_s() const { return m_capture_s; } // where in the capture the last head() was
    double performer_height_m() const { return m_height_m; }
    // The performer's standing height and where their mean head is (world), for the events and the report.
    Eigen::Vector3d mean_head() const { return m_mean_head; }
    // One frame of the capture as placed (world metres): the head, the hands (fists' centres) and the elbows
    // [left, right] — the elbows for measuring what a tracker without them estimates.
    const Eigen::Vector3d& frame_head(int frame) const { return m_heads[std::size_t(frame)]; }
    const std::array<Eigen::Vector3d, 2>& frame_hands(int frame) const { return m_hands[std::size_t(frame)]; }
    const std::array<Eigen::Vector3d, 2>& frame_elbows(int frame) const { return m_elbows[std::size_t(frame)]; }

private:
    std::string m_path;
    CapturePlacement m_placement;
    double m_frame_time_s = 0.0;
    double m_height_m = 0.0;
    Eigen::Vector3d m_mean_head = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> m_heads;            // [frame] world, placed
    std::vector<std::array<Eigen::Vector3d, 2>> m_hands; // [frame][left, right] world, placed
    std::vector<std::array<Eigen::Vector3d, 2>> m_elbows; // [frame][left, right] world, placed
    int m_loops = 0;
    double m_capture_s = 0.0;
};

} // namespace kumite
