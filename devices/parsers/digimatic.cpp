#include "devices/parsers/digimatic.h"

#include <cmath>
#include <stdexcept>

namespace tt::devices {

namespace {

std::string nibbleText(std::span<const std::uint8_t> nibbles) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string text;
    for (const std::uint8_t n : nibbles)
        text.push_back(n < 16 ? kHex[n] : '?');
    return text;
}

int hexValue(std::uint8_t c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

}  // namespace

ParseResult<DigimaticReading> decodeDigimatic(std::span<const std::uint8_t> nibbles) {
    using Result = ParseResult<DigimaticReading>;
    if (nibbles.size() != kDigimaticNibbles)
        return Result::failure("Digimatic frame has " + std::to_string(nibbles.size()) + " nibbles, expected 13");
    const std::string text = nibbleText(nibbles);
    for (std::size_t i = 0; i < 4; ++i)
        if (nibbles[i] != 0xF) return Result::failure("Digimatic frame " + text + " does not start with FFFF");
    if (nibbles[4] != 0 && nibbles[4] != 8)
        return Result::failure("Digimatic frame " + text + " has sign nibble " + text.substr(4, 1) +
                               ", expected 0 or 8");
    double magnitude = 0.0;
    for (std::size_t i = 5; i < 11; ++i) {
        if (nibbles[i] > 9)
            return Result::failure("Digimatic frame " + text + " has digit " + text.substr(i, 1) + " at d" +
                                   std::to_string(i + 1) + ", expected 0 to 9");
        magnitude = magnitude * 10.0 + nibbles[i];
    }
    if (nibbles[11] > 5)
        return Result::failure("Digimatic frame " + text + " has decimal position " + text.substr(11, 1) +
                               ", expected 0 to 5");
    DigimaticReading reading;
    switch (nibbles[12]) {
        case 0:
        case 2:
        case 3:
        case 4:
            reading.unit = LengthUnit::Millimetre;
            break;
        case 1:
        case 5:
        case 6:
        case 7:
            reading.unit = LengthUnit::Inch;
            break;
        default:
            return Result::failure("Digimatic frame " + text + " has unit nibble " + text.substr(12, 1) +
                                   ", expected 0 (mm) or 1 (inch)");
    }
    switch (nibbles[12]) {
        case 2:
        case 5:
            reading.judgement = DigimaticJudgement::AboveLimit;
            break;
        case 3:
        case 6:
            reading.judgement = DigimaticJudgement::Go;
            break;
        case 4:
        case 7:
            reading.judgement = DigimaticJudgement::BelowLimit;
            break;
        default:
            break;
    }
    reading.decimals = nibbles[11];
    reading.value = (nibbles[4] == 8 ? -1.0 : 1.0) * magnitude / std::pow(10.0, reading.decimals);
    return Result::success(reading);
}

DigimaticNibbles encodeDigimatic(double value, int decimals, LengthUnit unit) {
    if (!std::isfinite(value)) throw std::invalid_argument("Digimatic: the value is not a finite number");
    if (decimals < 0 || decimals > 5) throw std::invalid_argument("Digimatic: decimals must be 0 to 5");
    const double scaled = std::round(std::fabs(value) * std::pow(10.0, decimals));
    if (scaled > 999999.0)
        throw std::invalid_argument("Digimatic: " + std::to_string(value) + " does not fit six digits with " +
                                    std::to_string(decimals) + " decimals");
    auto digits = static_cast<long>(scaled);
    DigimaticNibbles nibbles{};
    for (std::size_t i = 0; i < 4; ++i)
        nibbles[i] = 0xF;
    nibbles[4] = (value < 0.0 && digits != 0) ? 8 : 0;
    for (std::size_t i = 10; i >= 5; --i) {
        nibbles[i] = static_cast<std::uint8_t>(digits % 10);
        digits /= 10;
    }
    nibbles[11] = static_cast<std::uint8_t>(decimals);
    nibbles[12] = unit == LengthUnit::Inch ? 1 : 0;
    return nibbles;
}

DigimaticFramer::DigimaticFramer(DigimaticEncoding encoding) : m_encoding(encoding) {}

void DigimaticFramer::reset() {
    m_count = 0;
    m_lineLength = 0;
    m_lineBroken = false;
}

void DigimaticFramer::dropPending() {
    m_discarded += m_count;
    m_count = 0;
}

void DigimaticFramer::takeNibble(std::uint8_t nibble, std::vector<DigimaticNibbles>& frames) {
    if (m_count < 4) {
        // Header: four 0xF in a row; anything else restarts the hunt.
        if (nibble == 0xF) {
            m_frame[m_count++] = nibble;
        } else {
            dropPending();
            ++m_discarded;
        }
        return;
    }
    if (nibble == 0xF) {
        // Inside a frame 0xF can only be the start of the next header: the frame was cut short.
        if (m_count == 4) {  // five or more F: keep the last four as the header
            ++m_discarded;
            return;
        }
        dropPending();
        m_frame[m_count++] = nibble;
        return;
    }
    m_frame[m_count++] = nibble;
    if (m_count == kDigimaticNibbles) {
        frames.push_back(m_frame);
        m_count = 0;
    }
}

std::vector<DigimaticNibbles> DigimaticFramer::feed(std::span<const std::uint8_t> bytes) {
    std::vector<DigimaticNibbles> frames;
    for (const std::uint8_t byte : bytes) {
        if (m_encoding == DigimaticEncoding::RawNibbles) {
            if (byte > 0x0F) {
                dropPending();
                ++m_discarded;
                continue;
            }
            takeNibble(byte, frames);
            continue;
        }
        // Hex text: exactly 13 hex characters per CR-terminated line.
        if (byte == '\n') continue;
        if (byte == '\r') {
            if (!m_lineBroken && m_count == kDigimaticNibbles)
                frames.push_back(m_frame);
            else if (m_lineLength > 0)
                m_discarded += m_lineLength;
            reset();
            continue;
        }
        ++m_lineLength;
        const int v = hexValue(byte);
        if (v < 0 || m_count == kDigimaticNibbles) {
            m_lineBroken = true;
            continue;
        }
        if (!m_lineBroken) m_frame[m_count++] = static_cast<std::uint8_t>(v);
    }
    return frames;
}

std::string digimaticHexLine(const DigimaticNibbles& nibbles) {
    return nibbleText(nibbles) + "\r";
}

}  // namespace tt::devices
