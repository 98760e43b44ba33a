#include "devices/parsers/gauge_decoder.h"

#include <cmath>
#include <cstdio>

#include "devices/parsers/gauge_ascii.h"

namespace tt::devices {

namespace {

std::string valueText(double value, int decimals, LengthUnit unit) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f %s", decimals, value, std::string(unitSymbol(unit)).c_str());
    return text;
}

}  // namespace

GaugeDecoder::GaugeDecoder(GaugeFormat format, LengthUnit instrumentUnit, LengthUnit jobUnit)
    : m_format(format),
      m_instrumentUnit(instrumentUnit),
      m_jobUnit(jobUnit),
      m_digimatic(format == GaugeFormat::DigimaticHex ? DigimaticEncoding::HexText : DigimaticEncoding::RawNibbles) {}

void GaugeDecoder::reset() {
    m_lines.reset();
    m_digimatic.reset();
}

std::uint64_t GaugeDecoder::discardedBytes() const {
    return m_format == GaugeFormat::Ascii ? m_lines.overlongLines() : m_digimatic.discardedBytes();
}

GaugeDecoded GaugeDecoder::check(double value, int decimals, LengthUnit unit) {
    GaugeDecoded d;
    d.value = value;
    d.unit = unit;
    d.decimals = decimals;
    if (unit != m_jobUnit) {
        ++m_refused;
        d.error = "reading " + valueText(value, decimals, unit) + " refused: the gauge sends " +
                  std::string(unitName(unit)) + " but the job is in " + std::string(unitName(m_jobUnit)) +
                  "; set the micrometer to " + std::string(unitSymbol(m_jobUnit));
        return d;
    }
    if (!(value > 0.0)) {
        ++m_refused;
        d.error = "reading " + valueText(value, decimals, unit) + " refused: not a diameter (zero or negative)";
        return d;
    }
    ++m_accepted;
    d.diameterMm = toMillimetres(value, unit);
    return d;
}

std::vector<GaugeDecoded> GaugeDecoder::feed(std::span<const std::uint8_t> bytes) {
    std::vector<GaugeDecoded> out;
    if (m_format == GaugeFormat::Ascii) {
        for (const std::string& line : m_lines.feed(bytes)) {
            const auto frame = parseAsciiGaugeLine(line);
            if (!frame) {
                ++m_malformed;
                GaugeDecoded d;
                d.error = frame.error();
                out.push_back(d);
                continue;
            }
            out.push_back(check(frame->value, frame->decimals, frame->unit.value_or(m_instrumentUnit)));
        }
        return out;
    }
    for (const DigimaticNibbles& nibbles : m_digimatic.feed(bytes)) {
        const auto reading = decodeDigimatic(nibbles);
        if (!reading) {
            ++m_malformed;
            GaugeDecoded d;
            d.error = reading.error();
            out.push_back(d);
            continue;
        }
        out.push_back(check(reading->value, reading->decimals, reading->unit));
    }
    return out;
}

}  // namespace tt::devices
