#pragma once
// A running summary of a long series of values in fixed memory (a VR session runs for hours; keeping every frame's
// time grew resident memory by ~29 KB a minute): count, exact mean, last and max, and quantiles from a histogram
// of log-spaced bins, each `relative_width` wide (1%: a quantile is off by at most 1%). Values below `lowest` share
// the first bin (reported as 0); above `highest`, the last (reported as the max). The bins are allocated by the
// constructor; add() never allocates.

#include <cstdint>
#include <vector>

namespace kumite {

class ValueHistogram {
public:
    ValueHistogram(double lowest, double highest, double relative_width = 0.01);

    void add(double value);

    std::int64_t count() const { return m_count; }
    bool empty() const { return m_count == 0; }
    double mean() const { return m_count ? m_sum / double(m_count) : 0.0; }
    double max() const { return m_count ? m_max : 0.0; }
    double last() const { return m_last; }
    // The value at quantile q (0..1): the upper edge of the bin that holds it, at most the max; 0 when empty.
    double quantile(double q) const;

private:
    double m_lowest, m_log_step;
    std::vector<std::int64_t> m_bins; // [0]: below lowest; [i >= 1]: lowest * step^(i-1) .. lowest * step^i
    std::int64_t m_count = 0;
    double m_sum = 0.0, m_max = 0.0, m_last = 0.0;
};

} // namespace kumite
