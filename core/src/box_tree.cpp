#include "kumite/core/box_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace kumite {

int BoxTree::add(std::span<const float> points, std::span<const float> split_scale, std::span<std::uint32_t> order, std::uint32_t begin,
                 std::uint32_t end, int leaf_size) {
    assert(split_scale.size() == std::size_t(m_dimensions) && end <= order.size() && begin <= end);
    if (begin == end) return -1;
    return build(points, split_scale, order, begin, end, std::max(1, leaf_size), 0);
}

int BoxTree::build(std::span<const float> points, std::span<const float> split_scale, std::span<std::uint32_t> order, std::uint32_t begin,
                   std::uint32_t end, int leaf_size, int depth) {
    const int index = static_cast<int>(m_nodes.size());
    m_nodes.push_back({begin, end, 0});
    const int dims = m_dimensions;
    m_bounds.resize(m_bounds.size() + 2 * std::size_t(dims));
    float* low = m_bounds.data() + std::size_t(index) * 2 * dims;
    float* high = low + dims;
    std::fill(low, low + dims, std::numeric_limits<float>::infinity());
    std::fill(high, high + dims, -std::numeric_limits<float>::infinity());
    for (std::uint32_t k = begin; k < end; ++k) {
        const float* point = points.data() + std::size_t(order[k]) * dims;
        for (int d = 0; d < dims; ++d) {
            low[d] = std::min(low[d], point[d]);
            high[d] = std::max(high[d], point[d]);
        }
    }
    if (end - begin <= std::uint32_t(leaf_size) || depth + 1 >= max_depth) return index;
    int widest = 0;
    float widest_width = -1.0f;
    for (int d = 0; d < dims; ++d) {
        const float width = (high[d] - low[d]) * split_scale[d];
        if (width > widest_width) widest_width = width, widest = d;
    }
    if (!(widest_width > 0.0f)) return index; // every point the same: a leaf, however many
    const std::uint32_t middle = begin + (end - begin) / 2;
    // NaN sorts after every number: a strict weak order whatever the points hold (a plain < with a NaN is not one,
    // and nth_element may then run past the range).
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
        const float x = points[std::size_t(a) * dims + widest], y = points[std::size_t(b) * dims + widest];
        return x < y || (!std::isnan(x) && std::isnan(y));
    });
    build(points, split_scale, order, begin, middle, leaf_size, depth + 1); // the left child is index + 1
    const int right = build(points, split_scale, order, middle, end, leaf_size, depth + 1);
    m_nodes[index].right = static_cast<std::uint32_t>(right);
    return index;
}

} // namespace kumite
