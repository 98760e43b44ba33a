// LinuxCNC on the Devices page: the plugin's settings and their checks, Test connection saying what it found in
// the user's words, an E-stop shown as such, and a correction written between parts (no part program set: the
// operator runs the parts) with its record for the history.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTest>

#include "core/loop/loop_clock.h"
#include "devices/linuxcnc/linuxcnc_factory.h"
#include "devices/linuxcnc/linuxcnc_output_device.h"
#include "devices/linuxcnc/linuxcnc_settings.h"
#include "tests/devices/support/linuxcnc_test_machine.h"

namespace {

using namespace tt;
using namespace tt::devices;
using devices::linuxcnc::LinuxCncOutputDevice;

QString statistic(const Device& device, const QString& label) {
    for (const DeviceStatistic& s : device.statistics())
        if (s.label == label) return s.value;
    return {};
}

bool waitFor(const std::function<bool()>& done, int ms = 20000) {
    for (int waited = 0; waited < ms; waited += 20) {
        if (done()) return true;
        QTest::qWait(20);
    }
    return done();
}

TEST(LinuxCncSettings, ReadsALinuxCncUrlAndRefusesOthers) {
    const QVariantMap s = linuxcnc::settingsFromUrl(QStringLiteral("linuxcnc://10.0.0.7:5008"), QStringLiteral("wear"));
    EXPECT_EQ(s.value(QStringLiteral("host")).toString(), QStringLiteral("10.0.0.7"));
    EXPECT_EQ(s.value(QStringLiteral("port")).toInt(), 5008);
    EXPECT_EQ(s.value(QStringLiteral("mode")).toString(), QStringLiteral("wear"));
    EXPECT_EQ(linuxcnc::settingsFromUrl(QStringLiteral("linuxcnc://lathe-3")).value(QStringLiteral("port")).toInt(),
              5007);
    EXPECT_EQ(linuxcnc::sessionSettings(s).corrections.mode, linuxcnc::CorrectionMode::Wear);
    EXPECT_EQ(linuxcnc::sessionSettings(s).corrections.firstParameter, 500);
    EXPECT_EQ(linuxcnc::sessionSettings(s).controller.endpoint.text(), "10.0.0.7:5008");
    EXPECT_THROW(linuxcnc::settingsFromUrl(QStringLiteral("modbus://10.0.0.7")), std::invalid_argument);
    EXPECT_THROW(linuxcnc::settingsFromUrl(QStringLiteral("linuxcnc://")), std::invalid_argument);
    EXPECT_THROW(linuxcnc::settingsFromUrl(QStringLiteral("linuxcnc://h:1/x")), std::invalid_argument);
    EXPECT_THROW(linuxcnc::settingsFromUrl(QStringLiteral("linuxcnc://h"), QStringLiteral("both")),
                 std::invalid_argument);
}

TEST(LinuxCncSettings, NamesEveryBadSettingInTheUsersWords) {
    linuxcnc::LinuxCncFactory factory;
    QVariantMap s;
    s.insert(QStringLiteral("host"), QStringLiteral("  "));
    s.insert(QStringLiteral("enablePassword"), QStringLiteral("two words"));
    s.insert(QStringLiteral("largestStepMm"), 0.4);
    s.insert(QStringLiteral("largestTotalMm"), 0.2);
    s.insert(QStringLiteral("programPath"), QStringLiteral("part.ngc"));
    QStringList keys;
    for (const SettingIssue& issue : factory.validate(DeviceKind::CorrectionOutput, s, Validation::Full))
        keys << issue.key;
    EXPECT_TRUE(keys.contains(QStringLiteral("host")));
    EXPECT_TRUE(keys.contains(QStringLiteral("enablePassword")));
    EXPECT_TRUE(keys.contains(QStringLiteral("largestStepMm")));
    EXPECT_TRUE(keys.contains(QStringLiteral("programPath")));
    EXPECT_TRUE(factory.validate(DeviceKind::CorrectionOutput, {}, Validation::Full).isEmpty())
        << "the defaults are good";
}

TEST(LinuxCncDevice, TestConnectionSaysWhatItFoundInTheUsersWords) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    const core::ManualClock clock;
    linuxcnc::LinuxCncFactory factory;
    auto device = factory.create(DeviceKind::CorrectionOutput, linuxcnc::settingsFromUrl(lc->url()), {&clock});
    device->testConnection();
    // What the session found reaches the device's state at its next refresh (every 0.1 s).
    ASSERT_TRUE(waitFor([&] {
        return QString::fromStdString(device->health().message).contains(QStringLiteral("homed")) &&
               !device->liveValue().isEmpty();
    })) << device->health().message;
    EXPECT_EQ(device->health().state, core::DeviceState::Ready) << device->health().message;
    const QString health = QString::fromStdString(device->health().message);
    EXPECT_TRUE(
        health.contains(QStringLiteral("LinuxCNC EMCNETSVR 1.1 at ") + QString::fromStdString(lc->endpoint().text())))
        << health.toStdString();
    EXPECT_TRUE(health.contains(QStringLiteral("machine on, homed"))) << health.toStdString();
    EXPECT_EQ(statistic(*device, QStringLiteral("LinuxCNC")), QStringLiteral("remote shell EMCNETSVR, protocol 1.1"));
    EXPECT_EQ(statistic(*device, QStringLiteral("Machine")), QStringLiteral("on"));
    EXPECT_EQ(statistic(*device, QStringLiteral("Homed")), QStringLiteral("yes"));
    EXPECT_EQ(statistic(*device, QStringLiteral("Machine units")), QStringLiteral("inch"))
        << "the package's simulated lathe is an inch machine";
    EXPECT_EQ(statistic(*device, QStringLiteral("Program units")), QStringLiteral("mm (G21), diameter (G7)"));
    EXPECT_TRUE(device->liveValue().contains(QStringLiteral("idle; X "))) << device->liveValue().toStdString();

    // The operator presses E-stop: the device says so.
    auto* output = dynamic_cast<LinuxCncOutputDevice*>(device.get());
    ASSERT_NE(output, nullptr);
    ASSERT_TRUE(test::operate(output->session(), [](linuxcnc::LinuxCncController& c) { c.request("set estop on"); }));
    ASSERT_TRUE(waitFor([&] { return device->health().state == core::DeviceState::Error; }));
    EXPECT_TRUE(QString::fromStdString(device->health().message).contains(QStringLiteral("E-stop on")));
    EXPECT_EQ(statistic(*device, QStringLiteral("Machine")), QStringLiteral("E-stop on"));
    ASSERT_TRUE(test::operate(output->session(), [](linuxcnc::LinuxCncController& c) { test::bringUp(c); }));
}

TEST(LinuxCncDevice, WritesACorrectionBetweenPartsAndKeepsItsRecordForTheHistory) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    const core::ManualClock clock;
    linuxcnc::LinuxCncFactory factory;
    QVariantMap settings = linuxcnc::settingsFromUrl(lc->url());
    settings.insert(QStringLiteral("xMode"), QStringLiteral("radius"));
    auto device = factory.create(DeviceKind::CorrectionOutput, settings, {&clock});
    auto* output = dynamic_cast<LinuxCncOutputDevice*>(device.get());
    ASSERT_NE(output, nullptr);
    device->open();
    core::PartCorrection c;
    c.partNumber = 41;
    c.pointZMm = {0.0, 27.5, 162.5, 262.5, 325.0};
    c.pointCorrectionMm = {0.0123, -0.0211, 0.0157, 0.0309, -0.0087};
    ASSERT_TRUE(device->correctionOutput()->sendPartCorrection(c).ok);
    ASSERT_TRUE(waitFor([&] { return device->liveValue().contains(QStringLiteral("read back")); }))
        << device->health().message << " / " << device->lastError().toStdString();
    EXPECT_EQ(statistic(*device, QStringLiteral("Writes verified")), QStringLiteral("1"));
    const auto writes = output->takeWrites();
    ASSERT_EQ(writes.size(), 1u);
    EXPECT_TRUE(writes[0].applied());
    EXPECT_EQ(writes[0].partNumber, 41);
    EXPECT_EQ(writes[0].writtenMm, c.pointCorrectionMm);
    EXPECT_TRUE(device->liveValue().contains(QStringLiteral("written to #500.. and read back")))
        << device->liveValue().toStdString();
    std::vector<double> held;
    ASSERT_TRUE(test::operate(output->session(), [&](linuxcnc::LinuxCncController& controller) {
        held = controller.readParameters({"#500", "#501", "#502", "#503", "#504", "#505"});
    }));
    EXPECT_EQ(held, (std::vector<double>{0.0123, -0.0211, 0.0157, 0.0309, -0.0087, 41.0})) << "what LinuxCNC holds";

    // Beyond the largest total (0.5 mm): refused when sent, nothing written.
    c.partNumber = 42;
    c.pointCorrectionMm[2] = 0.6;
    const core::OutputResult refused = device->correctionOutput()->sendPartCorrection(c);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.message.find("beyond the largest correction"), std::string::npos) << refused.message;
    EXPECT_EQ(statistic(*device, QStringLiteral("Writes refused")), QStringLiteral("1"));
    EXPECT_FALSE(device->correctionOutput()->sendDynamicOffset(0.01).ok);
    device->close();
}

}  // namespace

// The LinuxCNC lathe slows its cut while its sampler cannot keep up: the pace is LinuxCNC's feed override, which
// LinuxCNC holds as set (read back with its own get), and one outside 1 .. 100 % is never sent.
TEST(LinuxCncDevice, TheFeedOverrideIsSetAsLinuxCncReadsItBack) {
    TT_REQUIRE_LINUXCNC(lc);
    linuxcnc::ControllerOptions o;
    o.endpoint = lc->endpoint();
    o.clientName = "TrueTurnFeedOverride";
    linuxcnc::LinuxCncController c(o);
    c.connect();
    test::bringUp(c);
    c.setFeedOverride(40);
    const linuxcnc::Reply slowed = c.request("get feed_override");
    EXPECT_EQ(slowed.key, "FEED_OVERRIDE");
    EXPECT_EQ(slowed.words, std::vector<std::string>{"40"});
    EXPECT_THROW(c.setFeedOverride(0), std::invalid_argument);
    EXPECT_THROW(c.setFeedOverride(101), std::invalid_argument);
    c.setFeedOverride(100);
    EXPECT_EQ(c.request("get feed_override").words, std::vector<std::string>{"100"});
    c.disconnect();
}
