#pragma once
/// \file
/// Hands the latest value from one producer thread to one consumer thread
/// without locks: three slots, the producer writes the back one and swaps it
/// with the middle one; the consumer swaps the middle one with its front one
/// when the middle is marked fresh. Neither side ever waits.

#include <atomic>
#include <cstdint>

namespace colonosim::devices {

template <class T>
class TripleBuffer {
public:
    /// Producer: publish a new value.
    void write(const T& value)
    {
        m_slots[m_back] = value;
        const std::uint8_t previous = m_middle.exchange(static_cast<std::uint8_t>(m_back | kFresh));
        m_back = previous & kIndex;
    }
    /// Consumer: true (and `out` set) when a value newer than the last read exists.
    bool read(T& out)
    {
        if ((m_middle.load() & kFresh) == 0) {
            return false;
        }
        const std::uint8_t previous = m_middle.exchange(m_front);
        m_front = previous & kIndex;
        out = m_slots[m_front];
        return true;
    }

private:
    static constexpr std::uint8_t kFresh = 4;
    static constexpr std::uint8_t kIndex = 3;
    T m_slots[3]{};
    std::uint8_t m_back = 0;                ///< producer's
    std::atomic<std::uint8_t> m_middle{1};  ///< shared
    std::uint8_t m_front = 2;               ///< consumer's
};

}  // namespace colonosim::devices
