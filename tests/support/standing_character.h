#pragma once
// A shipped character (data/characters) standing at the origin in a database's guard, as the retrieval and
// adaptation tests start from: its rig, the pose, its MIR frame and ankles, and a query ready but for the order
// and target.

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/strike_adaptation.h"
#include "kumite/formats/bvh_reader.h"

#include <memory>
#include <string>

namespace kumite::test {

struct StandingCharacter {
    BvhFile file;
    RestAnatomy anatomy;
    std::unique_ptr<CharacterRig> rig;
    Pose pose;
    std::array<float, k_feature_dimensions> feature{};
    MirFrame mir;                              // the standing pose, encoded on the character
    std::array<Eigen::Vector3d, 2> ankles;     // world, [left, right]
    double pelvis_y = 0.0, head_y = 0.0;
    RetrievalQuery query;                      // feature, heading and size set

    StandingCharacter(const std::string& name, const MotionDatabaseView& database);
    StandingCharacter(const StandingCharacter&) = delete;

    const Skeleton& skeleton() const { return file.clip.skeleton; }
    RetrievalQuery order(const Retriever& retriever, const char* semantics, Side side, const Eigen::Vector3d& target) const;
};

} // namespace kumite::test
