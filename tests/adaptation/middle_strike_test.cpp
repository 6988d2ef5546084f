// Knee and elbow strikes on the reference database (hachaj-shorinryu's hiza-geri and empi): the knee or the elbow,
// not the foot or the hand, lands on a target inside its reach (the upper bone's length from the hip or shoulder,
// a few centimetres from where the clip lands) on every shipped character, and stays there: no
// sweep past the target, no joint bent the wrong way, bones exact, the support foot down.

#include "kumite/core/strike_adaptation.h"
#include "support/reference_database.h"
#include "support/standing_character.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

Limb limb_of_middle_strike(const char* semantics, Side side) {
    const bool left = side == Side::left;
    return std::string(semantics) == "knee" ? (left ? Limb::leg_l : Limb::leg_r) : (left ? Limb::arm_l : Limb::arm_r);
}

struct Landing {
    double contact_error_m = 0.0;
    double past_target_m = 0.0;
    unsigned violations = 0;
    double bone_error_m = 0.0;
    double support_drift_m = 0.0;
    int effector = -1;
};

Landing strike(const kumite::test::StandingCharacter& character, const Retriever& retriever, const MotionDatabaseView& db,
               const char* semantics, Side side, const Eigen::Vector3d& offset) {
    RetrievalWorkspace workspace = retriever.make_workspace();
    // Where this strike lands by itself on this character (its clip decoded on it), then a target a few
    // centimetres from there: inside the reach of a knee or elbow, whose distance to the hip or shoulder is fixed.
    const Eigen::Vector3d nominal = character.pose.root_translation + Eigen::Vector3d(0.0, 0.0, 0.5);
    const RetrievalResult natural = retriever.query(character.order(retriever, semantics, side, nominal), workspace);
    REQUIRE(natural.found);
    StrikeAdapter adapter(*character.rig, db);
    adapter.begin({natural.clip, natural.start_frame, natural.contact_frame, natural.clip_to_world, natural.contact_point_world},
                  character.mir, {true, true}, character.ankles);
    // Inside reach: the knee or elbow stays the upper bone's length from the hip or shoulder, so the offset target
    // goes onto that sphere about the root where the clip's own strike lands.
    Pose natural_pose;
    adapter.step(adapter.contact_index(), natural_pose);
    const Limb limb = limb_of_middle_strike(semantics, side);
    const LimbChain& chain = character.anatomy.limbs[int(limb)];
    const Eigen::Vector3d root = adapter.positions()[chain.root];
    const Eigen::Vector3d target = root + chain.upper_length * (adapter.clip_contact_point() + offset - root).normalized();
    adapter.begin({natural.clip, natural.start_frame, natural.contact_frame, natural.clip_to_world, target}, character.mir, {true, true},
                  character.ankles);
    REQUIRE(adapter.middle_strike());
    Landing landing;
    landing.effector = adapter.effector_joint();
    Pose pose;
    for (int i = 0; i < adapter.frame_count(); ++i) {
        const AdaptedFrame frame = adapter.step(i, pose);
        if (frame.contact) landing.contact_error_m = (frame.effector - target).norm();
        landing.past_target_m = std::max(landing.past_target_m, frame.past_target_m);
        landing.violations |= frame.joint_violations;
        landing.bone_error_m = std::max(landing.bone_error_m, bone_length_error(character.skeleton(), adapter.positions()));
        for (int foot = 0; foot < 2; ++foot) {
            if (!adapter.support_feet()[foot]) continue;
            const Eigen::Vector3d ankle = adapter.positions()[character.anatomy.limbs[2 + foot].extremity];
            landing.support_drift_m = std::max(landing.support_drift_m, (ankle - adapter.support_pins()[foot]).norm());
        }
    }
    return landing;
}

} // namespace

TEST_CASE("middle strikes: knees and elbows land on targets inside their reach on every character", "[adaptation][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    if (retriever.semantics_id("knee") < 0 || retriever.semantics_id("elbow") < 0) {
        WARN("the reference database holds no knee or elbow strikes");
        return;
    }
    int strikes = 0;
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) {
        const kumite::test::StandingCharacter character(name, db);
        for (const char* semantics : {"knee", "elbow"}) {
            for (const Side side : {Side::left, Side::right}) {
                for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.04, -0.05, 0.03),
                                                      Eigen::Vector3d(-0.05, 0.04, -0.04)}) {
                    INFO(name << " " << semantics << (side == Side::left ? " left" : " right") << " offset " << offset.transpose());
                    const Landing landing = strike(character, retriever, db, semantics, side, offset);
                    const int middle = character.anatomy.limbs[int(limb_of_middle_strike(semantics, side))].middle;
                    CHECK(landing.effector == middle); // the knee or the elbow strikes, not the foot or the hand
                    CHECK(landing.contact_error_m <= 0.01);
                    CHECK(landing.past_target_m <= 0.03);
                    CHECK(landing.violations == 0u);
                    CHECK(landing.bone_error_m < 1e-9);
                    CHECK(landing.support_drift_m < 1e-6);
                    ++strikes;
                }
            }
        }
    }
    CHECK(strikes == 5 * 2 * 2 * 3);
}

TEST_CASE("middle strikes: a knee or elbow segment strikes with the limb's middle joint", "[adaptation]") {
    CHECK(segment_strikes_with_middle(BodyPart::shin_l));
    CHECK(segment_strikes_with_middle(BodyPart::forearm_r));
    CHECK_FALSE(segment_strikes_with_middle(BodyPart::hand_l));
    CHECK_FALSE(segment_strikes_with_middle(BodyPart::foot_r));
    CHECK_FALSE(segment_strikes_with_middle(BodyPart::toe_r));
}
