#pragma once
// Rigs as they are made (formats/src only): the skin's joints of a real character file turned into the one body
// tree kumite animates. Artists' rigs carry more than the body: IK targets and pole vectors as extra roots,
// IK and FK copies of the arms beside the deforming chain, feet that hang from the root so an IK solver can
// pin them. What deforms the mesh (the joints with skin weight) is the body; the rest is control.
//
//   - The body is the deforming joint with no deforming ancestor that carries the most weight below it (the
//     hips, or a torso above them), with the joints above it up to its tree's root.
//   - Other deforming pieces (a foot hung from the root) are attached to the end of the limb they sit at the end
//     of, by rest position: the body's last deforming joint of a chain whose direction points at them, the
//     nearest one. A piece that continues no limb is attached to the root, at its bind pose.
//   - Joints that deform nothing, nor does anything below them (IK/FK copies, targets, poles), are left out when
//     the rig has such extra pieces or roots, or when `prune_controls` asks for it.
// Each change is said in a warning naming the joints.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace kumite::gltf {

struct RigJoints {
    std::vector<int> parent;          // [skin joint] its parent skin joint in the body tree, -1 for the root
    std::vector<bool> kept;           // [skin joint] part of the body tree
    std::vector<std::string> warnings;
};

// `joint_parent[k]`: the skin joint that is skin joint k's nearest joint ancestor in the node tree (-1: none);
// `rest_positions[k]`: its rest position (metres); `weights[k]`: the sum of its skin weights over the vertices;
// `names[k]` for the warnings.
RigJoints body_tree(const std::vector<int>& joint_parent, const std::vector<Eigen::Vector3d>& rest_positions,
                    const std::vector<double>& weights, const std::vector<std::string>& names, bool prune_controls);

} // namespace kumite::gltf
