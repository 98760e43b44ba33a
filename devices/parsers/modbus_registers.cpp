#include "devices/parsers/modbus_registers.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>

namespace tt::devices::modbus {

namespace {

std::uint32_t join(std::span<const std::uint16_t> words, WordOrder order) {
    const std::uint32_t first = words[0];
    const std::uint32_t second = words[1];
    return order == WordOrder::HighWordFirst ? (first << 16) | second : (second << 16) | first;
}

std::vector<std::uint16_t> split(std::uint32_t raw, WordOrder order) {
    const auto high = static_cast<std::uint16_t>(raw >> 16);
    const auto low = static_cast<std::uint16_t>(raw & 0xFFFF);
    return order == WordOrder::HighWordFirst ? std::vector<std::uint16_t>{high, low}
                                             : std::vector<std::uint16_t>{low, high};
}

}  // namespace

std::size_t registerCount(RegisterType type) {
    return (type == RegisterType::Int16 || type == RegisterType::UInt16) ? 1 : 2;
}

std::string_view typeKey(RegisterType type) {
    switch (type) {
        case RegisterType::Int16:
            return "int16";
        case RegisterType::UInt16:
            return "uint16";
        case RegisterType::Int32:
            return "int32";
        case RegisterType::UInt32:
            return "uint32";
        case RegisterType::Float32:
            return "float32";
    }
    return "int16";
}

std::optional<RegisterType> typeFromKey(std::string_view key) {
    for (auto t :
         {RegisterType::Int16, RegisterType::UInt16, RegisterType::Int32, RegisterType::UInt32, RegisterType::Float32})
        if (typeKey(t) == key) return t;
    return std::nullopt;
}

std::string_view wordOrderKey(WordOrder order) {
    return order == WordOrder::HighWordFirst ? "high-first" : "low-first";
}

std::optional<WordOrder> wordOrderFromKey(std::string_view key) {
    if (key == "high-first") return WordOrder::HighWordFirst;
    if (key == "low-first") return WordOrder::LowWordFirst;
    return std::nullopt;
}

std::string_view tableKey(RegisterTable table) {
    return table == RegisterTable::Holding ? "holding" : "input";
}

std::optional<RegisterTable> tableFromKey(std::string_view key) {
    if (key == "holding") return RegisterTable::Holding;
    if (key == "input") return RegisterTable::Input;
    return std::nullopt;
}

ParseResult<double> decodeValue(std::span<const std::uint16_t> words, RegisterType type, WordOrder order,
                                double scale) {
    if (words.size() != registerCount(type))
        return ParseResult<double>::failure(std::string(typeKey(type)) + " needs " +
                                            std::to_string(registerCount(type)) + " registers, got " +
                                            std::to_string(words.size()));
    if (!std::isfinite(scale) || scale == 0.0)
        return ParseResult<double>::failure("register scale must be a finite, non-zero number");
    double raw = 0.0;
    switch (type) {
        case RegisterType::Int16:
            raw = static_cast<std::int16_t>(words[0]);
            break;
        case RegisterType::UInt16:
            raw = words[0];
            break;
        case RegisterType::Int32:
            raw = static_cast<std::int32_t>(join(words, order));
            break;
        case RegisterType::UInt32:
            raw = join(words, order);
            break;
        case RegisterType::Float32: {
            const float f = std::bit_cast<float>(join(words, order));
            if (!std::isfinite(f))
                return ParseResult<double>::failure(std::string("float32 registers hold ") +
                                                    (std::isnan(f) ? "NaN" : "an infinite value"));
            raw = f;
            break;
        }
    }
    const double value = raw * scale;
    if (!std::isfinite(value)) return ParseResult<double>::failure("scaled register value overflows");
    return ParseResult<double>::success(value);
}

std::vector<std::uint16_t> encodeValue(double value, RegisterType type, WordOrder order, double scale) {
    if (!std::isfinite(value)) throw std::invalid_argument("register value is not a finite number");
    if (!std::isfinite(scale) || scale == 0.0)
        throw std::invalid_argument("register scale must be a finite, non-zero number");
    const double raw = value / scale;
    auto checkRange = [&](double lo, double hi) {
        const double r = std::round(raw);
        if (r < lo || r > hi)
            throw std::invalid_argument(std::to_string(value) + " / scale " + std::to_string(scale) + " = " +
                                        std::to_string(r) + " does not fit " + std::string(typeKey(type)));
        return r;
    };
    switch (type) {
        case RegisterType::Int16:
            return {static_cast<std::uint16_t>(static_cast<std::int16_t>(checkRange(-32768.0, 32767.0)))};
        case RegisterType::UInt16:
            return {static_cast<std::uint16_t>(checkRange(0.0, 65535.0))};
        case RegisterType::Int32:
            return split(static_cast<std::uint32_t>(static_cast<std::int32_t>(checkRange(-2147483648.0, 2147483647.0))),
                         order);
        case RegisterType::UInt32:
            return split(static_cast<std::uint32_t>(checkRange(0.0, 4294967295.0)), order);
        case RegisterType::Float32: {
            if (std::fabs(raw) > 3.4e38) throw std::invalid_argument("register value does not fit float32");
            return split(std::bit_cast<std::uint32_t>(static_cast<float>(raw)), order);
        }
    }
    return {};
}

std::vector<ReadBlock> planReads(std::span<const RegisterSpec> specs, std::size_t maxRegisters) {
    if (maxRegisters == 0 || maxRegisters > 125) throw std::invalid_argument("a Modbus read covers 1 to 125 registers");
    std::map<RegisterTable, std::vector<std::pair<std::uint32_t, std::uint32_t>>> ranges;  // [start, end)
    for (const RegisterSpec& spec : specs) {
        const std::uint32_t end = spec.address + static_cast<std::uint32_t>(registerCount(spec.type));
        if (end > 65536)
            throw std::invalid_argument(spec.name + ": register " + std::to_string(spec.address) + " with type " +
                                        std::string(typeKey(spec.type)) + " runs past address 65535");
        ranges[spec.table].emplace_back(spec.address, end);
    }
    std::vector<ReadBlock> blocks;
    for (auto& entry : ranges) {
        const RegisterTable table = entry.first;
        auto& list = entry.second;
        std::sort(list.begin(), list.end());
        std::uint32_t start = list.front().first;
        std::uint32_t end = list.front().second;
        auto flush = [&] {
            blocks.push_back({table, static_cast<std::uint16_t>(start), static_cast<std::uint16_t>(end - start)});
        };
        for (std::size_t i = 1; i < list.size(); ++i) {
            const std::uint32_t newEnd = std::max(end, list[i].second);
            if (newEnd - start <= maxRegisters) {
                end = newEnd;
            } else {
                flush();
                start = list[i].first;
                end = list[i].second;
            }
        }
        flush();
    }
    return blocks;
}

ParseResult<double> extractValue(const RegisterSpec& spec, const ReadBlock& block,
                                 std::span<const std::uint16_t> blockWords) {
    const std::size_t count = registerCount(spec.type);
    if (spec.table != block.table || spec.address < block.start ||
        spec.address + count > static_cast<std::size_t>(block.start) + block.count)
        return ParseResult<double>::failure(spec.name + ": register " + std::to_string(spec.address) +
                                            " is not in the block read");
    if (blockWords.size() != block.count)
        return ParseResult<double>::failure(spec.name + ": the reply has " + std::to_string(blockWords.size()) +
                                            " registers, expected " + std::to_string(block.count));
    const auto result =
        decodeValue(blockWords.subspan(spec.address - block.start, count), spec.type, spec.order, spec.scale);
    if (!result)
        return ParseResult<double>::failure(spec.name + " (register " + std::to_string(spec.address) +
                                            "): " + result.error());
    return result;
}

std::string modbusExceptionName(std::uint8_t code) {
    switch (code) {
        case 0x01:
            return "illegal function";
        case 0x02:
            return "illegal data address";
        case 0x03:
            return "illegal data value";
        case 0x04:
            return "server device failure";
        case 0x05:
            return "acknowledge";
        case 0x06:
            return "server device busy";
        case 0x08:
            return "memory parity error";
        case 0x0A:
            return "gateway path unavailable";
        case 0x0B:
            return "gateway target device failed to respond";
        default:
            break;
    }
    return "exception code " + std::to_string(code);
}

}  // namespace tt::devices::modbus
