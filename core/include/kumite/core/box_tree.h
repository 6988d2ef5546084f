#pragma once
// A forest of k-d trees whose nodes keep the bounding box of their points: the structure a branch-and-bound search
// descends, skipping every node whose box already bounds its points' scores above the best found.
//
// Points are rows of `dimensions` floats. `add` builds one tree over a range of a permutation of the points,
// reordering that range so every node covers a contiguous part of it: a caller that stores its items in the
// permutation's order reads a node's items as items[begin .. end). Splits are at the median of the widest
// dimension (widths multiplied by a per-dimension scale), so trees are balanced: depth <= log2(count) + 1.

#include <cstdint>
#include <span>
#include <vector>

namespace kumite {

class BoxTree {
public:
    struct Node {
        std::uint32_t begin = 0, end = 0; // positions in the permutation
        std::uint32_t right = 0;          // the right child; 0 for a leaf (the left child is the next node)
        bool leaf() const { return right == 0; }
    };
    static constexpr int max_depth = 64;

    explicit BoxTree(int dimensions = 1) : m_dimensions(dimensions) {}

    // Builds a tree over order[begin .. end) (point indices into `points`, rows of dimensions floats), reordering that
    // range. Returns the root node, or -1 when the range is empty. split_scale: [dimensions] weights of the widths.
    int add(std::span<const float> points, std::span<const float> split_scale, std::span<std::uint32_t> order, std::uint32_t begin,
            std::uint32_t end, int leaf_size);

    int dimensions() const { return m_dimensions; }
    int node_count() const { return static_cast<int>(m_nodes.size()); }
    const Node& node(int index) const { return m_nodes[index]; }
    const float* low(int index) const { return m_bounds.data() + std::size_t(index) * 2 * m_dimensions; }
    const float* high(int index) const { return low(index) + m_dimensions; }

private:
    int build(std::span<const float> points, std::span<const float> split_scale, std::span<std::uint32_t> order, std::uint32_t begin,
              std::uint32_t end, int leaf_size, int depth);

    int m_dimensions;
    std::vector<Node> m_nodes;
    std::vector<float> m_bounds; // [node][low dims, high dims]
};

} // namespace kumite
