// libFuzzer target: Modbus register decoding, encoding and read planning on arbitrary input.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "devices/parsers/modbus_registers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::devices::modbus;
    if (size < 3) return 0;
    const auto type = static_cast<RegisterType>(data[0] % 5);
    const auto order = (data[1] & 1) ? WordOrder::LowWordFirst : WordOrder::HighWordFirst;
    static constexpr double kScales[] = {1.0, 0.01, 0.001, 0.0001, -0.5, 1e-300, 1e300, 0.0};
    const double scale = kScales[data[2] % 8];
    std::vector<std::uint16_t> words;
    for (std::size_t i = 3; i + 1 < size; i += 2)
        words.push_back(static_cast<std::uint16_t>(data[i] << 8 | data[i + 1]));
    const auto value = decodeValue(words, type, order, scale);
    if (value && !std::isfinite(value.value())) __builtin_trap();  // refused, never passed on
    if (value) {
        try {
            const auto back = encodeValue(value.value(), type, order, scale);
            if (back.size() != registerCount(type)) __builtin_trap();
        } catch (const std::invalid_argument&) {
        }
    }
    // Doubles from the bytes through the encoder.
    if (size >= 11) {
        double v = 0.0;
        std::memcpy(&v, data + 3, sizeof v);
        try {
            (void)encodeValue(v, type, order, scale);
        } catch (const std::invalid_argument&) {
        }
    }
    // A register map from the bytes.
    std::vector<RegisterSpec> specs;
    for (std::size_t i = 3; i + 3 < size && specs.size() < 16; i += 4)
        specs.push_back({"v", (data[i] & 1) ? RegisterTable::Input : RegisterTable::Holding,
                         static_cast<std::uint16_t>(data[i + 1] << 8 | data[i + 2]),
                         static_cast<RegisterType>(data[i + 3] % 5), order, 1.0});
    try {
        const auto blocks = planReads(specs, 1 + data[1] % 125);
        for (const ReadBlock& b : blocks) {
            if (b.count == 0 || b.count > 125) __builtin_trap();
            const std::vector<std::uint16_t> zeros(b.count, 0);
            for (const RegisterSpec& s : specs)
                (void)extractValue(s, b, zeros);
        }
    } catch (const std::invalid_argument&) {
    }
    (void)modbusExceptionName(data[0]);
    return 0;
}
