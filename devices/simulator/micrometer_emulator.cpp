#include "devices/simulator/micrometer_emulator.h"

#include <cmath>

#include "devices/parsers/digimatic.h"
#include "devices/parsers/gauge_ascii.h"

namespace tt::devices {

MicrometerEmulator::MicrometerEmulator(Format format, LengthUnit unit, int decimals)
    : m_format(format), m_unit(unit), m_decimals(decimals), m_source([] { return 27.0; }) {}

void MicrometerEmulator::setSource(std::function<double()> diameterMm) {
    if (diameterMm) m_source = std::move(diameterMm);
}

std::vector<std::uint8_t> MicrometerEmulator::pressDataButton() {
    const double mm = m_source();
    const double shown = m_unit == LengthUnit::Inch ? mm / kMillimetresPerInch : mm;
    const double scale = std::pow(10.0, m_decimals);
    m_lastValue = std::round(shown * scale) / scale;
    ++m_sent;
    const bool corrupt = m_corrupt > 0;
    if (corrupt) --m_corrupt;
    if (m_format == Format::Ascii) {
        std::string line = formatAsciiGaugeLine(m_lastValue, m_decimals);
        if (corrupt) line[6] = 'X';  // a character error on the line
        return {line.begin(), line.end()};
    }
    DigimaticNibbles nibbles = encodeDigimatic(m_lastValue, m_decimals, m_unit);
    if (corrupt) nibbles[7] = 0xB;  // not a decimal digit
    if (m_format == Format::DigimaticNibbles) return {nibbles.begin(), nibbles.end()};
    const std::string hex = digimaticHexLine(nibbles);
    return {hex.begin(), hex.end()};
}

std::vector<std::uint8_t> MicrometerEmulator::receive(std::span<const std::uint8_t> bytes) {
    std::vector<std::uint8_t> out;
    if (m_request.empty()) return out;
    m_received.append(bytes.begin(), bytes.end());
    for (std::size_t at = m_received.find(m_request); at != std::string::npos; at = m_received.find(m_request)) {
        m_received.erase(0, at + m_request.size());
        const auto reading = pressDataButton();
        out.insert(out.end(), reading.begin(), reading.end());
    }
    if (m_received.size() > 256) m_received.erase(0, m_received.size() - m_request.size());
    return out;
}

}  // namespace tt::devices
