#pragma once
// The body the fighter is shown on (fighter.h): per character its rig, strike adapter, MIR decoder and encoder; which
// character is on; the pose shown this frame (decoded by the body's decoder, or the strike adapter's), its MIR frame
// (before the defence's edits: the next blend starts from it) and the heading taken from it. Owns those. Touches
// nothing else: the motion player, the strike and the defence write the pose through it.

#include "kumite/core/character_rig.h"
#include "kumite/core/mir.h"
#include "kumite/core/motion_database.h"
#include "kumite/core/strike_adaptation.h"

#include <memory>
#include <span>
#include <vector>

namespace kumite {

class CharacterBody {
public:
    // What the body keeps per character.
    struct Rig {
        CharacterRig* rig;
        StrikeAdapter adapter;
        MirDecoder decoder;
        MirEncoder encoder;
        Rig(CharacterRig* character, const MotionDatabaseView& db)
            : rig(character), adapter(*character, db), decoder(character->skeleton(), character->anatomy(), {}),
              encoder(character->skeleton(), character->anatomy()) {}
    };

    // Standing on the first character at `start_x_m`, facing +Z, with every buffer the frames reuse sized, and the
    // frames the other parts keep sized too (nothing allocates after this): `any_character` are set to each
    // character's standing frame in turn (they may hold any character's), `first_character` to the first one's.
    CharacterBody(const MotionDatabaseView& db, const std::vector<CharacterRig*>& characters, double start_x_m,
                  std::span<MirFrame* const> any_character, std::span<MirFrame* const> first_character);

    int index() const { return m_index; }
    bool select(int index); // false: no such character, or already on it
    Rig& current() { return *m_rigs[m_index]; }
    const Rig& current() const { return *m_rigs[m_index]; }
    const RestAnatomy& anatomy() const { return current().rig->anatomy(); }
    double leg_length() const { return anatomy().leg_length; }

    // The MIR frame shown, before the defence's edits, and the pose.
    MirFrame& mir() { return m_mir; }
    const MirFrame& mir() const { return m_mir; }
    Pose& pose() { return m_pose; }
    const Pose& pose() const { return m_pose; }
    // The pose decoded from `frame` (with `pins`) on the current character: the decoder's is shown.
    void decode(const MirFrame& frame, const LimbPins& pins = {});
    // The strike adapter's pose is shown (it decoded into pose()).
    void show_adapter() { m_shown = Shown::adapter; }
    // The pose in pose() is shown as it now is, edited after its decoding (the speed limit's): its model transforms
    // computed again here.
    void show_edited_pose();
    // The pose shown, encoded again into `frame`.
    void encode(MirFrame& frame) { current().encoder.encode(frame, m_pose.view()); }

    std::span<const Eigen::Vector3d> positions() const;    // model positions of the pose shown
    std::span<const Eigen::Quaterniond> rotations() const; // model rotations of the pose shown
    Eigen::Vector3d part_position(BodyPart part) const;    // world
    const HeadingFrame& heading() const { return m_heading; }
    void update_heading(); // from the pose shown, at the end of each frame

private:
    std::vector<std::unique_ptr<Rig>> m_rigs;
    int m_index = 0;
    enum class Shown { decoder, adapter, edited };
    Shown m_shown = Shown::decoder;
    std::vector<Eigen::Vector3d> m_edited_positions;    // model, of an edited pose: sized for the largest skeleton
    std::vector<Eigen::Quaterniond> m_edited_rotations;
    MirFrame m_mir;
    Pose m_pose;
    HeadingFrame m_heading;
};

} // namespace kumite
