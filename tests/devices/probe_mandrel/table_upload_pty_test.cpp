// A real 16-bit linearisation table (core/calibration, 131 104-byte image of format 2) uploaded by
// the probe-mandrel plugin through a real pseudo-terminal pair to the emulated mandrel: chunked,
// CRC-32C checked by the mandrel, read back and verified; the mandrel then holds a table that
// inverts its own bridge.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <cmath>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "devices/api/steady_clock.h"
#include "devices/probe_mandrel/probe_mandrel_factory.h"
#include "support/mandrel_on_pty.h"

namespace tt::devices {
namespace {

std::unique_ptr<Device> openProbe(ProbeMandrelFactory& factory, SteadyClock& clock, const QString& port) {
    const QVariantMap settings{{QStringLiteral("port"), port},
                               {QStringLiteral("baud"), 115200},
                               {QStringLiteral("rateHz"), 100},
                               {QStringLiteral("replyTimeoutMs"), 300}};
    auto device = factory.create(DeviceKind::Probe, settings, DeviceContext{&clock});
    device->open();
    return device;
}

/// The calibration a commissioning engineer does on the stand: 21 loads over ±0.27 mm, the
/// mandrel's ADC code against a dial indicator read to 1 µm.
core::Linearisation calibrateEmulatedMandrel() {
    std::vector<core::CalibrationPoint> points;
    for (int i = 0; i <= 20; ++i) {
        const double um = -270.0 + 27.0 * i;
        points.push_back({std::round(um), static_cast<double>(MandrelEmulator::adcCode(um / 1000.0)), 0});
    }
    return core::linearise(points, 16, core::kAutoDegree);
}

TEST(ProbeProtocol2OverPty, UploadsASixteenBitTableAndReadsBackItsCrc32c) {
    test::MandrelOnPty end(QStringLiteral("ttyP16"));
    SteadyClock clock;
    ProbeMandrelFactory factory;
    auto device = openProbe(factory, clock, end.pty.portName());
    ASSERT_TRUE(QTest::qWaitFor([&] { return device->health().ready(); }, 3000)) << device->health().message;
    TableUploadTarget* target = device->tableUploadTarget();
    ASSERT_NE(target, nullptr);
    const auto info = target->mandrelInfo();
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->protocol, 2);
    EXPECT_EQ(info->adcBits, 16);
    EXPECT_EQ(info->maxTableBytes, 262144U);

    const core::Linearisation lin = calibrateEmulatedMandrel();
    const std::vector<std::uint8_t> image = core::encodeTableImage(lin.table, {2, 1'741'900'000, 0, 3});
    ASSERT_EQ(image.size(), 131104U);  // over the 64 KiB of protocol 1
    const std::uint32_t crc = core::tableUploadCrc(image);
    QElapsedTimer took;
    took.start();
    target->uploadTable(image, 2, crc);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return target->uploadStatus().phase != TableUploadStatus::Phase::Running; }, 60000));
    ASSERT_EQ(target->uploadStatus().phase, TableUploadStatus::Phase::Done)
        << target->uploadStatus().message.toStdString();
    std::printf("16-bit table: %zu bytes, 1025 chunks, uploaded and verified over the pty in %lld ms\n", image.size(),
                static_cast<long long>(took.elapsed()));
    // Read back: version, size and the CRC-32C the mandrel computed over what its flash holds.
    const auto back = target->tableInfo();
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->version, 2);
    EXPECT_EQ(back->sizeBytes, image.size());
    EXPECT_EQ(back->crc32c, crc);
    EXPECT_EQ(back->crc, core::crc16Ccitt(image));
    EXPECT_TRUE(back->valid);
    EXPECT_EQ(end.mandrel.tableImage(), image);
    // What arrived is a table of the mandrel's own bridge: 1 µm indicator divisions and rounded
    // codes allow about half a micrometre.
    const core::TableImage stored = core::decodeTableImage(end.mandrel.tableImage());
    for (double mm = -0.25; mm <= 0.25; mm += 0.025)
        EXPECT_NEAR(stored.table.deflectionUm(MandrelEmulator::adcCode(mm)), mm * 1000.0, 0.6) << mm << " mm";
    EXPECT_TRUE(device->health().ready());
}

TEST(ProbeProtocol2OverPty, AProtocolOneMandrelRefusesASixteenBitTableWithTheReason) {
    test::MandrelOnPty end(QStringLiteral("ttyP16OLD"), 1);
    SteadyClock clock;
    ProbeMandrelFactory factory;
    auto device = openProbe(factory, clock, end.pty.portName());
    ASSERT_TRUE(QTest::qWaitFor([&] { return device->health().ready(); }, 3000)) << device->health().message;
    TableUploadTarget* target = device->tableUploadTarget();
    ASSERT_TRUE(target->mandrelInfo().has_value());
    EXPECT_EQ(target->mandrelInfo()->protocol, 1);
    EXPECT_FALSE(target->mandrelInfo()->adcBits.has_value());
    const std::vector<std::uint8_t> image = core::encodeTableImage(calibrateEmulatedMandrel().table, {2, 0, 0, 3});
    try {
        target->uploadTable(image, 2, core::tableUploadCrc(image));
        FAIL() << "a protocol-1 mandrel took a 128 KiB table";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("protocol 1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("131104"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(end.mandrel.tableImage().empty());
    EXPECT_TRUE(device->health().ready());
}

}  // namespace
}  // namespace tt::devices
