#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tt::devices {

/// Splits a serial byte stream into CR-terminated lines (the data-cable output of gauges:
/// `01A+00026.812` CR). A LF is ignored so CR LF also works. A line longer than the limit is
/// discarded up to its CR and counted, so a stream of garbage never grows memory.
class LineFramer {
public:
    /// `maxLength`: longest accepted line without its terminator, characters (> 0).
    explicit LineFramer(std::size_t maxLength = 64);

    /// Appends bytes and returns every line completed by them (without CR/LF), oldest first.
    /// Empty lines (a bare CR) are skipped.
    std::vector<std::string> feed(std::span<const std::uint8_t> bytes);

    /// Forgets a partly received line (after a reconnect).
    void reset();

    /// Lines thrown away because they exceeded maxLength.
    std::uint64_t overlongLines() const { return m_overlong; }
    /// Bytes waiting for their CR.
    std::size_t pending() const { return m_buffer.size(); }

private:
    std::size_t m_maxLength;
    std::string m_buffer;
    bool m_discarding = false;
    std::uint64_t m_overlong = 0;
};

}  // namespace tt::devices
