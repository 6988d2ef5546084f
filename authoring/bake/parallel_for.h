#pragma once
// Runs body(index) for index in [0, count) on up to `jobs` threads (the caller's included). Each index runs
// exactly once; results written by index keep the output independent of the thread count and the timing.

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace kumite::bake {

template <class Body>
void parallel_for(int count, int jobs, Body&& body) {
    std::atomic<int> next{0};
    auto work = [&] {
        for (int index = next++; index < count; index = next++) body(index);
    };
    std::vector<std::thread> helpers;
    for (int j = 1; j < std::min(jobs, count); ++j) helpers.emplace_back(work);
    work();
    for (std::thread& helper : helpers) helper.join();
}

} // namespace kumite::bake
