// The probe-mandrel plugin through a real pseudo-terminal pair, with the emulated
// microcontroller (devices/simulator/mandrel_emulator.h) at the mandrel's end.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <QTimer>
#include <numeric>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"
#include "devices/api/steady_clock.h"
#include "devices/probe_mandrel/probe_mandrel_factory.h"
#include "devices/simulator/mandrel_emulator.h"
#include "support/mandrel_on_pty.h"

namespace tt::devices {
namespace {

using test::MandrelOnPty;

class SerialProbeTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> make(const QString& port, int rateHz = 200) {
        const QVariantMap settings{{QStringLiteral("port"), port},
                                   {QStringLiteral("baud"), 115200},
                                   {QStringLiteral("rateHz"), rateHz},
                                   {QStringLiteral("silenceTimeoutMs"), 200},
                                   {QStringLiteral("replyTimeoutMs"), 100}};
        EXPECT_TRUE(factory.validate(DeviceKind::Probe, settings, Validation::Full).isEmpty());
        return factory.create(DeviceKind::Probe, settings, DeviceContext{&clock});
    }
    static bool waitState(Device& d, core::DeviceState s, int ms = 3000) {
        return QTest::qWaitFor([&] { return d.health().state == s; }, ms);
    }
    static std::vector<core::ProbeSample> collect(core::DeflectionProbe& p, int ms) {
        std::vector<core::ProbeSample> got;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            QTest::qWait(10);
            while (auto s = p.takeSample())
                got.push_back(*s);
        }
        return got;
    }
    static QString stat(const Device& d, const QString& label) {
        for (const auto& s : d.statistics())
            if (s.label == label) return s.value;
        return {};
    }

    SteadyClock clock;
    ProbeMandrelFactory factory;
};

TEST_F(SerialProbeTest, HandshakeThenLinearisedSamplesAtTheSetRate) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    end.mandrel.preloadTable(std::vector<std::uint8_t>(256, 1), 3);
    auto device = make(end.pty.portName(), 200);
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready)) << device->health().message;
    EXPECT_EQ(end.mandrel.rateHz(), 200);
    EXPECT_TRUE(end.mandrel.streaming());
    const auto samples = collect(*device->deflectionProbe(), 300);
    // 200 Hz for 0.3 s: about 60 samples (timer jitter on a shared machine: generous bounds).
    EXPECT_GT(samples.size(), 30u);
    EXPECT_LT(samples.size(), 100u);
    for (const auto& s : samples) {
        EXPECT_TRUE(s.linearised);
        EXPECT_NEAR(s.deflectionMm[0], 0.020, 1e-6);  // the emulator's default bending
        EXPECT_NEAR(s.deflectionMm[1], -0.005, 1e-6);
        EXPECT_EQ(s.adcCode[0], MandrelEmulator::adcCode(0.020));
        // The emulator's bridge: u = 0.02 mm * 0.8505 (coils at 0.9 of the overhang) / 0.25 mm,
        // r = 1.15 u - 0.15 u^3, code = (1 + r) / 2 * 65535 = 35329.88.
        EXPECT_EQ(s.adcCode[0], 35330);
    }
    const auto info = device->tableUploadTarget()->tableInfo();
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->version, 3);
    EXPECT_EQ(info->crc, core::crc16Ccitt(std::vector<std::uint8_t>(256, 1)));
}

TEST_F(SerialProbeTest, WithoutATableSamplesAreRawCodesOnly) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    const auto samples = collect(*device->deflectionProbe(), 100);
    ASSERT_FALSE(samples.empty());
    EXPECT_FALSE(samples.front().linearised);
    EXPECT_EQ(samples.front().adcCode[1], MandrelEmulator::adcCode(-0.005));
}

TEST_F(SerialProbeTest, LostDuplicatedAndCorruptFramesAreCountedAndNeverUsed) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    end.mandrel.preloadTable(std::vector<std::uint8_t>(16, 2), 1);
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    // The count of samples used is taken with the mandrel quiet for a moment (nothing on the line, nothing queued),
    // so that it compares exactly with the samples taken.
    const auto quietCount = [&](std::vector<core::ProbeSample>* into) {
        end.mandrel.setSilent(true);
        const auto got = collect(*device->deflectionProbe(), 100);
        if (into) into->insert(into->end(), got.begin(), got.end());
        const QString count = stat(*device, QStringLiteral("Samples used"));
        end.mandrel.setSilent(false);
        return count.toULongLong();
    };
    (void)collect(*device->deflectionProbe(), 50);
    const auto usedBefore = quietCount(nullptr);
    std::vector<core::ProbeSample> samples;
    auto more = [&] {
        const auto got = collect(*device->deflectionProbe(), 100);
        samples.insert(samples.end(), got.begin(), got.end());
    };
    end.mandrel.dropNextFrames(3);
    more();
    end.mandrel.duplicateNextFrames(2);
    more();
    end.mandrel.corruptNextFrames(4);
    more();
    ASSERT_FALSE(samples.empty());
    for (const auto& s : samples)
        EXPECT_NEAR(s.deflectionMm[0], 0.020, 1e-6);  // nothing corrupt got through
    EXPECT_EQ(stat(*device, QStringLiteral("Frames corrupt")), QStringLiteral("4"));
    EXPECT_EQ(stat(*device, QStringLiteral("Frames duplicated")), QStringLiteral("2"));
    EXPECT_EQ(stat(*device, QStringLiteral("Frames lost")), QStringLiteral("7"));  // 3 dropped + 4 corrupt
    // Each sample used once: the duplicates were not delivered a second time.
    const auto used = quietCount(&samples) - usedBefore;
    EXPECT_EQ(used, samples.size());
    (void)collect(*device->deflectionProbe(), 50);
    EXPECT_EQ(device->health().state, core::DeviceState::Ready);
    EXPECT_TRUE(device->lastError().contains(QStringLiteral("corrupt"))) << device->lastError().toStdString();
}

TEST_F(SerialProbeTest, TableUploadIsChunkedStoredAndVerified) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    std::vector<std::uint8_t> image(1000);
    std::iota(image.begin(), image.end(), std::uint8_t{0});
    const std::uint32_t crc = core::crc32c(image);
    TableUploadTarget* target = device->tableUploadTarget();
    target->uploadTable(image, 7, crc);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return target->uploadStatus().phase != TableUploadStatus::Phase::Running; }, 5000));
    EXPECT_EQ(target->uploadStatus().phase, TableUploadStatus::Phase::Done)
        << target->uploadStatus().message.toStdString();
    EXPECT_EQ(end.mandrel.tableImage(), image);
    EXPECT_EQ(end.mandrel.tableInfo().version, 7);
    EXPECT_EQ(target->tableInfo()->crc32c, crc);  // protocol 2 reads back the CRC-32C
    EXPECT_EQ(target->tableInfo()->crc, core::crc16Ccitt(image));
    // Samples are linearised from now on.
    (void)collect(*device->deflectionProbe(), 50);
    const auto samples = collect(*device->deflectionProbe(), 50);
    ASSERT_FALSE(samples.empty());
    EXPECT_TRUE(samples.back().linearised);
}

TEST_F(SerialProbeTest, UploadWithChunkErrorsOnTheLineStillSucceedsByResending) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    std::vector<std::uint8_t> image(600, 0xAB);
    TableUploadTarget* target = device->tableUploadTarget();
    target->uploadTable(image, 2, core::crc32c(image));
    end.mandrel.corruptNextFrames(3);  // some ACKs (and samples) get corrupted on the way back
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return target->uploadStatus().phase != TableUploadStatus::Phase::Running; }, 5000));
    EXPECT_EQ(target->uploadStatus().phase, TableUploadStatus::Phase::Done)
        << target->uploadStatus().message.toStdString();
    EXPECT_EQ(end.mandrel.tableImage(), image);
}

TEST_F(SerialProbeTest, AFlashErrorInTheMandrelFailsVerification) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    end.mandrel.setFaultyFlash(true);
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    std::vector<std::uint8_t> image(300, 0x11);
    TableUploadTarget* target = device->tableUploadTarget();
    target->uploadTable(image, 4, core::crc32c(image));
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return target->uploadStatus().phase != TableUploadStatus::Phase::Running; }, 5000));
    EXPECT_EQ(target->uploadStatus().phase, TableUploadStatus::Phase::Failed);
    EXPECT_TRUE(target->uploadStatus().message.contains(QStringLiteral("verification failed")))
        << target->uploadStatus().message.toStdString();
    EXPECT_THROW(target->uploadTable(image, 4, 0x1234), std::invalid_argument);  // CRC does not match the image
}

TEST_F(SerialProbeTest, SilenceIsAnErrorAndStreamingRecovers) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    end.mandrel.setSilent(true);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_NE(device->health().message.find("no data from the probe mandrel"), std::string::npos);
    end.mandrel.setSilent(false);
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
}

TEST_F(SerialProbeTest, AMandrelThatNeverAnswersIsReportedByCommand) {
    test::PtyPair pty(QStringLiteral("ttyDEAD"));
    auto device = make(pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    EXPECT_NE(device->health().message.find("does not answer READ_DEVICE_INFO (3 tries)"), std::string::npos)
        << device->health().message;
}

TEST_F(SerialProbeTest, UnplugMidStreamGoesToErrorAndReconnectRecovers) {
    MandrelOnPty end(QStringLiteral("ttyPROBE"));
    auto device = make(end.pty.portName());
    device->open();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready));
    end.pty.releaseSlave();
    ASSERT_FALSE(collect(*device->deflectionProbe(), 50).empty());
    end.pty.unplug();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Error));
    end.pty.plug();
    ASSERT_TRUE(waitState(*device, core::DeviceState::Ready, 5000)) << device->health().message;
    (void)collect(*device->deflectionProbe(), 20);
    EXPECT_FALSE(collect(*device->deflectionProbe(), 100).empty());
}

TEST_F(SerialProbeTest, TwoProbesRunAtOnce) {
    MandrelOnPty left(QStringLiteral("ttyLEFT"));
    MandrelOnPty right(QStringLiteral("ttyRIGHT"));
    left.mandrel.preloadTable({1, 2, 3}, 1);
    right.mandrel.preloadTable({4, 5, 6}, 1);
    right.mandrel.setDeflectionSource([](double) { return std::array<double, 2>{-0.031, 0.002}; });
    auto a = make(left.pty.portName());
    auto b = make(right.pty.portName(), 100);
    a->open();
    b->open();
    ASSERT_TRUE(waitState(*a, core::DeviceState::Ready));
    ASSERT_TRUE(waitState(*b, core::DeviceState::Ready));
    const auto sa = collect(*a->deflectionProbe(), 100);
    const auto sb = collect(*b->deflectionProbe(), 100);
    ASSERT_FALSE(sa.empty());
    ASSERT_FALSE(sb.empty());
    EXPECT_NEAR(sa.back().deflectionMm[0], 0.020, 1e-6);
    EXPECT_NEAR(sb.back().deflectionMm[0], -0.031, 1e-6);
    EXPECT_EQ(right.mandrel.rateHz(), 100);
}

}  // namespace
}  // namespace tt::devices
