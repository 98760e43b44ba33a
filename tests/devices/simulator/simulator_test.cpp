// The built-in simulator: every device kind stand-alone, the fault switches, and the inputs a
// lathe simulator plugs in.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTest>
#include <numeric>

#include "core/common/crc32c.h"
#include "devices/api/simulated_instrument.h"
#include "devices/api/steady_clock.h"
#include "devices/simulator/simulated_drive.h"
#include "devices/simulator/simulated_output.h"
#include "devices/simulator/simulated_probe.h"
#include "devices/simulator/simulator_plugin.h"

namespace tt::devices {
namespace {

class SimulatorTest : public ::testing::Test {
protected:
    std::unique_ptr<Device> make(DeviceKind kind, const QVariantMap& settings = {}) {
        auto d = plugin.create(kind, settings, DeviceContext{&clock});
        d->open();
        EXPECT_TRUE(QTest::qWaitFor([&] { return d->health().state == core::DeviceState::Ready; }, 2000))
            << d->health().message;
        return d;
    }
    static bool waitState(Device& d, core::DeviceState s, int ms = 2000) {
        return QTest::qWaitFor([&] { return d.health().state == s; }, ms);
    }
    template <typename Take>
    static auto collect(Take take, int ms) {
        std::vector<std::decay_t<decltype(*take())>> got;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            QTest::qWait(10);
            while (auto s = take())
                got.push_back(*s);
        }
        return got;
    }

    SteadyClock clock;
    SimulatorPlugin plugin;
};

TEST_F(SimulatorTest, MakesEveryKindWithItsPort) {
    EXPECT_EQ(plugin.kinds().size(), 4);
    for (DeviceKind kind : allDeviceKinds()) {
        auto d = make(kind);
        EXPECT_NE(tt::devices::simulatedInstrument(*d), nullptr);
        EXPECT_EQ(d->diameterGauge() != nullptr, kind == DeviceKind::Gauge);
        EXPECT_EQ(d->deflectionProbe() != nullptr, kind == DeviceKind::Probe);
        EXPECT_EQ(d->driveCurrentReadout() != nullptr, kind == DeviceKind::DriveCurrent);
        EXPECT_EQ(d->correctionOutput() != nullptr, kind == DeviceKind::CorrectionOutput);
    }
}

TEST_F(SimulatorTest, GaugeMeasuresTheInjectedDiametersAtItsResolution) {
    auto d = make(DeviceKind::Gauge, {{QStringLiteral("decimals"), 3}});
    std::vector<double> truth{27.01234, 26.99951, 27.1};
    std::size_t next = 0;
    tt::devices::simulatedInstrument(*d)->simulationInputs().setDiameterSource([&] { return truth[next++]; });
    for (std::size_t i = 0; i < truth.size(); ++i)
        d->diameterGauge()->requestReading();
    std::vector<double> got;
    while (auto r = d->diameterGauge()->takeReading())
        got.push_back(r->diameterMm);
    EXPECT_EQ(got, (std::vector<double>{27.012, 27.0, 27.1}));  // rounded like a 0.001 mm micrometer
}

TEST_F(SimulatorTest, GaugeFaultSwitches) {
    auto d =
        make(DeviceKind::Gauge, {{QStringLiteral("nominalDiameterMm"), 30.0}, {QStringLiteral("replyTimeoutMs"), 150}});
    FaultSwitches* f = &tt::devices::simulatedInstrument(*d)->faultSwitches();
    auto* gauge = d->diameterGauge();
    // Stuck: the same value, whatever the source says.
    gauge->requestReading();
    f->stuck = true;
    tt::devices::simulatedInstrument(*d)->simulationInputs().setDiameterSource([] { return 31.0; });
    gauge->requestReading();
    EXPECT_DOUBLE_EQ(gauge->takeReading()->diameterMm, 30.0);
    EXPECT_DOUBLE_EQ(gauge->takeReading()->diameterMm, 30.0);
    f->stuck = false;
    // Noisy: within the amplitude, not all equal.
    f->noisy = true;
    f->noiseAmplitude = 0.01;
    std::vector<double> noisy;
    for (int i = 0; i < 20; ++i) {
        gauge->requestReading();
        noisy.push_back(gauge->takeReading()->diameterMm);
    }
    const auto [lo, hi] = std::minmax_element(noisy.begin(), noisy.end());
    EXPECT_GE(*lo, 30.99 - 0.0005);
    EXPECT_LE(*hi, 31.01 + 0.0005);
    EXPECT_GT(*hi - *lo, 0.002);
    f->noisy = false;
    // Malformed: the frame is refused by the parser, nothing reaches the port.
    f->malformed = true;
    gauge->requestReading();
    EXPECT_FALSE(gauge->takeReading().has_value());
    EXPECT_FALSE(d->lastError().isEmpty());
    f->malformed = false;
    // Silent: no answer, then an error after the reply timeout.
    f->silent = true;
    gauge->requestReading();
    ASSERT_TRUE(waitState(*d, core::DeviceState::Error));
    EXPECT_NE(d->health().message.find("no answer from the simulated gauge"), std::string::npos);
    f->silent = false;
    gauge->requestReading();
    EXPECT_EQ(d->health().state, core::DeviceState::Ready);
    // Disconnect: error until plugged in again.
    f->disconnected = true;
    ASSERT_TRUE(waitState(*d, core::DeviceState::Error));
    EXPECT_NE(d->health().message.find("unplugged"), std::string::npos);
    f->disconnected = false;
    ASSERT_TRUE(waitState(*d, core::DeviceState::Ready));
}

TEST_F(SimulatorTest, GaugeRefusesInchReadingsOnAMillimetreJob) {
    auto d = make(DeviceKind::Gauge, {{QStringLiteral("instrumentUnit"), QStringLiteral("in")}});
    d->diameterGauge()->requestReading();
    EXPECT_FALSE(d->diameterGauge()->takeReading().has_value());
    EXPECT_TRUE(d->lastError().contains(QStringLiteral("refused"))) << d->lastError().toStdString();
}

TEST_F(SimulatorTest, ProbeStreamsTheInjectedDeflectionAndCountsCorruptFrames) {
    auto d = make(DeviceKind::Probe, {{QStringLiteral("rateHz"), 500}});
    tt::devices::simulatedInstrument(*d)->simulationInputs().setDeflectionSource([](double) { return std::array<double, 2>{0.0421, -0.0013}; });
    (void)collect([&] { return d->deflectionProbe()->takeSample(); }, 50);
    const auto samples = collect([&] { return d->deflectionProbe()->takeSample(); }, 100);
    ASSERT_FALSE(samples.empty());
    EXPECT_NEAR(samples.back().deflectionMm[0], 0.0421, 1e-6);
    EXPECT_TRUE(samples.back().linearised);
    tt::devices::simulatedInstrument(*d)->faultSwitches().malformed = true;
    const auto during = collect([&] { return d->deflectionProbe()->takeSample(); }, 100);
    for (const auto& s : during)
        EXPECT_NEAR(s.deflectionMm[0], 0.0421, 1e-6);
    QString corrupt;
    for (const auto& s : d->statistics())
        if (s.label == QStringLiteral("Frames corrupt")) corrupt = s.value;
    EXPECT_GT(corrupt.toInt(), 0);
    tt::devices::simulatedInstrument(*d)->faultSwitches().malformed = false;
    tt::devices::simulatedInstrument(*d)->faultSwitches().silent = true;
    ASSERT_TRUE(waitState(*d, core::DeviceState::Error));
    tt::devices::simulatedInstrument(*d)->faultSwitches().silent = false;
    ASSERT_TRUE(waitState(*d, core::DeviceState::Ready));
}

TEST_F(SimulatorTest, ProbeTakesATableUpload) {
    auto d = make(DeviceKind::Probe);
    std::vector<std::uint8_t> image(500);
    std::iota(image.begin(), image.end(), std::uint8_t{3});
    d->tableUploadTarget()->uploadTable(image, 9, core::crc32c(image));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return d->tableUploadTarget()->uploadStatus().phase == TableUploadStatus::Phase::Done; }, 3000))
        << d->tableUploadTarget()->uploadStatus().message.toStdString();
    EXPECT_EQ(dynamic_cast<SimulatedProbe&>(*d).emulator().tableImage(), image);
    EXPECT_EQ(d->tableUploadTarget()->tableInfo()->version, 9);
}

TEST_F(SimulatorTest, DriveOscillatesAsInPaper001) {
    // Triangle of amplitude 0.02 mm and period 1 s: velocity +-0.08 mm/s; current = 0.6 +- 2.0 A.
    const auto forward = oscillatingCrossFeed(0.25, 0.02, 1.0, 2.0, 0.6);
    EXPECT_NEAR(forward.positionMm, 0.0, 1e-12);
    EXPECT_NEAR(forward.velocityMmPerS, 0.08, 1e-12);
    EXPECT_NEAR(forward.currentA, 2.6, 1e-12);
    const auto back = oscillatingCrossFeed(0.75, 0.02, 1.0, 2.0, 0.6);
    EXPECT_NEAR(back.velocityMmPerS, -0.08, 1e-12);
    EXPECT_NEAR(back.currentA, -1.4, 1e-12);
    // Half the difference of the magnitudes is the cutting component (paper 001).
    EXPECT_NEAR((std::fabs(forward.currentA) - std::fabs(back.currentA)) / 2.0, 0.6, 1e-12);
    auto d = make(DeviceKind::DriveCurrent, {{QStringLiteral("pollMs"), 10}});
    const auto samples = collect([&] { return d->driveCurrentReadout()->takeSample(); }, 100);
    ASSERT_GE(samples.size(), 3u);
    for (const auto& s : samples)
        EXPECT_NEAR(std::fabs(s.currentA - 0.6), 2.0, 0.006);  // int16 in 0.01 A
    tt::devices::simulatedInstrument(*d)->faultSwitches().malformed = true;
    EXPECT_TRUE(collect([&] { return d->driveCurrentReadout()->takeSample(); }, 50).empty());
    EXPECT_TRUE(d->lastError().contains(QStringLiteral("NaN")));
}

TEST_F(SimulatorTest, OutputVerifiesAndForwardsCorrections) {
    auto d = make(DeviceKind::CorrectionOutput);
    std::vector<double> forwarded;
    tt::devices::simulatedInstrument(*d)->simulationInputs().setOffsetSink([&](double x) { forwarded.push_back(x); });
    EXPECT_TRUE(d->correctionOutput()->sendDynamicOffset(-0.0123).ok);
    EXPECT_EQ(forwarded, std::vector<double>{-0.0123});
    EXPECT_NEAR(*dynamic_cast<SimulatedOutput&>(*d).plcOffsetMm(), -0.0123, 1e-12);
    tt::devices::simulatedInstrument(*d)->faultSwitches().malformed = true;
    const core::OutputResult r = d->correctionOutput()->sendDynamicOffset(0.02);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.message.find("read-back mismatch"), std::string::npos);
    EXPECT_EQ(d->health().state, core::DeviceState::Error);
    EXPECT_EQ(forwarded.size(), 1u);  // the failed one never reached the machine
}

}  // namespace
}  // namespace tt::devices
