#include "kumite/core/foot_contacts.h"

#include <algorithm>

namespace kumite {

std::vector<ContactInterval> foot_contacts_detect(const std::vector<Eigen::Vector3d>& ankle, double frame_time_s,
                                                  double leg_length, double standing_ankle_y,
                                                  const FootContactThresholds& thresholds) {
    std::vector<ContactInterval> contacts;
    if (!(frame_time_s > 0.0)) return contacts; // no rate, no speeds: callers refuse such clips first
    const int frames = static_cast<int>(ankle.size());
    bool planted = false;
    for (int frame = 0; frame < frames; ++frame) {
        // Central difference of the horizontal position (one-sided at the ends).
        const int before = std::max(0, frame - 1), after = std::min(frames - 1, frame + 1);
        Eigen::Vector3d step = ankle[after] - ankle[before];
        step.y() = 0.0;
        const double speed = after > before ? step.norm() / ((after - before) * frame_time_s) / leg_length : 0.0;
        const double height = (ankle[frame].y() - standing_ankle_y) / leg_length;
        const bool slid_away = planted && [&] {
            Eigen::Vector3d moved = ankle[frame] - ankle[contacts.back().first_frame];
            moved.y() = 0.0;
            return moved.norm() / leg_length > thresholds.max_slide;
        }();
        if (planted && (height > thresholds.leave_height || speed > thresholds.leave_speed || slid_away)) planted = false;
        if (!planted && height < thresholds.enter_height && speed < thresholds.enter_speed) {
            planted = true; // a foot that slid away re-plants at once: a new contact from here
            contacts.push_back({frame, frame});
        }
        if (planted) contacts.back().last_frame = frame;
    }
    return contacts;
}

} // namespace kumite
