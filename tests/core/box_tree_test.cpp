// BoxTree: every node's range splits into its children's, every point lies in the box of every node above it,
// the trees are balanced, and identical points make a leaf however many they are.

#include "kumite/core/box_tree.h"
#include "kumite/core/split_mix.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace kumite;

namespace {

// Checks the subtree under `node` over order[begin, end); returns its depth.
int check_subtree(const BoxTree& tree, int node, const std::vector<float>& points, const std::vector<std::uint32_t>& order, int leaf_size) {
    const int dims = tree.dimensions();
    const BoxTree::Node& n = tree.node(node);
    for (std::uint32_t k = n.begin; k < n.end; ++k) {
        for (int d = 0; d < dims; ++d) {
            const float value = points[std::size_t(order[k]) * dims + d];
            if (std::isnan(value)) continue; // in no box: a NaN bounds nothing
            REQUIRE(value >= tree.low(node)[d]);
            REQUIRE(value <= tree.high(node)[d]);
        }
    }
    if (n.leaf()) return 1;
    REQUIRE(n.end - n.begin > std::uint32_t(leaf_size));
    const BoxTree::Node& left = tree.node(node + 1);
    const BoxTree::Node& right = tree.node(static_cast<int>(n.right));
    REQUIRE(left.begin == n.begin);
    REQUIRE(left.end == right.begin);
    REQUIRE(right.end == n.end);
    return 1 + std::max(check_subtree(tree, node + 1, points, order, leaf_size), check_subtree(tree, static_cast<int>(n.right), points, order, leaf_size));
}

} // namespace

TEST_CASE("box_tree: ranges split, boxes hold their points, trees are balanced", "[core]") {
    SplitMix64 random{4};
    const int dims = 5;
    for (int leaf_size : {1, 3, 64}) {
        const std::uint32_t count = 1000;
        std::vector<float> points(std::size_t(count) * dims);
        for (float& value : points) value = static_cast<float>(random.uniform(-1.0, 1.0));
        std::vector<float> scale(dims, 1.0f);
        scale[2] = 10.0f; // weighted widths: dimension 2 is split first
        std::vector<std::uint32_t> order(count);
        std::iota(order.begin(), order.end(), 0u);
        BoxTree tree(dims);
        // Two trees in one forest, over two halves of the permutation.
        const int first = tree.add(points, scale, order, 0, 600, leaf_size);
        const int second = tree.add(points, scale, order, 600, count, leaf_size);
        CHECK(tree.add(points, scale, order, 600, 600, leaf_size) == -1);
        std::vector<std::uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        for (std::uint32_t k = 0; k < count; ++k) REQUIRE(sorted[k] == k);
        const int first_depth = check_subtree(tree, first, points, order, leaf_size);
        const int second_depth = check_subtree(tree, second, points, order, leaf_size);
        CHECK(first_depth <= std::ceil(std::log2(600.0 / leaf_size)) + 2);
        CHECK(second_depth <= std::ceil(std::log2(400.0 / leaf_size)) + 2);
        if (leaf_size < 600) {
            // The root's children are split along the weighted widest dimension.
            CHECK(tree.high(first + 1)[2] <= tree.low(static_cast<int>(tree.node(first).right))[2]);
        }
    }
}

TEST_CASE("box_tree: identical points make one leaf", "[core]") {
    std::vector<float> points(3 * 50, 0.25f);
    std::vector<float> scale(3, 1.0f);
    std::vector<std::uint32_t> order(50);
    std::iota(order.begin(), order.end(), 0u);
    BoxTree tree(3);
    const int root = tree.add(points, scale, order, 0, 50, 4);
    CHECK(tree.node(root).leaf());
    CHECK(tree.node_count() == 1);
}

TEST_CASE("box_tree: NaN coordinates still give a permutation split into balanced ranges, NaN after the numbers", "[core]") {
    SplitMix64 random{9};
    const int dims = 3;
    const std::uint32_t count = 2000;
    std::vector<float> points(std::size_t(count) * dims);
    for (float& value : points) value = random.uniform(0.0, 1.0) < 0.3 ? NAN : static_cast<float>(random.uniform(-1.0, 1.0));
    std::vector<float> scale(dims, 1.0f);
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    BoxTree tree(dims);
    const int root = tree.add(points, scale, order, 0, count, 4);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t k = 0; k < count; ++k) REQUIRE(sorted[k] == k);
    CHECK(check_subtree(tree, root, points, order, 4) <= std::ceil(std::log2(count / 4.0)) + 2);
    // The root's split: every number on the left is at most every number on the right, and no NaN lies left of a
    // number (NaN sorts last).
    const BoxTree::Node& top = tree.node(root);
    REQUIRE_FALSE(top.leaf());
    int split = 0;
    float widest = -1.0f;
    for (int d = 0; d < dims; ++d) {
        const float width = tree.high(root)[d] - tree.low(root)[d];
        if (width > widest) widest = width, split = d;
    }
    float left_max = -INFINITY;
    bool left_nan = false;
    for (std::uint32_t k = top.begin; k < tree.node(root + 1).end; ++k) {
        const float value = points[std::size_t(order[k]) * dims + split];
        if (std::isnan(value)) left_nan = true;
        else left_max = std::max(left_max, value);
    }
    for (std::uint32_t k = tree.node(root + 1).end; k < top.end; ++k) {
        const float value = points[std::size_t(order[k]) * dims + split];
        if (std::isnan(value)) continue;
        CHECK_FALSE(left_nan); // a number right of a NaN: NaN did not sort last
        CHECK(value >= left_max);
    }
}
