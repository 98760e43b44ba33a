#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/parsers/length_unit.h"
#include "devices/parsers/parse_result.h"

namespace tt::devices {

/// The 13-nibble Digimatic data frame that Mitutoyo instruments send to data loggers and
/// mini-processors (d1..d13, each a 4-bit digit; sources: Mitutoyo LSM-6200 manual No. 99MBC095A
/// section 6.2.1.5, measuring projector manual No. 99MBA043A section 6, QM-Height manual
/// No. 99MAF600B section 6.2.1):
///   d1..d4  0xF each (header)
///   d5      sign: 0 = '+', 8 = '-'
///   d6..d11 six BCD digits of the value, most significant first
///   d12     decimal point position: the value is d6..d11 x 10^-d12, 0..5
///   d13     unit: 0 = mm, 1 = inch; loggers with limit judgement also send 2/3/4 = mm +NG/GO/-NG
///           and 5/6/7 = inch +NG/GO/-NG (LSM-6200 table)
/// Example: F F F F 0 2 1 0 7 6 5 4 0 = +21.0765 mm.
inline constexpr std::size_t kDigimaticNibbles = 13;
using DigimaticNibbles = std::array<std::uint8_t, kDigimaticNibbles>;

/// Limit judgement that some loggers send in d13.
enum class DigimaticJudgement { None, AboveLimit, Go, BelowLimit };

/// A decoded Digimatic reading.
struct DigimaticReading {
    double value = 0.0;  ///< signed value in `unit`
    int decimals = 0;    ///< digits after the decimal point (d12)
    LengthUnit unit = LengthUnit::Millimetre;
    DigimaticJudgement judgement = DigimaticJudgement::None;
};

/// Decodes one frame of 13 nibbles (values 0..15). Refuses a wrong header, sign, digit,
/// decimal position or unit, with the reason.
ParseResult<DigimaticReading> decodeDigimatic(std::span<const std::uint8_t> nibbles);

/// Encodes a value as the instrument would: |value| x 10^decimals rounded must fit six digits.
/// Throws std::invalid_argument otherwise.
DigimaticNibbles encodeDigimatic(double value, int decimals, LengthUnit unit);

/// How the nibbles travel over the serial line from the Digimatic interface.
enum class DigimaticEncoding {
    RawNibbles,  ///< one byte per nibble, value in the low four bits (0x00..0x0F)
    HexText,     ///< the 13 nibbles as hexadecimal characters, then CR ("FFFF02107654" "0" CR)
};

/// Cuts a serial byte stream into 13-nibble frames. Raw nibbles synchronise on the four 0xF
/// header nibbles (no other nibble of a valid frame is 0xF); hex text is line based.
/// Bytes that cannot belong to a frame are dropped and counted.
class DigimaticFramer {
public:
    explicit DigimaticFramer(DigimaticEncoding encoding);

    /// Appends bytes; returns every complete frame (not yet decoded), oldest first.
    std::vector<DigimaticNibbles> feed(std::span<const std::uint8_t> bytes);
    /// Forgets a partly received frame.
    void reset();
    /// Bytes dropped while hunting for a frame.
    std::uint64_t discardedBytes() const { return m_discarded; }

private:
    void takeNibble(std::uint8_t nibble, std::vector<DigimaticNibbles>& frames);
    void dropPending();

    DigimaticEncoding m_encoding;
    DigimaticNibbles m_frame{};
    std::size_t m_count = 0;
    std::size_t m_lineLength = 0;
    bool m_lineBroken = false;
    std::uint64_t m_discarded = 0;
};

/// The frame as the 13 hexadecimal characters of the hex-text encoding plus CR (for emulators).
std::string digimaticHexLine(const DigimaticNibbles& nibbles);

}  // namespace tt::devices
