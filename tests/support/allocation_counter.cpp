#include "support/allocation_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

// A breakpoint target: in gdb, `break kumite_allocation_while_counting` and ask for a backtrace.
extern "C" __attribute__((noinline)) void kumite_allocation_while_counting(std::size_t size) { asm volatile("" : : "r"(size) : "memory"); }

void* counted_allocation(std::size_t size) {
    if (g_counting.load(std::memory_order_relaxed)) {
        g_allocations.fetch_add(1, std::memory_order_relaxed);
        kumite_allocation_while_counting(size);
    }
    if (void* pointer = std::malloc(size == 0 ? 1 : size)) return pointer;
    throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t size) { return counted_allocation(size); }
void* operator new[](std::size_t size) { return counted_allocation(size); }
void operator delete(void* pointer) noexcept { std::free(pointer); }
void operator delete[](void* pointer) noexcept { std::free(pointer); }
void operator delete(void* pointer, std::size_t) noexcept { std::free(pointer); }
void operator delete[](void* pointer, std::size_t) noexcept { std::free(pointer); }

namespace kumite::test {

void allocation_counting(bool on) { g_counting.store(on, std::memory_order_relaxed); }
long allocations_counted() { return g_allocations.load(std::memory_order_relaxed); }
void allocation_count_reset() { g_allocations.store(0, std::memory_order_relaxed); }

} // namespace kumite::test
