// Captured blocks (block_clips.h): the database's block clips placed on a character's arm where a full decode puts
// them, chosen by side, kind and time, and played by the fighter against a punching user.

#include "kumite/core/contact_point.h"
#include "kumite/runtime/block_clips.h"
#include "support/reference_database.h"
#include "support/standing_character.h"

#include <catch2/catch.hpp>

using namespace kumite;

TEST_CASE("block_clips: the clip's arm placed on a frame is where the decoder puts it", "[runtime][corpus]") {
    const MotionDatabaseContent* content = test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const BlockClips blocks(db);
    REQUIRE(blocks.count() >= 80);
    test::StandingCharacter character("brawler", db);
    const RestAnatomy& anatomy = character.rig->anatomy();
    MirDecoder decoder(character.skeleton(), anatomy, {});
    Pose pose;
    MirFrame frame;
    double worst = 0.0;
    int checked = 0;
    for (std::size_t c = 0; c < db.clips.size(); c += 7) {
        const DbClip& clip = db.clips[c];
        if (!semantics_is_block(db.string(clip.semantics))) continue;
        const int limb = clip.side == std::uint32_t(Side::left) ? int(Limb::arm_l) : int(Limb::arm_r);
        db_mir_frame_load(frame, db.mir_frames[clip.first_pose + clip.hit_frame]);
        decoder.decode(pose, frame);
        const auto positions = decoder.model_positions();
        const LimbChain& chain = anatomy.limbs[limb];
        const BlockClips::ArmPoints placed =
            blocks.arm_points(anatomy, limb, int(c), clip.hit_frame, positions[chain.root], db.poses[clip.first_pose + clip.hit_frame].heading[2],
                              Eigen::Vector3d::Zero());
        const Eigen::Vector3d contact = positions[chain.extremity] + k_block_contact_fraction * (positions[chain.middle] - positions[chain.extremity]);
        worst = std::max({worst, (placed.wrist - positions[chain.extremity]).norm(), (placed.contact - contact).norm()});
        ++checked;
        // A rising block ends with the forearm over the head; a downward one low in front of the hips.
        const double head_y = positions[anatomy.body_map.joint(BodyPart::head)].y();
        if (clip.strike_kind() == StrikeKind::rising) CHECK(contact.y() > head_y - 0.1);
        if (clip.strike_kind() == StrikeKind::downward) CHECK(contact.y() < positions[chain.root].y() - 0.3);
    }
    CHECK(checked >= 10);
    CHECK(worst < 1e-4);
}
