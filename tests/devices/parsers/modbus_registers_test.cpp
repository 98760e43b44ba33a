#include "devices/parsers/modbus_registers.h"

#include <gtest/gtest.h>

#include <vector>

#include "devices/parsers/drive_units.h"

namespace tt::devices::modbus {
namespace {

using Words = std::vector<std::uint16_t>;

TEST(ModbusRegisters, DecodesEachTypeAndWordOrder) {
    EXPECT_DOUBLE_EQ(decodeValue(Words{0xFFFE}, RegisterType::Int16, WordOrder::HighWordFirst, 1.0).value(), -2.0);
    EXPECT_DOUBLE_EQ(decodeValue(Words{0xFFFE}, RegisterType::UInt16, WordOrder::HighWordFirst, 1.0).value(), 65534.0);
    // 100000 = 0x000186A0.
    EXPECT_DOUBLE_EQ(decodeValue(Words{0x0001, 0x86A0}, RegisterType::Int32, WordOrder::HighWordFirst, 1.0).value(),
                     100000.0);
    EXPECT_DOUBLE_EQ(decodeValue(Words{0x86A0, 0x0001}, RegisterType::Int32, WordOrder::LowWordFirst, 1.0).value(),
                     100000.0);
    EXPECT_DOUBLE_EQ(decodeValue(Words{0xFFFF, 0xFFFF}, RegisterType::Int32, WordOrder::HighWordFirst, 1.0).value(),
                     -1.0);
    EXPECT_DOUBLE_EQ(decodeValue(Words{0xFFFF, 0xFFFF}, RegisterType::UInt32, WordOrder::HighWordFirst, 1.0).value(),
                     4294967295.0);
    // IEEE 754: 25.0f = 0x41C80000.
    EXPECT_DOUBLE_EQ(decodeValue(Words{0x41C8, 0x0000}, RegisterType::Float32, WordOrder::HighWordFirst, 1.0).value(),
                     25.0);
    EXPECT_DOUBLE_EQ(decodeValue(Words{0x0000, 0x41C8}, RegisterType::Float32, WordOrder::LowWordFirst, 1.0).value(),
                     25.0);
    // Scale: a drive reporting current in 0.01 A counts.
    EXPECT_DOUBLE_EQ(decodeValue(Words{1234}, RegisterType::Int16, WordOrder::HighWordFirst, 0.01).value(), 12.34);
}

TEST(ModbusRegisters, RefusesNaNWrongCountsAndZeroScale) {
    const auto nan = decodeValue(Words{0x7FC0, 0x0000}, RegisterType::Float32, WordOrder::HighWordFirst, 1.0);
    EXPECT_FALSE(nan);
    EXPECT_NE(nan.error().find("NaN"), std::string::npos);
    EXPECT_FALSE(decodeValue(Words{0x7F80, 0x0000}, RegisterType::Float32, WordOrder::HighWordFirst, 1.0));
    EXPECT_FALSE(decodeValue(Words{1}, RegisterType::Int32, WordOrder::HighWordFirst, 1.0));
    EXPECT_FALSE(decodeValue(Words{1}, RegisterType::Int16, WordOrder::HighWordFirst, 0.0));
}

TEST(ModbusRegisters, EncodesWithRangeChecks) {
    EXPECT_EQ(encodeValue(-0.012, RegisterType::Int16, WordOrder::HighWordFirst, 0.001), Words{0xFFF4});
    EXPECT_EQ(encodeValue(100000.0, RegisterType::Int32, WordOrder::LowWordFirst, 1.0), (Words{0x86A0, 0x0001}));
    EXPECT_EQ(encodeValue(25.0, RegisterType::Float32, WordOrder::HighWordFirst, 1.0), (Words{0x41C8, 0x0000}));
    EXPECT_THROW(encodeValue(40.0, RegisterType::Int16, WordOrder::HighWordFirst, 0.001), std::invalid_argument);
    EXPECT_THROW(encodeValue(-1.0, RegisterType::UInt16, WordOrder::HighWordFirst, 1.0), std::invalid_argument);
    for (auto type : {RegisterType::Int16, RegisterType::Int32, RegisterType::Float32}) {
        const auto words = encodeValue(-0.125, type, WordOrder::LowWordFirst, 0.001);
        EXPECT_DOUBLE_EQ(decodeValue(words, type, WordOrder::LowWordFirst, 0.001).value(), -0.125);
    }
}

TEST(ModbusRegisters, PlansTheFewestReads) {
    const std::vector<RegisterSpec> specs{
        {"current", RegisterTable::Input, 10, RegisterType::Int16, WordOrder::HighWordFirst, 0.01},
        {"velocity", RegisterTable::Input, 12, RegisterType::Float32, WordOrder::HighWordFirst, 1.0},
        {"position", RegisterTable::Input, 200, RegisterType::Int32, WordOrder::HighWordFirst, 0.001},
        {"offset", RegisterTable::Holding, 5, RegisterType::Int16, WordOrder::HighWordFirst, 1.0},
    };
    const auto blocks = planReads(specs);
    ASSERT_EQ(blocks.size(), 3u);  // holding 5; input 10..13; input 200..201 (too far to merge)
    EXPECT_EQ(blocks[0].table, RegisterTable::Holding);
    EXPECT_EQ(blocks[1].start, 10);
    EXPECT_EQ(blocks[1].count, 4);
    EXPECT_EQ(blocks[2].start, 200);
    EXPECT_EQ(blocks[2].count, 2);
    const Words words{1234, 0xFFFF, 0x41C8, 0x0000};
    EXPECT_DOUBLE_EQ(extractValue(specs[0], blocks[1], words).value(), 12.34);
    EXPECT_DOUBLE_EQ(extractValue(specs[1], blocks[1], words).value(), 25.0);
    EXPECT_FALSE(extractValue(specs[2], blocks[1], words));
    const std::vector<RegisterSpec> pastEnd{{"x", RegisterTable::Holding, 65535, RegisterType::Int32}};
    EXPECT_THROW(planReads(pastEnd), std::invalid_argument);
}

TEST(ModbusRegisters, NamesExceptionCodes) {
    // Modbus application protocol v1.1b3, section 7.
    EXPECT_EQ(modbusExceptionName(2), "illegal data address");
    EXPECT_EQ(modbusExceptionName(1), "illegal function");
    EXPECT_EQ(modbusExceptionName(11), "gateway target device failed to respond");
    EXPECT_EQ(modbusExceptionName(0x42), "exception code 66");
    EXPECT_EQ(typeFromKey("float32"), RegisterType::Float32);
    EXPECT_FALSE(typeFromKey("double").has_value());
}

TEST(DriveUnits, ConvertsToTheEngineUnitsOnly) {
    EXPECT_DOUBLE_EQ(*toEngineUnitFactor(DriveQuantity::Current, "mA"), 0.001);
    EXPECT_DOUBLE_EQ(*toEngineUnitFactor(DriveQuantity::Velocity, "mm/min") * 600.0, 10.0);
    EXPECT_DOUBLE_EQ(*toEngineUnitFactor(DriveQuantity::Position, "um"), 0.001);
    EXPECT_FALSE(toEngineUnitFactor(DriveQuantity::Current, "mm").has_value());
    EXPECT_EQ(driveUnits(DriveQuantity::Velocity).front(), "mm/s");
}

}  // namespace
}  // namespace tt::devices::modbus
