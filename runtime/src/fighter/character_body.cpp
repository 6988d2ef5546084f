#include "fighter/character_body.h"

#include "kumite/core/forward_kinematics.h"

namespace kumite {

CharacterBody::CharacterBody(const MotionDatabaseView& db, const std::vector<CharacterRig*>& characters, double start_x_m,
                             std::span<MirFrame* const> any_character, std::span<MirFrame* const> first_character) {
    for (CharacterRig* character : characters) m_rigs.push_back(std::make_unique<Rig>(character, db));
    const int punch = db_first_clip_of(db, "punch");
    for (auto& rig : m_rigs) {
        rig->rig->stand_at_origin(m_pose, db);
        rig->encoder.encode(m_mir, m_pose.view());
        rig->decoder.decode(m_pose, m_mir);
        m_shown = Shown::decoder;
        const std::size_t joints = std::size_t(rig->rig->skeleton().joint_count());
        if (joints > m_edited_positions.size()) m_edited_positions.resize(joints), m_edited_rotations.resize(joints);
        for (MirFrame* frame : any_character) *frame = m_mir;
        rig->adapter.begin({punch >= 0 ? punch : 0, 0, 0, {}, {}}, m_mir, {true, true}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
    }
    Rig& first = *m_rigs[0];
    first.rig->stand_at_origin(m_pose, db);
    first.encoder.encode(m_mir, m_pose.view());
    for (MirFrame* frame : first_character) *frame = m_mir;
    m_heading = first.rig->heading();
    m_heading.origin.x() += start_x_m;
}

bool CharacterBody::select(int index) {
    if (index < 0 || index >= static_cast<int>(m_rigs.size()) || index == m_index) return false;
    m_index = index;
    return true;
}

void CharacterBody::decode(const MirFrame& frame, const LimbPins& pins) {
    current().decoder.decode(m_pose, frame, pins);
    m_shown = Shown::decoder;
}

void CharacterBody::show_edited_pose() {
    const std::size_t joints = std::size_t(current().rig->skeleton().joint_count());
    forward_kinematics(std::span(m_edited_positions).first(joints), std::span(m_edited_rotations).first(joints), current().rig->skeleton(), m_pose.view());
    m_shown = Shown::edited;
}

std::span<const Eigen::Vector3d> CharacterBody::positions() const {
    const Rig& rig = current();
    if (m_shown == Shown::edited) return std::span<const Eigen::Vector3d>(m_edited_positions).first(std::size_t(rig.rig->skeleton().joint_count()));
    return m_shown == Shown::adapter ? rig.adapter.positions() : rig.decoder.model_positions();
}

std::span<const Eigen::Quaterniond> CharacterBody::rotations() const {
    const Rig& rig = current();
    if (m_shown == Shown::edited) return std::span<const Eigen::Quaterniond>(m_edited_rotations).first(std::size_t(rig.rig->skeleton().joint_count()));
    return m_shown == Shown::adapter ? rig.adapter.rotations() : rig.decoder.model_rotations();
}

Eigen::Vector3d CharacterBody::part_position(BodyPart part) const {
    const int joint = anatomy().body_map.joint(part);
    return joint >= 0 ? positions()[joint] : m_heading.origin;
}

void CharacterBody::update_heading() {
    const Rig& rig = current();
    m_heading = pose_heading(rig.rig->skeleton(), rig.rig->anatomy(), positions(), rotations());
}

} // namespace kumite
