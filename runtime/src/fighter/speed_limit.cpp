#include "fighter/speed_limit.h"

#include <algorithm>


namespace kumite {
namespace {

// `out` part of the way from `from` to `to` (share in [0, 1]); the three poses are of one skeleton.
void blend_pose(Pose& out, const Pose& from, const Pose& to, double share) {
    out.root_translation = from.root_translation + share * (to.root_translation - from.root_translation);
    for (std::size_t j = 0; j < to.local_rotations.size(); ++j) out.local_rotations[j] = from.local_rotations[j].slerp(share, to.local_rotations[j]);
    for (std::size_t j = 0; j < to.local_translations.size() && j < from.local_translations.size(); ++j) {
        out.local_translations[j] = from.local_translations[j] + share * (to.local_translations[j] - from.local_translations[j]);
    }
}

} // namespace

SpeedLimit::SpeedLimit(std::shared_ptr<const LibrarySpeeds> library) : m_library(std::move(library)) {}

void SpeedLimit::reserve(int joints) {
    for (Pose* pose : {&m_last, &m_asked}) {
        pose->local_rotations.reserve(std::size_t(joints));
        pose->local_translations.reserve(std::size_t(joints));
    }
}

double SpeedLimit::over_bar(const LimbSample& sample, const JointSpeeds& bar, double dt_s) const {
    const JointSpeeds speeds = joint_speeds(m_last_sample, sample, dt_s);
    auto ratio = [](double value, double limit) { return limit > 0.0 ? value / limit : 0.0; };
    return std::max({ratio(speeds.wrist_mps, bar.wrist_mps), ratio(speeds.ankle_mps, bar.ankle_mps), ratio(speeds.elbow_radps, bar.elbow_radps),
                     ratio(speeds.knee_radps, bar.knee_radps)});
}

void SpeedLimit::apply(double t_s, MoveKind kind, CharacterBody& body) {
    const RestAnatomy& anatomy = body.anatomy();
    const double dt_s = t_s - m_last_s;
    const bool comparable = m_has_last && m_character == body.index() && dt_s > 0.0 && m_library &&
                            body.index() < int(m_library->per_character.size());
    if (comparable) {
        const JointSpeeds bar = speed_bar(m_library->per_character[std::size_t(body.index())], kind);
        const LimbSample asked = LimbSample::of(anatomy, body.positions());
        double over = over_bar(asked, bar, dt_s);
        if (over > 1.0) {
            // Part of the way: the share that brings the fastest joint to its bar. Estimated from the speeds (near
            // linear in the share over one frame) and refined between the largest share known under the bar (0: the
            // last pose, no speed at all) and the smallest known over it; the one under the bar is shown.
            m_asked = body.pose();
            double under = 0.0, above = 1.0, share = 1.0 / over;
            for (int refine = 0; refine < 10 && above - under > 1e-3; ++refine) {
                blend_pose(body.pose(), m_last, m_asked, share);
                body.show_edited_pose();
                const double ratio = over_bar(LimbSample::of(anatomy, body.positions()), bar, dt_s);
                if (ratio <= 1.001) {
                    under = share;
                    if (ratio >= 0.98) break;
                } else {
                    above = share;
                }
                const double estimate = ratio > 1e-6 ? share / ratio : above;
                share = estimate > under && estimate < above ? estimate : 0.5 * (under + above);
            }
            if (share != under) {
                blend_pose(body.pose(), m_last, m_asked, under);
                body.show_edited_pose();
            }
            // What comes next (a blend, a strike) starts from the pose shown, not from the one asked for.
            body.encode(body.mir());
            ++m_held_frames[int(kind)];
            const LimbSample shown = LimbSample::of(anatomy, body.positions());
            for (int k = 0; k < 4; ++k) m_largest_lag_m = std::max(m_largest_lag_m, (shown.extremity[k] - asked.extremity[k]).norm());
        }
    }
    m_has_last = true;
    m_character = body.index();
    m_last_s = t_s;
    m_last = body.pose();
    m_last_sample = LimbSample::of(anatomy, body.positions());
}

} // namespace kumite
