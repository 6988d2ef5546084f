#include "support/standing_character.h"

#include "support/test_paths.h"

#include <catch2/catch.hpp>

namespace kumite::test {

StandingCharacter::StandingCharacter(const std::string& name, const MotionDatabaseView& database) {
    Result<BvhFile> read = bvh_read_file(source_dir() / "data/characters" / (name + ".bvh"));
    REQUIRE(read.has_value());
    file = std::move(*read);
    Result<RestAnatomy> built = rest_anatomy_build(file.clip, file.body_map);
    REQUIRE(built.has_value());
    anatomy = std::move(*built);
    rig = std::make_unique<CharacterRig>(file.clip.skeleton, anatomy);
    rig->stand_at_origin(pose, database);
    rig->still_feature(feature);
    MirEncoder encoder(file.clip.skeleton, anatomy);
    encoder.encode(mir, pose.view());
    const auto positions = rig->positions();
    ankles = {positions[anatomy.limbs[int(Limb::leg_l)].extremity], positions[anatomy.limbs[int(Limb::leg_r)].extremity]};
    pelvis_y = positions[anatomy.body_map.joint(BodyPart::pelvis)].y();
    head_y = positions[anatomy.body_map.joint(BodyPart::head)].y();
    query.pose_feature = feature;
    query.heading = rig->heading();
    query.character = rig->size();
}

RetrievalQuery StandingCharacter::order(const Retriever& retriever, const char* semantics, Side side, const Eigen::Vector3d& target) const {
    RetrievalQuery q = query;
    q.semantics = retriever.semantics_id(semantics);
    q.side = side;
    q.target_world = target;
    return q;
}

} // namespace kumite::test
