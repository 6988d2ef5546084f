#include "kumite/runtime/motion_meter.h"

namespace kumite {

MotionMeter::MotionMeter(int fighters) : m_last(std::size_t(std::max(1, fighters))) {}

MoveKind MotionMeter::move_kind(const Fighter& fighter, const MotionDatabaseView& db) {
    const Defence& defence = fighter.defence();
    if (defence.block_weight() > 0.0) return MoveKind::block;
    if (defence.slip_weight() > 0.0) return MoveKind::slip;
    switch (fighter.state()) {
    case FighterState::strike: {
        const int segment = db.clips[fighter.strike_clip()].segment;
        return segment >= 0 && segment < k_body_part_count ? strike_move_kind(static_cast<BodyPart>(segment)) : MoveKind::punch;
    }
    case FighterState::approach: return MoveKind::step;
    case FighterState::recover: return MoveKind::recover;
    case FighterState::hold: return MoveKind::hold;
    case FighterState::hit_reaction: return MoveKind::hit_reaction;
    case FighterState::rest: break;
    }
    return MoveKind::guard;
}

void MotionMeter::measure(int fighter_index, double t_s, const Fighter& fighter, const MotionDatabaseView& db, const RestAnatomy& anatomy,
                          const Eigen::Vector3d* head) {
    Last& last = m_last[std::size_t(fighter_index)];
    const LimbSample sample = LimbSample::of(anatomy, fighter.positions());
    const MoveKind kind = move_kind(fighter, db);
    ++m_frames[int(kind)];
    if (last.valid && last.character == fighter.character() && t_s > last.t_s) {
        const JointSpeeds speeds = joint_speeds(last.sample, sample, t_s - last.t_s);
        JointSpeeds& fastest = m_fastest[int(kind)];
        if (speeds.wrist_mps > fastest.wrist_mps) m_peak_times[int(kind)].wrist_at_s = t_s;
        if (speeds.ankle_mps > fastest.ankle_mps) m_peak_times[int(kind)].ankle_at_s = t_s;
        fastest.keep_fastest(speeds);
    }
    last = {true, fighter.character(), t_s, sample};
    if (head && (fighter.state() == FighterState::rest || fighter.state() == FighterState::approach)) {
        const Eigen::Vector3d to_head = *head - fighter.heading().origin;
        const double distance = Eigen::Vector2d(to_head.x(), to_head.z()).norm();
        m_distance_m.add(distance);
        m_distance_legs.add(distance / anatomy.leg_length);
    }
}

JointSpeeds MotionMeter::fastest_overall() const {
    JointSpeeds all;
    for (const JointSpeeds& speeds : m_fastest) all.keep_fastest(speeds);
    return all;
}

} // namespace kumite
