#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "devices/parsers/length_unit.h"
#include "devices/parsers/parse_result.h"

namespace tt::devices {

/// One reading in the ASCII output of digital micrometer data cables and USB/RS-232 input
/// tools, e.g. `01A+00026.812` followed by CR (9600 baud, 8 data bits, no parity, 1 stop bit).
///
/// Layout (Mitutoyo, QM-Height manual No. 99MAF600B, section 6.2.2 "USB data output
/// specifications": D1 code "0", D2 channel "1", D3 measurement item "A", D4 sign "+"/"-",
/// D5.. the value with a floating decimal point, then CR):
///   - two digits: code and channel number ("01"),
///   - one letter: measurement item ("A"),
///   - sign: '+' or '-',
///   - the value: 1..12 characters, digits with at most one '.', in the instrument's unit,
///   - optional unit suffix "mm" or "in" (some interfaces append it; the Mitutoyo format does not).
/// The format carries no unit of its own: when there is no suffix the caller must know the unit
/// the instrument is set to (never guess it from the number of decimals).
struct AsciiGaugeFrame {
    int channel = 1;                 ///< the two leading digits as a number (1 for "01")
    char item = 'A';                 ///< measurement item letter
    double value = 0.0;              ///< signed value in the instrument's unit
    int decimals = 0;                ///< digits after the decimal point (the instrument's resolution)
    std::optional<LengthUnit> unit;  ///< only when the line carries a unit suffix
};

/// Decodes one line (without its CR). Refuses anything that does not match the layout above,
/// with the reason.
ParseResult<AsciiGaugeFrame> parseAsciiGaugeLine(std::string_view line);

/// Encodes a reading as the instrument would send it, with the trailing CR: `value` rounded to
/// `decimals` places, the value field zero-padded to `width` characters (9 gives
/// `01A+00026.812`). Used by the emulated micrometer and the simulator. Throws
/// std::invalid_argument when the value does not fit the field.
std::string formatAsciiGaugeLine(double value, int decimals, int width = 9, int channel = 1, char item = 'A',
                                 std::optional<LengthUnit> unitSuffix = std::nullopt);

}  // namespace tt::devices
