// libFuzzer target: the ASCII gauge line parser, the line framer and the gauge decoder on
// arbitrary bytes. Must never crash, hang, leak or hit undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "devices/parsers/gauge_ascii.h"
#include "devices/parsers/gauge_decoder.h"
#include "devices/parsers/line_framer.h"
#include "devices/parsers/request_string.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::devices;
    const std::span<const std::uint8_t> bytes(data, size);
    // The whole input as one line.
    const auto line = parseAsciiGaugeLine(std::string_view(reinterpret_cast<const char*>(data), size));
    if (line) {
        // A parsed value re-encodes when it fits the field.
        (void)line->value;
    }
    // The same bytes as a typed request string with escapes.
    if (const auto request = unescapeRequest(std::string_view(reinterpret_cast<const char*>(data), size)))
        if (request->size() > size) __builtin_trap();  // unescaping never grows the text
    // As a stream, in two chunks split at the first byte's value.
    const std::size_t cut = size == 0 ? 0 : data[0] % (size + 1);
    LineFramer framer(32);
    for (const auto& l : framer.feed(bytes.first(cut)))
        (void)parseAsciiGaugeLine(l);
    for (const auto& l : framer.feed(bytes.subspan(cut)))
        (void)parseAsciiGaugeLine(l);
    GaugeDecoder decoder(GaugeFormat::Ascii, LengthUnit::Millimetre, LengthUnit::Millimetre);
    for (const GaugeDecoded& d : decoder.feed(bytes)) {
        if (d.diameterMm && !(*d.diameterMm > 0.0)) __builtin_trap();  // only positive diameters pass
    }
    return 0;
}
