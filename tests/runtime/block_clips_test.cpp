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

namespace {

// A downward block asked of `limb` for a punch to be met at `contact_target` in 0.15 s, the arm where `positions` has it.
BlockClipQuery downward_query(const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> positions, int limb,
                              const Eigen::Vector3d& contact_target, double heading_yaw_rad) {
    const LimbChain& chain = anatomy.limbs[limb];
    BlockClipQuery query;
    query.limb = limb;
    query.kind = StrikeKind::downward;
    query.course[0].point = contact_target;
    query.course[0].time_s = 0.15;
    query.course_count = 1;
    query.heading_yaw_rad = heading_yaw_rad;
    query.shoulder = positions[chain.root];
    query.wrist = positions[chain.extremity];
    query.upper_length = chain.upper_length;
    query.lower_length = chain.lower_length;
    return query;
}

} // namespace

TEST_CASE("block_clips: a course in front of the chest is met mid-sweep by a downward block, where the choice says", "[runtime][corpus]") {
    const MotionDatabaseContent* content = test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const BlockClips blocks(db);
    test::StandingCharacter character("brawler", db);
    const RestAnatomy& anatomy = character.rig->anatomy();
    MirDecoder decoder(character.skeleton(), anatomy, {});
    Pose pose;
    decoder.decode(pose, character.mir);
    const auto positions = decoder.model_positions();
    const HeadingFrame& heading = character.query.heading;
    const double yaw = heading.yaw_rad;
    const Eigen::Vector3d forward = heading.to_world(Eigen::Vector3d::UnitZ()) - heading.origin; // +Z ahead, +X the left
    const Eigen::Vector3d left = heading.to_world(Eigen::Vector3d::UnitX()) - heading.origin;
    const Eigen::Vector3d chest = positions[anatomy.body_map.joint(BodyPart::chest)];
    int before_hit = 0, checked = 0;
    double worst = 0.0, worst_estimate = 0.0;
    for (const int limb : {int(Limb::arm_l), int(Limb::arm_r)}) {
        const LimbChain& chain = anatomy.limbs[limb];
        for (const double across : {-0.1, 0.0, 0.1}) {
            for (const double ahead : {0.3, 0.4}) {
                // A punch at the chest, met 15 cm short of it: in front of the chest, at its height.
                const BlockClipQuery query = downward_query(anatomy, positions, limb, chest + ahead * forward + across * left, yaw);
                BlockClipChoice choice;
                REQUIRE(blocks.choose(query, anatomy, choice));
                const DbClip& clip = db.clips[choice.clip];
                CHECK(clip.strike_kind() == StrikeKind::downward);
                CHECK(clip.side == std::uint32_t(limb == int(Limb::arm_l) ? Side::left : Side::right));
                CHECK(choice.start_frame < choice.meet_frame);
                CHECK(choice.meet_frame <= int(clip.hit_frame));
                CHECK(choice.contact_error_m <= query.max_contact_error * chain.length() + 1e-9);
                CHECK((choice.meet_frame - choice.start_frame) * blocks.frame_time_s() <= query.course[0].time_s + 1e-9);
                before_hit += choice.meet_frame < int(clip.hit_frame);
                // The choice's estimate (a unit arm, placed once) against the arm placed exactly at that frame.
                const auto at_meet = blocks.arm_points(anatomy, limb, choice.clip, choice.meet_frame, query.shoulder, yaw, Eigen::Vector3d::Zero());
                const double exact = (at_meet.contact - query.course[0].point).norm();
                worst = std::max(worst, exact);
                worst_estimate = std::max(worst_estimate, std::abs(exact - choice.contact_error_m));
                ++checked;
            }
        }
    }
    CHECK(checked == 12);
    CHECK(before_hit >= 9); // a gedan-barai ends low: the chest is crossed on the way down
    CHECK(worst < 0.5 * anatomy.limbs[int(Limb::arm_l)].length());
    CHECK(worst_estimate < 0.03);
    INFO("worst contact error " << worst << " m");

    // A course no block's forearm passes near (a metre behind the fighter's back) gets no captured block: the
    // synthesized one answers it.
    BlockClipQuery behind = downward_query(anatomy, positions, int(Limb::arm_r), chest - 1.0 * forward, yaw);
    BlockClipChoice none;
    CHECK_FALSE(blocks.choose(behind, anatomy, none));
    behind.max_contact_error = 10.0; // no limit: the nearest one, however far
    CHECK(blocks.choose(behind, anatomy, none));

    // Where on the course is part of the choice: of a point behind the fighter and one in front of its chest, the
    // one in front is met, with its own time.
    BlockClipQuery two = downward_query(anatomy, positions, int(Limb::arm_r), chest - 1.0 * forward, yaw);
    two.course[1].point = chest + 0.3 * forward;
    two.course[1].time_s = 0.2;
    two.course_count = 2;
    BlockClipChoice in_front;
    REQUIRE(blocks.choose(two, anatomy, in_front));
    CHECK(in_front.course_point == 1);
    CHECK((in_front.meet_frame - in_front.start_frame) * blocks.frame_time_s() <= 0.2 + 1e-9);
    CHECK(in_front.contact_error_m <= two.max_contact_error * anatomy.limbs[int(Limb::arm_r)].length() + 1e-9);
    // Only the first course_count points count.
    two.course_count = 1;
    CHECK_FALSE(blocks.choose(two, anatomy, in_front));
}
