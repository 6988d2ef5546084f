#pragma once
// Where the user's head is going: an alpha-beta filter on the tracked head (position and velocity from noisy
// samples at any rate) and the head's position after a delay if it keeps its course. The prediction is bounded:
// the horizontal speed to a brisk walk, the delay to a second, the point to the room; the height is the filtered
// height (a walking head bobs, and a duck is a change of course that no extrapolation should guess).

#include <Eigen/Core>

namespace kumite {

struct HeadMotionSettings {
    // Gains per sample. High: a head tracker's noise is millimetres, and a walker's turn must show within a few
    // samples (measured with scripts/hit_rates.py: 0.35/0.05 hit 40% of strikes on a 1.2 m/s walker, 0.7/0.4 60%).
    double alpha = 0.7;            // position
    double beta = 0.4;             // velocity
    double settled_mps = 0.15;     // the course is settled while the recent prediction residuals stay below this speed
    double max_speed_mps = 2.0;    // a brisk walk; faster estimates are scaled down to it
    double max_horizon_s = 1.0;    // predictions further ahead are cut there
    double gap_reset_s = 0.5;      // samples further apart than this restart the filter
    Eigen::Vector2d room_min{-4.0, -4.0}; // the room's floor (x, z), metres, world: predictions stay inside
    Eigen::Vector2d room_max{4.0, 6.0};
};

class HeadMotionFilter {
public:
    explicit HeadMotionFilter(HeadMotionSettings settings = {}) : m_settings(settings) {}

    void reset() { m_samples = 0; }
    void update(double t_s, const Eigen::Vector3d& head);

    bool ready() const { return m_samples >= 2; }
    // The head keeps its course: the filter's recent residuals (what it failed to predict, as a speed, averaged
    // over about 0.1 s) are small. Right after a turn, a stop or a start they are not.
    bool settled() const { return ready() && m_residual_mps < m_settings.settled_mps; }
    double residual_mps() const { return m_residual_mps; }
    const Eigen::Vector3d& position() const { return m_position; }
    Eigen::Vector3d velocity() const; // horizontal, bounded to max_speed_mps; zero until ready()
    // Where the head will be `after_s` seconds after the last sample, on its current course.
    Eigen::Vector3d predict(double after_s) const;

private:
    HeadMotionSettings m_settings;
    int m_samples = 0;
    double m_last_s = 0.0;
    Eigen::Vector3d m_position = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_velocity = Eigen::Vector3d::Zero();
    double m_residual_mps = 0.0;
};

} // namespace kumite
