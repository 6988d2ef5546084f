#include "gltf_rig.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstddef>

namespace kumite::gltf {
namespace {

// Names in a warning: the first few, then how many more.
std::string listed(const std::vector<int>& joints, const std::vector<std::string>& names) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(joints.size(), 6);
    for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + names[std::size_t(joints[i])];
    if (joints.size() > shown) text += " and " + std::to_string(joints.size() - shown) + " more";
    return text;
}

struct Tree {
    std::vector<int> parent;
    std::vector<std::vector<int>> children;

    explicit Tree(std::vector<int> parents) : parent(std::move(parents)), children(parent.size()) {
        for (std::size_t k = 0; k < parent.size(); ++k) {
            if (parent[k] >= 0) children[std::size_t(parent[k])].push_back(int(k));
        }
    }
    bool is_ancestor(int ancestor, int joint) const {
        for (int at = joint; at >= 0; at = parent[std::size_t(at)]) {
            if (at == ancestor) return true;
        }
        return false;
    }
    int root_of(int joint) const {
        while (parent[std::size_t(joint)] >= 0) joint = parent[std::size_t(joint)];
        return joint;
    }
    // Joints of the subtree of `top` (itself first), iteratively: a limb of thousands of joints is no recursion.
    std::vector<int> subtree(int top) const {
        std::vector<int> out{top};
        for (std::size_t i = 0; i < out.size(); ++i) {
            for (int child : children[std::size_t(out[i])]) out.push_back(child);
        }
        return out;
    }
};

// The last deforming joint of a limb among `candidates` whose direction points at `piece` and that ends nearest
// to it, or -1. `parent` is the tree as attached so far: a joint below `piece` is never its limb.
int limb_end_for(const Tree& tree, const std::vector<int>& parent, const std::vector<int>& candidates, int piece,
                 const std::vector<Eigen::Vector3d>& at, const std::vector<bool>& deforming) {
    int best = -1;
    double best_distance = 1e300;
    for (int end : candidates) {
        const int end_parent = tree.parent[std::size_t(end)];
        if (end == piece || end_parent < 0 || !deforming[std::size_t(end)]) continue;
        const bool deforming_child = std::any_of(tree.children[std::size_t(end)].begin(), tree.children[std::size_t(end)].end(),
                                                 [&](int child) { return deforming[std::size_t(child)]; });
        if (deforming_child) continue;
        bool below_piece = false;
        for (int a = end; a >= 0 && !below_piece; a = parent[std::size_t(a)]) below_piece = a == piece;
        if (below_piece) continue;
        const Eigen::Vector3d segment = at[std::size_t(end)] - at[std::size_t(end_parent)];
        const Eigen::Vector3d gap = at[std::size_t(piece)] - at[std::size_t(end)];
        const double length = segment.norm(), distance = gap.norm();
        if (length < 1e-6 || distance < 1e-6 || distance > 2.5 * length) continue;
        if (segment.dot(gap) < 0.7 * length * distance) continue; // more than 45 degrees off the limb's line
        if (distance < best_distance) best = end, best_distance = distance;
    }
    return best;
}

} // namespace

RigJoints body_tree(const std::vector<int>& joint_parent, const std::vector<Eigen::Vector3d>& rest_positions,
                    const std::vector<double>& weights, const std::vector<std::string>& names, bool prune_controls) {
    const int n = int(joint_parent.size());
    RigJoints rig;
    rig.parent = joint_parent;
    rig.kept.assign(std::size_t(n), true);
    if (n == 0) return rig;
    Tree tree(joint_parent);
    std::vector<bool> deforming(std::size_t(n), false);
    for (int k = 0; k < n; ++k) deforming[std::size_t(k)] = weights[std::size_t(k)] > 0.0;

    // Weight below each joint (children have higher indices only in parent-first order, which skins need not
    // follow: accumulate along a subtree order instead).
    std::vector<double> below(weights.begin(), weights.end());
    std::vector<int> roots;
    for (int k = 0; k < n; ++k) {
        if (joint_parent[std::size_t(k)] < 0) roots.push_back(k);
    }
    std::vector<int> order; // parents first, over every tree
    for (int root : roots) {
        const std::vector<int> joints = tree.subtree(root);
        order.insert(order.end(), joints.begin(), joints.end());
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const int parent = joint_parent[std::size_t(*it)];
        if (parent >= 0) below[std::size_t(parent)] += below[std::size_t(*it)];
    }

    // The deforming tops: deforming joints with no deforming ancestor.
    std::vector<int> tops;
    for (int k : order) {
        if (!deforming[std::size_t(k)]) continue;
        bool has_deforming_ancestor = false;
        for (int at = joint_parent[std::size_t(k)]; at >= 0 && !has_deforming_ancestor; at = joint_parent[std::size_t(at)]) has_deforming_ancestor = deforming[std::size_t(at)];
        if (!has_deforming_ancestor) tops.push_back(k);
    }
    if (tops.empty()) { // nothing deforms: every tree but the largest is left out, as before
        int largest = roots.front();
        for (int root : roots) {
            if (tree.subtree(root).size() > tree.subtree(largest).size()) largest = root;
        }
        for (int k = 0; k < n; ++k) rig.kept[std::size_t(k)] = tree.root_of(k) == largest;
        if (roots.size() > 1) rig.warnings.push_back(std::to_string(roots.size() - 1) + " joint trees beside the skeleton left out");
        return rig;
    }
    const int body_top = *std::max_element(tops.begin(), tops.end(), [&](int a, int b) { return below[std::size_t(a)] < below[std::size_t(b)]; });
    const int body_root = tree.root_of(body_top);
    const bool odd = roots.size() > 1 || tops.size() > 1;

    // Other deforming pieces: onto the limb they end; else, hung from the trunk above the body's top (a leg from
    // the armature's root joint), where they are; else onto the root.
    std::vector<int> candidates = tree.subtree(body_top);
    for (int piece : tops) {
        if (piece == body_top) continue;
        const std::vector<int> joints = tree.subtree(piece);
        candidates.insert(candidates.end(), joints.begin(), joints.end());
    }
    for (int piece : tops) {
        if (piece == body_top) continue;
        const int end = limb_end_for(tree, rig.parent, candidates, piece, rest_positions, deforming);
        const int from = joint_parent[std::size_t(piece)];
        const std::string hung = from >= 0 ? "hangs from " + names[std::size_t(from)] : "is a root of its own";
        if (end >= 0) {
            rig.parent[std::size_t(piece)] = end;
            rig.warnings.push_back("joint " + names[std::size_t(piece)] + " " + hung + " (an IK rig); attached to " + names[std::size_t(end)] +
                                   ", the limb it sits at the end of");
        } else if (from < 0 || !tree.is_ancestor(from, body_top)) {
            rig.parent[std::size_t(piece)] = body_root;
            rig.warnings.push_back("joint " + names[std::size_t(piece)] + " deforms the mesh but " + hung +
                                   " and continues no limb; attached to " + names[std::size_t(body_root)] + " at its bind pose");
        }
    }
    Tree attached(rig.parent);

    // What is kept: the body's tree, less the control joints when pruning.
    std::vector<bool> deforms_below(std::size_t(n), false); // the joint or a descendant in the attached tree deforms
    std::vector<int> attached_order = attached.subtree(body_root);
    for (auto it = attached_order.rbegin(); it != attached_order.rend(); ++it) {
        if (deforming[std::size_t(*it)]) deforms_below[std::size_t(*it)] = true;
        const int parent = rig.parent[std::size_t(*it)];
        if (parent >= 0 && deforms_below[std::size_t(*it)]) deforms_below[std::size_t(parent)] = true;
    }
    const bool prune = prune_controls || odd;
    std::vector<int> left_out, other_trees;
    std::vector<bool> in_body(std::size_t(n), false);
    for (int k : attached_order) in_body[std::size_t(k)] = true;
    for (int k = 0; k < n; ++k) {
        bool keep = in_body[std::size_t(k)];
        if (!keep) other_trees.push_back(k);
        else if (prune && !deforms_below[std::size_t(k)]) keep = false, left_out.push_back(k);
        rig.kept[std::size_t(k)] = keep;
    }
    // A left-out joint's children are left out too (none deforms), so the kept joints stay one tree.
    if (!other_trees.empty()) {
        rig.warnings.push_back(std::to_string(other_trees.size()) + " joints outside the body's tree (IK targets, control bones: " +
                               listed(other_trees, names) + ") left out; they deform nothing");
    }
    if (!left_out.empty()) {
        rig.warnings.push_back(std::to_string(left_out.size()) + " control joints that deform nothing (IK/FK copies, poles: " +
                               listed(left_out, names) + ") left out");
    }
    for (int k = 0; k < n; ++k) {
        if (!rig.kept[std::size_t(k)]) rig.parent[std::size_t(k)] = -1;
    }
    return rig;
}

} // namespace kumite::gltf
