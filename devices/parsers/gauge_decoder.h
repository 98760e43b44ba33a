#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devices/parsers/digimatic.h"
#include "devices/parsers/length_unit.h"
#include "devices/parsers/line_framer.h"

namespace tt::devices {

/// Output format of a gauge's data cable.
enum class GaugeFormat {
    Ascii,             ///< "01A+00026.812" CR (gauge_ascii.h)
    DigimaticNibbles,  ///< 13 raw nibbles (digimatic.h)
    DigimaticHex,      ///< 13 hexadecimal characters + CR
};

/// One frame from the gauge, decoded and checked.
struct GaugeDecoded {
    std::optional<double> diameterMm;  ///< set when the reading is accepted (converted to mm)
    double value = 0.0;                ///< the value as sent, in `unit`
    LengthUnit unit = LengthUnit::Millimetre;
    int decimals = 0;
    std::string error;  ///< why the frame was refused (malformed, wrong unit); empty when accepted
};

/// Turns the gauge's byte stream into diameters. Units are converted, never guessed: the unit
/// comes from the frame (Digimatic d13, an ASCII suffix) or, for ASCII without a suffix, from
/// the unit the instrument is set to (a setting); a reading whose unit is not the job's unit is
/// refused with a message, as is a malformed frame or a value that cannot be a diameter.
class GaugeDecoder {
public:
    GaugeDecoder(GaugeFormat format, LengthUnit instrumentUnit, LengthUnit jobUnit);

    /// Appends bytes; returns one result per complete frame, oldest first.
    std::vector<GaugeDecoded> feed(std::span<const std::uint8_t> bytes);
    /// Forgets a partly received frame.
    void reset();

    std::uint64_t accepted() const { return m_accepted; }
    std::uint64_t malformed() const { return m_malformed; }
    std::uint64_t refused() const { return m_refused; }
    /// Bytes that belonged to no frame (overlong lines, noise between Digimatic frames).
    std::uint64_t discardedBytes() const;

private:
    GaugeDecoded check(double value, int decimals, LengthUnit unit);

    GaugeFormat m_format;
    LengthUnit m_instrumentUnit;
    LengthUnit m_jobUnit;
    LineFramer m_lines{32};
    DigimaticFramer m_digimatic;
    std::uint64_t m_accepted = 0;
    std::uint64_t m_malformed = 0;
    std::uint64_t m_refused = 0;
};

}  // namespace tt::devices
