#pragma once
/// \file
/// A triple buffer: one writer thread publishes values, one reader thread
/// takes the newest, and neither ever waits for the other. Three slots: the
/// writer fills its back slot and swaps it with the shared one (marking it
/// fresh); the reader swaps its front slot with the shared one when it is
/// fresh. The index exchange is one atomic operation, so a slot is only ever
/// touched by one thread at a time.

#include <array>
#include <atomic>

namespace colonosim::app {

template <class T>
class TripleBuffer {
public:
    /// Writer: the slot to fill (its old content is stale; overwrite all of it).
    T& back() { return m_slots[m_back]; }
    /// Writer: hands the back slot to the reader.
    void publish() { m_back = m_shared.exchange(m_back | kFresh, std::memory_order_acq_rel) & kIndex; }

    /// Reader: takes the newest published value, if any came since the last call.
    bool fetch()
    {
        if ((m_shared.load(std::memory_order_acquire) & kFresh) == 0) {
            return false;
        }
        m_front = m_shared.exchange(m_front, std::memory_order_acq_rel) & kIndex;
        return true;
    }
    /// Reader: the value taken by the last successful fetch.
    [[nodiscard]] const T& front() const { return m_slots[m_front]; }

private:
    static constexpr unsigned kIndex = 3U;
    static constexpr unsigned kFresh = 4U;
    std::array<T, 3> m_slots{};
    std::atomic<unsigned> m_shared{1U};
    unsigned m_back = 0U;   ///< writer's
    unsigned m_front = 2U;  ///< reader's
};

}  // namespace colonosim::app
