#pragma once
// Skeleton: joint names, parents in topological order (parents[i] < i, the root has -1) and rest offsets.
// Lengths are metres. A rest offset is the joint's position in its parent's frame when every rotation is
// identity; End Sites (leaf markers without channels) are kept as offsets from their joint.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kumite {

struct EndSite {
    int joint = -1;                  // the joint this End Site hangs from
    Eigen::Vector3d offset_in_joint; // metres, in that joint's frame
};

struct Skeleton {
    std::vector<std::string> names;
    std::vector<int> parents;                   // [joint] parent index, -1 for the root; parents[i] < i
    std::vector<Eigen::Vector3d> rest_offsets;  // [joint] metres, in the parent's frame (root: in world)
    std::vector<EndSite> end_sites;

    int joint_count() const { return static_cast<int>(names.size()); }
    std::optional<int> find(std::string_view name) const;
    std::vector<int> children(int joint) const;
    bool is_ancestor(int ancestor, int joint) const; // true when ancestor == joint too

    // Asserts the structural invariants (sizes agree, parents topological, one root at index 0).
    void assert_valid() const;
};

// Every joint's position in the rest pose (identity rotations): the rest offsets summed down the tree. [joint]
std::vector<Eigen::Vector3d> rest_model_positions(const Skeleton& skeleton);

// The deepest joint that is an ancestor of both (a joint is its own ancestor).
int lowest_common_ancestor(const Skeleton& skeleton, int a, int b);

} // namespace kumite
