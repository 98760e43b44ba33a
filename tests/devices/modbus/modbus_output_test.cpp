// The Modbus correction output against a Modbus TCP server on 127.0.0.1 started by the test:
// per-point corrections and the dynamic X offset written, read back and verified.
#include <gtest/gtest.h>

#include <QTest>

#include "devices/api/steady_clock.h"
#include "devices/modbus/modbus_factory.h"
#include "devices/modbus/modbus_output_device.h"
#include "devices/parsers/modbus_registers.h"
#include "support/modbus_servers.h"

namespace tt::devices {
namespace {

using namespace test;
constexpr auto kHolding = QModbusDataUnit::HoldingRegisters;

/// A PLC that clamps what it is given: stores every written register with its lowest bit cleared
/// (a read-back then differs for odd values).
class ClampingServer : public QModbusTcpServer {
protected:
    bool writeData(const QModbusDataUnit& unit) override {
        QModbusDataUnit changed = unit;
        for (qsizetype i = 0; i < changed.valueCount(); ++i)
            changed.setValue(i, static_cast<quint16>(changed.value(i) & 0xFFFE));
        return QModbusTcpServer::writeData(changed);
    }
};

class ModbusOutputTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> make(quint16 port, QVariantMap extra) {
        QVariantMap s{{QStringLiteral("transport"), QStringLiteral("tcp")},
                      {QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                      {QStringLiteral("tcpPort"), port},
                      {QStringLiteral("timeoutMs"), 200},
                      {QStringLiteral("pointsAddress"), 100},
                      {QStringLiteral("offsetAddress"), 120},
                      {QStringLiteral("partAddress"), 110},
                      {QStringLiteral("valueType"), QStringLiteral("int32")},
                      {QStringLiteral("valueScale"), 0.0001}};
        for (auto it = extra.begin(); it != extra.end(); ++it)
            s.insert(it.key(), it.value());
        EXPECT_TRUE(factory.validate(DeviceKind::CorrectionOutput, s, Validation::Full).isEmpty())
            << joinIssues(factory.validate(DeviceKind::CorrectionOutput, s, Validation::Full)).toStdString();
        return factory.create(DeviceKind::CorrectionOutput, s, DeviceContext{&clock});
    }
    static bool waitState(Device& d, core::DeviceState s, int ms = 3000) {
        return QTest::qWaitFor([&] { return d.health().state == s; }, ms);
    }
    static core::PartCorrection part(std::int64_t number, std::vector<double> corrections) {
        core::PartCorrection c;
        c.partNumber = number;
        c.pointCorrectionMm = std::move(corrections);
        for (std::size_t i = 0; i < c.pointCorrectionMm.size(); ++i)
            c.pointZMm.push_back(5.0 + 78.75 * i);
        return c;
    }
    static std::vector<double> corrections(const QModbusServer& server, int n) {
        std::vector<double> out;
        const auto words = registers(server, kHolding, 100, static_cast<quint16>(2 * n));
        for (int i = 0; i < n; ++i)
            out.push_back(modbus::decodeValue(std::span(words).subspan(2 * static_cast<std::size_t>(i), 2),
                                              modbus::RegisterType::Int32, modbus::WordOrder::HighWordFirst, 0.0001)
                              .value());
        return out;
    }

    SteadyClock clock;
    ModbusFactory factory;
};

TEST_F(ModbusOutputTest, PerPointCorrectionsAreWrittenVerifiedThenThePartNumber) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    auto device =
        make(port, {{QStringLiteral("target"), QStringLiteral("points")}, {QStringLiteral("writePartNumber"), true}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready)) << device->health().message;
    auto* out = device->correctionOutput();
    const core::OutputResult r = out->sendPartCorrection(part(12, {-0.0102, -0.0451, -0.0750, -0.0433, -0.0051}));
    EXPECT_TRUE(r.ok) << r.message;
    auto* modbusOut = dynamic_cast<ModbusOutputDevice*>(device.get());
    ASSERT_NE(modbusOut, nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return modbusOut->verifiedWrites() == 1; }, 3000))
        << device->lastError().toStdString();
    const auto plc = corrections(*server, 5);
    EXPECT_NEAR(plc[0], -0.0102, 1e-12);
    EXPECT_NEAR(plc[2], -0.0750, 1e-12);
    EXPECT_EQ(registers(*server, kHolding, 110, 2), (std::vector<std::uint16_t>{0, 12}));
    EXPECT_EQ(device->liveValue(), QStringLiteral("part 12: 5 corrections written and verified"));
}

TEST_F(ModbusOutputTest, TheLatestDynamicOffsetWinsAndIsVerified) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    auto device = make(port, {{QStringLiteral("target"), QStringLiteral("offset")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    auto* out = device->correctionOutput();
    for (double offset : {0.010, 0.012, 0.015, 0.0183})
        EXPECT_TRUE(out->sendDynamicOffset(offset).ok);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return device->liveValue() == QStringLiteral("X offset 0.0183 mm written and verified"); }, 3000))
        << device->liveValue().toStdString();
    const auto words = registers(*server, kHolding, 120, 2);
    EXPECT_NEAR(
        modbus::decodeValue(words, modbus::RegisterType::Int32, modbus::WordOrder::HighWordFirst, 0.0001).value(),
        0.0183, 1e-12);
    auto* modbusOut = dynamic_cast<ModbusOutputDevice*>(device.get());
    EXPECT_LE(modbusOut->verifiedWrites(), 4u);  // offsets sent while the bus was busy were skipped
    EXPECT_GE(modbusOut->verifiedWrites(), 2u);
}

TEST_F(ModbusOutputTest, AReadBackMismatchIsAnErrorWithBothValues) {
    const quint16 port = freeTcpPort();
    ClampingServer server;
    giveRegisters(server);
    server.setConnectionParameter(QModbusDevice::NetworkAddressParameter, QStringLiteral("127.0.0.1"));
    server.setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
    ASSERT_TRUE(server.connectDevice());
    auto device = make(port, {{QStringLiteral("target"), QStringLiteral("offset")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    EXPECT_TRUE(device->correctionOutput()->sendDynamicOffset(0.0123).ok);  // 123 counts: odd
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_NE(device->health().message.find(
                  "read-back mismatch for X offset 0.0123 mm at register 120: wrote 0 123, read 0 122"),
              std::string::npos)
        << device->health().message;
}

TEST_F(ModbusOutputTest, OutOfLimitOrMismatchedCorrectionsAreRefusedAndNothingIsSent) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    auto device = make(port, {{QStringLiteral("target"), QStringLiteral("points")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    auto* out = device->correctionOutput();
    const core::OutputResult tooBig = out->sendPartCorrection(part(3, {0.0, 0.8, 0.0}));
    EXPECT_FALSE(tooBig.ok);
    EXPECT_NE(tooBig.message.find("beyond the limit of 0.500 mm"), std::string::npos);
    EXPECT_FALSE(out->sendPartCorrection(part(3, std::vector<double>(6, 0.01))).ok);  // 6 points, 5 configured
    EXPECT_FALSE(out->sendDynamicOffset(0.01).ok);                                    // set up for points
    QTest::qWait(100);
    EXPECT_EQ(registers(*server, kHolding, 100, 10), std::vector<std::uint16_t>(10, 0));
}

TEST_F(ModbusOutputTest, WritingWhileTheServerIsGoneIsRefusedAndReconnectRecovers) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    auto device = make(port, {{QStringLiteral("target"), QStringLiteral("offset")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    server.reset();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_FALSE(device->correctionOutput()->sendDynamicOffset(0.01).ok);
    server = startTcpServer(port);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready, 8000));
    EXPECT_TRUE(device->correctionOutput()->sendDynamicOffset(0.01).ok);
}

}  // namespace
}  // namespace tt::devices
