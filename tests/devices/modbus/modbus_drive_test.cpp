// The Modbus drive-current readout against servers started by the test: Modbus TCP on
// 127.0.0.1 and Modbus RTU on a pseudo-terminal null modem.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>

#include "devices/api/steady_clock.h"
#include "devices/modbus/modbus_factory.h"
#include "devices/parsers/modbus_registers.h"
#include "support/modbus_servers.h"
#include "support/pty_pair.h"

namespace tt::devices {
namespace {

using namespace test;
using modbus::encodeValue;
using modbus::RegisterType;
using modbus::WordOrder;

constexpr auto kInput = QModbusDataUnit::InputRegisters;

/// The drive's registers: current int16 in 0.01 A at input 0, velocity float32 mm/min (low word
/// first) at input 1..2, position int32 in um at input 3..4.
void writeDriveState(QModbusServer& server, double currentA, double velocityMmPerMin, double positionUm) {
    setRegisters(server, kInput, 0, encodeValue(currentA, RegisterType::Int16, WordOrder::HighWordFirst, 0.01));
    setRegisters(server, kInput, 1, encodeValue(velocityMmPerMin, RegisterType::Float32, WordOrder::LowWordFirst, 1.0));
    setRegisters(server, kInput, 3, encodeValue(positionUm, RegisterType::Int32, WordOrder::HighWordFirst, 1.0));
}

QVariantMap driveMap() {
    return {{QStringLiteral("pollMs"), 20},
            {QStringLiteral("timeoutMs"), 100},
            {QStringLiteral("retries"), 0},
            {QStringLiteral("currentTable"), QStringLiteral("input")},
            {QStringLiteral("currentAddress"), 0},
            {QStringLiteral("currentType"), QStringLiteral("int16")},
            {QStringLiteral("currentScale"), 0.01},
            {QStringLiteral("currentUnit"), QStringLiteral("A")},
            {QStringLiteral("velocityTable"), QStringLiteral("input")},
            {QStringLiteral("velocityAddress"), 1},
            {QStringLiteral("velocityType"), QStringLiteral("float32")},
            {QStringLiteral("velocityWordOrder"), QStringLiteral("low-first")},
            {QStringLiteral("velocityScale"), 1.0},
            {QStringLiteral("velocityUnit"), QStringLiteral("mm/min")},
            {QStringLiteral("positionTable"), QStringLiteral("input")},
            {QStringLiteral("positionAddress"), 3},
            {QStringLiteral("positionType"), QStringLiteral("int32")},
            {QStringLiteral("positionScale"), 1.0},
            {QStringLiteral("positionUnit"), QStringLiteral("um")}};
}

class ModbusDriveTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> makeTcp(quint16 port, QVariantMap extra = {}) {
        QVariantMap s = driveMap();
        s.insert(QStringLiteral("transport"), QStringLiteral("tcp"));
        s.insert(QStringLiteral("host"), QStringLiteral("127.0.0.1"));
        s.insert(QStringLiteral("tcpPort"), port);
        for (auto it = extra.begin(); it != extra.end(); ++it)
            s.insert(it.key(), it.value());
        EXPECT_TRUE(factory.validate(DeviceKind::DriveCurrent, s, Validation::Full).isEmpty())
            << joinIssues(factory.validate(DeviceKind::DriveCurrent, s, Validation::Full)).toStdString();
        return factory.create(DeviceKind::DriveCurrent, s, DeviceContext{&clock});
    }
    std::unique_ptr<Device> makeRtu(const QString& port) {
        QVariantMap s = driveMap();
        s.insert(QStringLiteral("transport"), QStringLiteral("rtu"));
        s.insert(QStringLiteral("port"), port);
        s.insert(QStringLiteral("baud"), 115200);
        s.insert(QStringLiteral("parity"), QStringLiteral("none"));
        return factory.create(DeviceKind::DriveCurrent, s, DeviceContext{&clock});
    }
    static bool waitState(Device& d, core::DeviceState s, int ms = 3000) {
        return QTest::qWaitFor([&] { return d.health().state == s; }, ms);
    }
    static std::vector<core::DriveSample> collect(core::DriveCurrentReadout& r, int ms) {
        std::vector<core::DriveSample> got;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            QTest::qWait(10);
            while (auto s = r.takeSample())
                got.push_back(*s);
        }
        return got;
    }

    SteadyClock clock;
    ModbusFactory factory;
};

TEST_F(ModbusDriveTest, TcpReadingsAreScaledConvertedAndStamped) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    writeDriveState(*server, 2.6, 120.0, -15.5);  // 2.6 A, 120 mm/min = 2 mm/s, -15.5 um (int32 rounds to -16)
    auto device = makeTcp(port);
    const double before = clock.nowS();
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready)) << device->health().message;
    const auto samples = collect(*device->driveCurrentReadout(), 200);
    // 20 ms polling for 0.2 s: about 10 samples.
    ASSERT_GE(samples.size(), 4u);
    EXPECT_LE(samples.size(), 14u);
    for (const auto& s : samples) {
        EXPECT_NEAR(s.currentA, 2.6, 1e-12);
        EXPECT_NEAR(s.velocityMmPerS, 2.0, 1e-6);
        EXPECT_NEAR(s.positionMm, -0.016, 1e-12);
    }
    EXPECT_GT(samples.front().timeS, before);
    for (std::size_t i = 1; i < samples.size(); ++i)
        EXPECT_GT(samples[i].timeS, samples[i - 1].timeS);
    EXPECT_EQ(device->liveValue(), QStringLiteral("2.60 A, 2.000 mm/s, -0.0160 mm"));
}

TEST_F(ModbusDriveTest, AModbusExceptionIsReportedByName) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    auto device = makeTcp(port, {{QStringLiteral("positionAddress"), 400}});  // beyond the 50 input registers
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error)) << device->health().message;
    EXPECT_NE(device->health().message.find("Modbus exception 2 (illegal data address)"), std::string::npos)
        << device->health().message;
    EXPECT_FALSE(device->driveCurrentReadout()->takeSample().has_value());
}

TEST_F(ModbusDriveTest, ANaNRegisterValueIsRefusedNotUsed) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    writeDriveState(*server, 1.0, 60.0, 0.0);
    setRegisters(*server, kInput, 1, {0x0000, 0x7FC0});  // float32 NaN, low word first
    auto device = makeTcp(port);
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    EXPECT_TRUE(collect(*device->driveCurrentReadout(), 100).empty());
    EXPECT_TRUE(device->lastError().contains(QStringLiteral("NaN"))) << device->lastError().toStdString();
    writeDriveState(*server, 1.0, 60.0, 0.0);
    EXPECT_FALSE(collect(*device->driveCurrentReadout(), 100).empty());
}

TEST_F(ModbusDriveTest, TcpServerGoneMidStreamIsAnErrorAndReconnectRecovers) {
    const quint16 port = freeTcpPort();
    auto server = startTcpServer(port);
    writeDriveState(*server, 1.5, 0.0, 0.0);
    auto device = makeTcp(port);
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    ASSERT_FALSE(collect(*device->driveCurrentReadout(), 60).empty());
    server->disconnectDevice();
    server.reset();  // the drive is switched off
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error)) << device->health().message;
    QTest::qWait(300);  // a few reconnect attempts fail
    EXPECT_EQ(device->health().state, core::DeviceState::Error);
    server = startTcpServer(port);  // switched on again
    writeDriveState(*server, 1.75, 0.0, 0.0);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready, 8000)) << device->health().message;
    const auto samples = collect(*device->driveCurrentReadout(), 100);
    ASSERT_FALSE(samples.empty());
    EXPECT_NEAR(samples.back().currentA, 1.75, 1e-12);
}

TEST_F(ModbusDriveTest, RtuOnAPseudoTerminal) {
    PtyNullModem cable;
    auto server = startRtuServer(cable.endA());
    writeDriveState(*server, -0.8, -30.0, 20000.0);
    auto device = makeRtu(cable.endB());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready)) << device->health().message;
    const auto samples = collect(*device->driveCurrentReadout(), 200);
    ASSERT_FALSE(samples.empty());
    EXPECT_NEAR(samples.back().currentA, -0.8, 1e-12);
    EXPECT_NEAR(samples.back().velocityMmPerS, -0.5, 1e-6);
    EXPECT_NEAR(samples.back().positionMm, 20.0, 1e-12);
}

TEST_F(ModbusDriveTest, RtuCableCutTimesOutToErrorAndRecovers) {
    PtyNullModem cable;
    auto server = startRtuServer(cable.endA());
    writeDriveState(*server, 0.5, 0.0, 0.0);
    auto device = makeRtu(cable.endB());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    cable.setCut(true);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error)) << device->health().message;
    EXPECT_NE(device->health().message.find("no answer from"), std::string::npos) << device->health().message;
    EXPECT_NE(device->health().message.find("polls in a row"), std::string::npos);
    (void)collect(*device->driveCurrentReadout(), 10);
    cable.setCut(false);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    EXPECT_FALSE(collect(*device->driveCurrentReadout(), 100).empty());
}

TEST_F(ModbusDriveTest, RtuCorruptRepliesAreNeverUsed) {
    PtyNullModem cable;
    auto server = startRtuServer(cable.endA());
    writeDriveState(*server, 3.0, 0.0, 0.0);
    auto device = makeRtu(cable.endB());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    (void)collect(*device->driveCurrentReadout(), 50);
    cable.setCorruptAtoB(true);  // every reply's CRC is broken
    const auto during = collect(*device->driveCurrentReadout(), 200);
    for (const auto& s : during)
        EXPECT_NEAR(s.currentA, 3.0, 1e-12);  // at most the replies already in flight
    EXPECT_LE(during.size(), 2u);
    EXPECT_FALSE(device->lastError().isEmpty());
    cable.setCorruptAtoB(false);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    const auto after = collect(*device->driveCurrentReadout(), 100);
    ASSERT_FALSE(after.empty());
    EXPECT_NEAR(after.back().currentA, 3.0, 1e-12);
}

TEST_F(ModbusDriveTest, RegisterMapIsValidated) {
    QVariantMap s = driveMap();
    s.insert(QStringLiteral("transport"), QStringLiteral("tcp"));
    s.insert(QStringLiteral("host"), QString());
    s.insert(QStringLiteral("positionAddress"), 65535);  // an int32 cannot start at the last register
    s.insert(QStringLiteral("pollMs"), 5);               // faster than the 10 ms minimum
    const auto issues = factory.validate(DeviceKind::DriveCurrent, s, Validation::Full);
    const QString all = joinIssues(issues);
    EXPECT_TRUE(all.contains(QStringLiteral("Polling period: 5 is outside 10 to 100 ms"))) << all.toStdString();
    EXPECT_TRUE(all.contains(QStringLiteral("Host:")));
    s.insert(QStringLiteral("pollMs"), 20);
    s.insert(QStringLiteral("host"), QStringLiteral("10.0.0.1"));
    EXPECT_TRUE(joinIssues(factory.validate(DeviceKind::DriveCurrent, s, Validation::Full))
                    .contains(QStringLiteral("runs past address 65535")));
}

}  // namespace
}  // namespace tt::devices
