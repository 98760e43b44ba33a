// The serial gauge plugin through a real pseudo-terminal pair, with the emulated micrometer
// (devices/simulator/micrometer_emulator.h) at the instrument's end.
#include <gtest/gtest.h>

#include <QTest>

#include "devices/api/steady_clock.h"
#include "devices/gauge_serial/gauge_serial_factory.h"
#include "devices/simulator/micrometer_emulator.h"
#include "support/pty_pair.h"

namespace tt::devices {
namespace {

using test::PtyPair;

class SerialGaugeTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> make(const QVariantMap& extra = {}) {
        QVariantMap settings{{QStringLiteral("port"), pty.portName()}, {QStringLiteral("baud"), 9600}};
        for (auto it = extra.begin(); it != extra.end(); ++it)
            settings.insert(it.key(), it.value());
        EXPECT_TRUE(factory.validate(DeviceKind::Gauge, settings, Validation::Full).isEmpty())
            << joinIssues(factory.validate(DeviceKind::Gauge, settings, Validation::Full)).toStdString();
        return factory.create(DeviceKind::Gauge, settings, DeviceContext{&clock});
    }
    static bool waitState(Device& d, core::DeviceState s, int ms = 3000) {
        return QTest::qWaitFor([&] { return d.health().state == s; }, ms);
    }
    static std::vector<core::GaugeReading> waitReadings(core::DiameterGauge& g, std::size_t n, int ms = 3000) {
        std::vector<core::GaugeReading> got;
        (void)QTest::qWaitFor(
            [&] {
                while (auto r = g.takeReading())
                    got.push_back(*r);
                return got.size() >= n;
            },
            ms);
        return got;
    }

    SteadyClock clock;
    GaugeSerialFactory factory;
    PtyPair pty{QStringLiteral("ttyGAUGE")};
};

TEST_F(SerialGaugeTest, DataButtonReadingsArriveInOrderInMillimetres) {
    auto device = make();
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready)) << device->health().message;
    MicrometerEmulator micrometer(MicrometerEmulator::Format::Ascii);
    for (double d : {26.812, 26.95, 27.0004}) {
        micrometer.setSource([d] { return d; });
        pty.send(micrometer.pressDataButton());
    }
    const auto readings = waitReadings(*device->diameterGauge(), 3);
    ASSERT_EQ(readings.size(), 3u);
    // Resolution 0.001 mm: the micrometer rounds 27.0004 to 27.000.
    EXPECT_DOUBLE_EQ(readings[0].diameterMm, 26.812);
    EXPECT_DOUBLE_EQ(readings[1].diameterMm, 26.95);
    EXPECT_DOUBLE_EQ(readings[2].diameterMm, 27.0);
    EXPECT_LE(readings[0].timeS, readings[2].timeS);
    EXPECT_EQ(device->liveValue(), QStringLiteral("27.000 mm"));
}

TEST_F(SerialGaugeTest, PolledWithTheConfiguredRequestString) {
    auto device =
        make({{QStringLiteral("mode"), QStringLiteral("polled")}, {QStringLiteral("request"), QStringLiteral("1\\r")}});
    MicrometerEmulator micrometer(MicrometerEmulator::Format::Ascii);
    micrometer.setRequest("1\r");
    micrometer.setSource([] { return 24.8; });
    pty.onBytes([&](const QByteArray& bytes) {
        pty.send(micrometer.receive(
            {reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())}));
    });
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    EXPECT_FALSE(device->diameterGauge()->takeReading().has_value());  // nothing until asked
    device->diameterGauge()->requestReading();
    const auto readings = waitReadings(*device->diameterGauge(), 1);
    ASSERT_EQ(readings.size(), 1u);
    EXPECT_DOUBLE_EQ(readings[0].diameterMm, 24.8);
    EXPECT_EQ(micrometer.readingsSent(), 1);
}

TEST_F(SerialGaugeTest, DigimaticFramesInBothEncodings) {
    for (const auto& [key, format] :
         {std::pair{QStringLiteral("digimatic-nibbles"), MicrometerEmulator::Format::DigimaticNibbles},
          std::pair{QStringLiteral("digimatic-hex"), MicrometerEmulator::Format::DigimaticHex}}) {
        auto device = make({{QStringLiteral("format"), key}});
        device->open();
        ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
        MicrometerEmulator micrometer(format, LengthUnit::Millimetre, 4);
        micrometer.setSource([] { return 21.0765; });         // the LSM-6200 manual's example value
        pty.send(std::vector<std::uint8_t>{0x3, 0x7, '\r'});  // line noise before the frame
        pty.send(micrometer.pressDataButton());
        const auto readings = waitReadings(*device->diameterGauge(), 1);
        ASSERT_EQ(readings.size(), 1u) << key.toStdString();
        EXPECT_NEAR(readings[0].diameterMm, 21.0765, 1e-12);
        device->close();
    }
}

TEST_F(SerialGaugeTest, AnInchReadingOnAMillimetreJobIsRefusedWithAMessage) {
    auto device = make({{QStringLiteral("format"), QStringLiteral("digimatic-nibbles")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    MicrometerEmulator micrometer(MicrometerEmulator::Format::DigimaticNibbles, LengthUnit::Inch, 4);
    micrometer.setSource([] { return 26.812; });  // displayed as 1.0556 in
    pty.send(micrometer.pressDataButton());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !device->lastError().isEmpty(); }, 3000));
    EXPECT_TRUE(device->lastError().contains(QStringLiteral("1.0556 in refused"))) << device->lastError().toStdString();
    EXPECT_TRUE(device->lastError().contains(QStringLiteral("set the micrometer to mm")));
    EXPECT_FALSE(device->diameterGauge()->takeReading().has_value());
    EXPECT_EQ(device->health().state, core::DeviceState::Ready);  // the line is fine; the reading is not
    // Set to mm, the same part is accepted.
    micrometer.setUnit(LengthUnit::Millimetre);
    pty.send(micrometer.pressDataButton());
    EXPECT_EQ(waitReadings(*device->diameterGauge(), 1).size(), 1u);
}

TEST_F(SerialGaugeTest, AnInchJobConvertsInchReadingsToMillimetres) {
    auto device = make(
        {{QStringLiteral("instrumentUnit"), QStringLiteral("in")}, {QStringLiteral("jobUnit"), QStringLiteral("in")}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    pty.send(QByteArray("01A+001.0556\r"));
    const auto readings = waitReadings(*device->diameterGauge(), 1);
    ASSERT_EQ(readings.size(), 1u);
    EXPECT_NEAR(readings[0].diameterMm, 1.0556 * 25.4, 1e-12);  // 1 in = 25.4 mm exactly
}

TEST_F(SerialGaugeTest, MalformedAndCorruptFramesAreCountedAndNeverUsed) {
    auto device = make();
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    MicrometerEmulator micrometer(MicrometerEmulator::Format::Ascii);
    micrometer.corruptNext();
    pty.send(micrometer.pressDataButton());                                 // "01A+0X026.812"
    pty.send(QByteArray("01A*00026.812\r") + QByteArray(200, 'z') + "\r");  // bad sign; garbage line
    pty.send(micrometer.pressDataButton());                                 // a good one
    const auto readings = waitReadings(*device->diameterGauge(), 1);
    ASSERT_EQ(readings.size(), 1u);
    EXPECT_DOUBLE_EQ(readings[0].diameterMm, 27.0);
    EXPECT_FALSE(device->diameterGauge()->takeReading().has_value());
    const auto stats = device->statistics();
    EXPECT_EQ(stats[1].value, QStringLiteral("2"));  // malformed
    EXPECT_EQ(stats[3].value, QStringLiteral("1"));  // the overlong garbage line
    EXPECT_FALSE(device->lastError().isEmpty());
}

TEST_F(SerialGaugeTest, APolledGaugeThatDoesNotAnswerTimesOutThenRecovers) {
    auto device = make({{QStringLiteral("mode"), QStringLiteral("polled")}, {QStringLiteral("replyTimeoutMs"), 200}});
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    device->diameterGauge()->requestReading();  // nobody answers
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error, 2000));
    EXPECT_NE(device->health().message.find("no answer from the gauge on"), std::string::npos)
        << device->health().message;
    pty.send(QByteArray("01A+00026.812\r"));  // it answers after all
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    EXPECT_EQ(waitReadings(*device->diameterGauge(), 1).size(), 1u);
}

TEST_F(SerialGaugeTest, UnplugMidStreamGoesToErrorAndReconnectRecovers) {
    auto device = make();
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    pty.releaseSlave();
    pty.send(QByteArray("01A+00026.812\r"));
    ASSERT_EQ(waitReadings(*device->diameterGauge(), 1).size(), 1u);
    pty.unplug();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_NE(device->health().message.find("disconnected"), std::string::npos) << device->health().message;
    pty.plug();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready, 5000)) << device->health().message;
    pty.send(QByteArray("01A+00026.813\r"));
    const auto readings = waitReadings(*device->diameterGauge(), 1);
    ASSERT_EQ(readings.size(), 1u);
    EXPECT_DOUBLE_EQ(readings[0].diameterMm, 26.813);
}

TEST_F(SerialGaugeTest, SettingsAreValidatedInTheUsersTerms) {
    const auto issues = factory.validate(DeviceKind::Gauge,
                                         {{QStringLiteral("port"), QStringLiteral("/dev/ttyNOPE7")},
                                          {QStringLiteral("baud"), 9601},
                                          {QStringLiteral("mode"), QStringLiteral("polled")},
                                          {QStringLiteral("request"), QStringLiteral("\\q")}},
                                         Validation::Full);
    ASSERT_EQ(issues.size(), 3);
    EXPECT_EQ(issues[0].key, QStringLiteral("port"));
    EXPECT_TRUE(issues[0].message.contains(QStringLiteral("/dev/ttyNOPE7 does not exist")));
    EXPECT_EQ(issues[1].key, QStringLiteral("baud"));
    EXPECT_TRUE(issues[1].message.startsWith(QStringLiteral("Baud rate: 9601 is not one of 1200, 2400")));
    EXPECT_EQ(issues[2].key, QStringLiteral("request"));
    // A missing port is fine for creation (restored at start-up, adapter unplugged) ...
    auto device = factory.create(DeviceKind::Gauge, {{QStringLiteral("port"), QStringLiteral("/dev/ttyNOPE7")}},
                                 DeviceContext{&clock});
    device->open();  // ... and reported when opened, with retries running.
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_NE(device->health().message.find("cannot open /dev/ttyNOPE7"), std::string::npos);
    EXPECT_THROW(factory.create(DeviceKind::Gauge, {{QStringLiteral("baud"), 9601}}, DeviceContext{&clock}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace tt::devices
