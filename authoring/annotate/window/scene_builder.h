#pragma once
// Fills the viewport's Scene from the document's state at one frame: the capture's skeleton as capsules (each
// pickable by the joint its segment starts at, the hit segment highlighted), and for the strike on show (the
// selected clip, or a previewed suggestion) the hit joint's trajectory as dots (dimmer after the hit), the contact
// point as a sphere and the hit-path box as twelve edges. Everything is lowered by the capture's floor height so
// it stands on the grid.

#include "capture_library.h"
#include "clip_trajectory.h"
#include "scene.h"

#include <optional>

namespace kumite::annotate {

struct StrikeOnShow {
    BodyPart segment = BodyPart::hand_r;
    int first_frame = 0;
    int hit_frame = 0;
    int last_frame = 0;
    bool proposal = false; // a suggestion not accepted yet: drawn in other colours
    bool block = false;    // a block: its path is the forearm's contact point (contact_point.h), not a joint's

    bool operator==(const StrikeOnShow&) const = default;
};

// The strike's trajectory, recomputed only when the capture or the strike changes (not at every frame of
// playback: the start boxes cost hit_frame² point transforms).
class TrajectoryCache {
public:
    const Result<ClipTrajectory>& get(const LoadedCapture& capture, const StrikeOnShow& strike);

private:
    std::filesystem::path m_capture_path;
    std::optional<StrikeOnShow> m_strike;
    std::optional<Result<ClipTrajectory>> m_trajectory;
};

// Replaces the scene by the capture's skeleton at `frame`, and when given, the strike's trajectory (dots, contact
// sphere, box edges; a proposal in other colours).
void scene_build(view::Scene& scene, const LoadedCapture& capture, int frame, std::optional<BodyPart> highlight,
                 const ClipTrajectory* trajectory = nullptr, bool proposal = false);

// The body part a picked capsule id (a joint) belongs to: the joint's own part, else its nearest mapped ancestor's.
std::optional<BodyPart> scene_part_of_pick(const LoadedCapture& capture, int picked_joint);

} // namespace kumite::annotate
