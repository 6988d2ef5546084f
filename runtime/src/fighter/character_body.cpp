#include "fighter/character_body.h"

namespace kumite {

CharacterBody::CharacterBody(const MotionDatabaseView& db, const std::vector<CharacterRig*>& characters, double start_x_m,
                             std::span<MirFrame* const> any_character, std::span<MirFrame* const> first_character) {
    for (CharacterRig* character : characters) m_rigs.push_back(std::make_unique<Rig>(character, db));
    const int punch = db_first_clip_of(db, "punch");
    for (auto& rig : m_rigs) {
        rig->rig->stand_at_origin(m_pose, db);
        rig->encoder.encode(m_mir, m_pose.view());
        rig->decoder.decode(m_pose, m_mir);
        m_shown_by_adapter = false;
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
    m_shown_by_adapter = false;
}

std::span<const Eigen::Vector3d> CharacterBody::positions() const {
    const Rig& rig = current();
    return m_shown_by_adapter ? rig.adapter.positions() : rig.decoder.model_positions();
}

std::span<const Eigen::Quaterniond> CharacterBody::rotations() const {
    const Rig& rig = current();
    return m_shown_by_adapter ? rig.adapter.rotations() : rig.decoder.model_rotations();
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
