#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devices/parsers/parse_result.h"

/// Values in Modbus registers: how a drive or PLC lays out a number in 16-bit registers, the
/// read plan for a register map, and the names of Modbus exception codes. Pure functions; the
/// Qt SerialBus client that moves the registers lives in devices/modbus.
namespace tt::devices::modbus {

/// Register table of a value (Modbus application protocol v1.1b3, section 4.3).
enum class RegisterTable { Holding, Input };

/// How the number is stored.
enum class RegisterType { Int16, UInt16, Int32, UInt32, Float32 };

/// Order of the two registers of a 32-bit value. Modbus fixes big-endian bytes within a
/// register but not the order of registers; drives differ, so it is configured.
enum class WordOrder { HighWordFirst, LowWordFirst };

/// Registers a type occupies: 1 or 2.
std::size_t registerCount(RegisterType type);

/// Stable key of a type for settings ("int16", "uint16", "int32", "uint32", "float32").
std::string_view typeKey(RegisterType type);
std::optional<RegisterType> typeFromKey(std::string_view key);
std::string_view wordOrderKey(WordOrder order);  ///< "high-first" / "low-first"
std::optional<WordOrder> wordOrderFromKey(std::string_view key);
std::string_view tableKey(RegisterTable table);  ///< "holding" / "input"
std::optional<RegisterTable> tableFromKey(std::string_view key);

/// The engineering value of registers: raw number x scale. Refuses a wrong register count and
/// a float32 that is NaN or infinite (a drive reporting NaN current is a fault, not a value).
ParseResult<double> decodeValue(std::span<const std::uint16_t> words, RegisterType type, WordOrder order, double scale);

/// Registers for an engineering value: raw = round(value / scale). Throws std::invalid_argument
/// when the value is not finite, scale is zero, or raw does not fit the type.
std::vector<std::uint16_t> encodeValue(double value, RegisterType type, WordOrder order, double scale);

/// One value of a register map.
struct RegisterSpec {
    std::string name;  ///< for messages ("current")
    RegisterTable table = RegisterTable::Holding;
    std::uint16_t address = 0;  ///< zero-based protocol address
    RegisterType type = RegisterType::Int16;
    WordOrder order = WordOrder::HighWordFirst;
    double scale = 1.0;  ///< engineering units per raw count (to the map's unit)
};

/// One read request: `count` registers from `start` of `table`.
struct ReadBlock {
    RegisterTable table = RegisterTable::Holding;
    std::uint16_t start = 0;
    std::uint16_t count = 0;
};

/// The fewest reads that cover every spec: specs of the same table are merged into one read
/// when the span stays within `maxRegisters` (125, the protocol limit for function 03/04).
/// Throws std::invalid_argument when a value runs past address 65535.
std::vector<ReadBlock> planReads(std::span<const RegisterSpec> specs, std::size_t maxRegisters = 125);

/// The value of `spec` taken from the registers read for `block` (which must cover it).
ParseResult<double> extractValue(const RegisterSpec& spec, const ReadBlock& block,
                                 std::span<const std::uint16_t> blockWords);

/// Name of a Modbus exception code in plain words (Modbus application protocol v1.1b3,
/// section 7): 1 "illegal function", 2 "illegal data address", 3 "illegal data value",
/// 4 "server device failure", 5 "acknowledge", 6 "server device busy", 8 "memory parity error",
/// 10 "gateway path unavailable", 11 "gateway target device failed to respond".
std::string modbusExceptionName(std::uint8_t code);

}  // namespace tt::devices::modbus
