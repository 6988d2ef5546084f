#include "kumite/core/skeleton.h"

#include <cassert>

namespace kumite {

std::optional<int> Skeleton::find(std::string_view name) const {
    for (int joint = 0; joint < joint_count(); ++joint) {
        if (names[joint] == name) return joint;
    }
    return std::nullopt;
}

std::vector<Eigen::Vector3d> rest_model_positions(const Skeleton& skeleton) {
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    for (int j = 0; j < skeleton.joint_count(); ++j) {
        positions[j] = skeleton.rest_offsets[j] + (skeleton.parents[j] >= 0 ? positions[skeleton.parents[j]] : Eigen::Vector3d::Zero());
    }
    return positions;
}

std::vector<int> Skeleton::children(int joint) const {
    std::vector<int> result;
    for (int child = joint + 1; child < joint_count(); ++child) {
        if (parents[child] == joint) result.push_back(child);
    }
    return result;
}

bool Skeleton::is_ancestor(int ancestor, int joint) const {
    for (int j = joint; j >= 0; j = parents[j]) {
        if (j == ancestor) return true;
    }
    return false;
}

void Skeleton::assert_valid() const {
    assert(parents.size() == names.size());
    assert(rest_offsets.size() == names.size());
    for (int joint = 0; joint < joint_count(); ++joint) {
        assert((joint == 0) == (parents[joint] < 0));
        assert(parents[joint] < joint);
    }
    for (const EndSite& end_site : end_sites) {
        assert(end_site.joint >= 0 && end_site.joint < joint_count());
        (void)end_site;
    }
}

int lowest_common_ancestor(const Skeleton& skeleton, int a, int b) {
    // Parents are topological, so walking the larger index up always meets the smaller one's chain.
    while (a != b) {
        if (a < 0 || b < 0) return -1;
        if (a > b) a = skeleton.parents[a];
        else b = skeleton.parents[b];
    }
    return a;
}

} // namespace kumite
