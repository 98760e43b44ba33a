#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "devices/parsers/length_unit.h"

namespace tt::devices {

/// A digital micrometer behind its data cable, emulated byte for byte: on the data button (or
/// when the configured request string arrives) it sends the displayed value in its output
/// format. Used by the simulator's gauge and, over a pseudo-terminal, by the tests of the
/// serial gauge plugin. Pure C++, no I/O.
class MicrometerEmulator {
public:
    enum class Format {
        Ascii,             ///< "01A+00026.812" CR
        DigimaticNibbles,  ///< 13 bytes, one nibble each
        DigimaticHex,      ///< 13 hexadecimal characters + CR
    };

    /// `unit`: what the instrument displays (values from the source are converted from mm).
    /// `decimals`: the display resolution (3 = 0.001 mm).
    MicrometerEmulator(Format format, LengthUnit unit = LengthUnit::Millimetre, int decimals = 3);

    /// The true diameter under the anvils for each reading, mm (default 27.000).
    void setSource(std::function<double()> diameterMm);
    /// Polled mode: the request that makes it send (empty: push only).
    void setRequest(std::string request) { m_request = std::move(request); }
    void setUnit(LengthUnit unit) { m_unit = unit; }
    /// The next `count` readings are sent malformed (a character or nibble out of range).
    void corruptNext(int count = 1) { m_corrupt += count; }

    /// The operator presses the data button: the bytes of one reading.
    std::vector<std::uint8_t> pressDataButton();
    /// Bytes from the host; answers each complete request with one reading.
    std::vector<std::uint8_t> receive(std::span<const std::uint8_t> bytes);

    /// The last value sent, in the instrument's unit.
    double lastValue() const { return m_lastValue; }
    int readingsSent() const { return m_sent; }

private:
    Format m_format;
    LengthUnit m_unit;
    int m_decimals;
    std::function<double()> m_source;
    std::string m_request;
    std::string m_received;
    int m_corrupt = 0;
    double m_lastValue = 0.0;
    int m_sent = 0;
};

}  // namespace tt::devices
