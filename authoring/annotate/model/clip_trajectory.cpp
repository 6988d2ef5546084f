#include "clip_trajectory.h"

namespace kumite::annotate {

Result<ClipTrajectory> clip_trajectory_compute(const LoadedCapture& capture, std::string_view semantics, BodyPart segment,
                                               int first_frame, int hit_frame, int last_frame) {
    if (!capture.anatomy) return make_error(ErrorCode::invalid, capture.anatomy_error);
    const ContactPoint contact = contact_point_of(semantics, segment, capture.file.body_map);
    if (!contact.valid()) {
        return make_error(ErrorCode::invalid, capture.source + ": no joint plays " + std::string(body_part_name(segment)));
    }
    const int frame_count = capture.file.clip.frame_count();
    if (first_frame < 0 || first_frame > hit_frame || hit_frame > last_frame || last_frame >= frame_count) {
        return make_error(ErrorCode::invalid, capture.source + ": frames " + std::to_string(first_frame) + " <= hit " +
                                                  std::to_string(hit_frame) + " <= " + std::to_string(last_frame) + " < " +
                                                  std::to_string(frame_count) + " do not hold");
    }
    const HitTrajectory trajectory =
        hit_trajectory_compute(capture.file.clip, *capture.anatomy, contact, first_frame, hit_frame, last_frame);

    ClipTrajectory result;
    result.points_world = trajectory.hit_points;
    result.hit_index = hit_frame - first_frame;
    result.contact_world = trajectory.hit_points[static_cast<size_t>(result.hit_index)];
    result.box_in_heading = trajectory.box_in_heading;
    if (!trajectory.start_boxes.empty()) {
        result.box_in_first_heading = trajectory.start_boxes.front();
    } else { // the hit is the first frame: the path is one point
        result.box_in_first_heading.extend(trajectory.point_from(0, 0));
    }
    const AlignedBox& box = result.box_in_first_heading;
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d in_heading((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                                         (corner & 4) ? box.max.z() : box.min.z());
        result.box_corners_world[static_cast<size_t>(corner)] = trajectory.headings.front().to_world(in_heading);
    }
    return result;
}

} // namespace kumite::annotate
