#pragma once
// Counts heap allocations (global operator new) made while counting is on. Link support/allocation_counter.cpp
// into an executable to replace its global allocation functions; the frame loop's promise of no allocation
// (STYLE.md 5) is checked with it in allocation_tests and reported by the benchmarks.

namespace kumite::test {

void allocation_counting(bool on);
long allocations_counted(); // since the last reset
void allocation_count_reset();

// Counts over a scope: AllocationScope scope; ...; scope.count().
class AllocationScope {
public:
    AllocationScope() { allocation_count_reset(), allocation_counting(true); }
    ~AllocationScope() { allocation_counting(false); }
    long count() const { return allocations_counted(); }
};

} // namespace kumite::test
