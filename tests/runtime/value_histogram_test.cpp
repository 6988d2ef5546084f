// The fixed-memory summary a bout keeps of its frame times and strikes: quantiles within the bin width of the
// exact ones, exact count, mean and max, values out of range kept in the end bins.

#include "kumite/runtime/value_histogram.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace kumite;

TEST_CASE("value histogram: quantiles within 1% of the exact ones, count, mean and max exact", "[runtime]") {
    std::mt19937 random(3);
    std::lognormal_distribution<double> frame_time(std::log(20.0), 0.6);
    ValueHistogram histogram(0.1, 1e7);
    std::vector<double> values;
    double sum = 0.0;
    for (int i = 0; i < 200000; ++i) {
        const double value = frame_time(random);
        histogram.add(value);
        values.push_back(value);
        sum += value;
    }
    std::sort(values.begin(), values.end());
    CHECK(histogram.count() == 200000);
    CHECK(histogram.mean() == Approx(sum / 200000.0));
    CHECK(histogram.max() == values.back());
    CHECK(histogram.last() > 0.0);
    for (const double q : {0.01, 0.5, 0.95, 0.99, 0.999}) {
        const double exact = values[std::size_t(std::ceil(q * double(values.size()))) - 1];
        INFO("q " << q);
        CHECK(histogram.quantile(q) >= exact * (1.0 - 1e-12));
        CHECK(histogram.quantile(q) <= exact * 1.0101);
    }
    CHECK(histogram.quantile(1.0) == values.back());
}

TEST_CASE("value histogram: empty, zeros below the range and huge values above it", "[runtime]") {
    ValueHistogram histogram(1e-5, 10.0);
    CHECK(histogram.empty());
    CHECK(histogram.quantile(0.5) == 0.0);
    for (int i = 0; i < 10; ++i) histogram.add(0.0);
    histogram.add(50.0);
    histogram.add(std::numeric_limits<double>::quiet_NaN()); // ignored
    CHECK(histogram.count() == 11);
    CHECK(histogram.quantile(0.5) == 0.0);
    CHECK(histogram.quantile(1.0) == 50.0);
    CHECK(histogram.max() == 50.0);
}
