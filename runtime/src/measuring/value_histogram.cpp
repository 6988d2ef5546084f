#include "kumite/runtime/value_histogram.h"

#include <algorithm>
#include <cmath>

namespace kumite {

ValueHistogram::ValueHistogram(double lowest, double highest, double relative_width)
    : m_lowest(lowest), m_log_step(std::log1p(relative_width)) {
    const int bins = 2 + static_cast<int>(std::ceil(std::log(highest / lowest) / m_log_step));
    m_bins.assign(std::size_t(std::max(bins, 2)), 0);
}

void ValueHistogram::add(double value) {
    if (!std::isfinite(value)) return;
    std::size_t bin = 0;
    if (value >= m_lowest) bin = std::min(m_bins.size() - 1, std::size_t(1 + std::floor(std::log(value / m_lowest) / m_log_step)));
    ++m_bins[bin];
    m_max = m_count ? std::max(m_max, value) : value;
    ++m_count;
    m_sum += value;
    m_last = value;
}

double ValueHistogram::quantile(double q) const {
    if (m_count == 0) return 0.0;
    const std::int64_t rank = std::clamp<std::int64_t>(std::int64_t(std::ceil(std::clamp(q, 0.0, 1.0) * double(m_count))), 1, m_count);
    std::int64_t seen = 0;
    for (std::size_t bin = 0; bin < m_bins.size(); ++bin) {
        seen += m_bins[bin];
        if (seen < rank) continue;
        if (bin == 0) return 0.0;
        if (bin + 1 == m_bins.size()) return m_max;
        return std::min(m_max, m_lowest * std::exp(m_log_step * double(bin)));
    }
    return m_max;
}

} // namespace kumite
