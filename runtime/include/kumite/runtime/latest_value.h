#pragma once
// A single-producer, single-consumer mailbox that keeps only the newest value: a triple buffer. The producer
// fills its own slot, then swaps it with the middle one in one atomic exchange; the consumer swaps the middle
// one for its own when it holds something new. Neither side ever waits for the other or takes a lock, and
// nothing is allocated after construction — what a frame loop may do.

#include <array>
#include <atomic>
#include <cstdint>

namespace kumite {

template <class T>
class LatestValue {
public:
    // Producer: the slot to fill, then publish() it. A value published before the consumer took the previous one
    // replaces it.
    T& slot() { return m_slots[m_back]; }
    void publish() { m_back = m_middle.exchange(m_back | k_fresh, std::memory_order_acq_rel) & k_index; }

    // Consumer: swaps in the newest published value if there is one; returns whether it did. The value is then
    // in current() until the next successful take().
    bool take() {
        if ((m_middle.load(std::memory_order_relaxed) & k_fresh) == 0) return false;
        m_front = m_middle.exchange(m_front, std::memory_order_acq_rel) & k_index;
        return true;
    }
    const T& current() const { return m_slots[m_front]; }

private:
    static constexpr std::uint8_t k_fresh = 4;
    static constexpr std::uint8_t k_index = 3;
    std::array<T, 3> m_slots{};
    std::uint8_t m_back = 0;  // producer's
    std::uint8_t m_front = 1; // consumer's
    std::atomic<std::uint8_t> m_middle{2};
};

} // namespace kumite
