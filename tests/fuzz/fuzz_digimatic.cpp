// libFuzzer target: the Digimatic framer (raw nibbles and hex text) and frame decoder.
#include <cstddef>
#include <cstdint>
#include <span>

#include "devices/parsers/digimatic.h"
#include "devices/parsers/gauge_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::devices;
    if (size == 0) return 0;
    // First byte: the encoding; the rest: the serial stream.
    const bool hex = data[0] & 1;
    const std::span<const std::uint8_t> stream(data + 1, size - 1);
    DigimaticFramer framer(hex ? DigimaticEncoding::HexText : DigimaticEncoding::RawNibbles);
    for (const DigimaticNibbles& frame : framer.feed(stream)) {
        const auto reading = decodeDigimatic(frame);
        if (reading && (reading->decimals < 0 || reading->decimals > 5)) __builtin_trap();
    }
    // Any 13 bytes as a frame.
    if (stream.size() >= kDigimaticNibbles) (void)decodeDigimatic(stream.first(kDigimaticNibbles));
    (void)decodeDigimatic(stream);
    GaugeDecoder decoder(hex ? GaugeFormat::DigimaticHex : GaugeFormat::DigimaticNibbles, LengthUnit::Millimetre,
                         LengthUnit::Inch);
    for (const GaugeDecoded& d : decoder.feed(stream)) {
        if (d.diameterMm && d.unit != LengthUnit::Inch) __builtin_trap();  // a mm reading on an inch job passed
    }
    return 0;
}
