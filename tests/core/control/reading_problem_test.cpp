// The in-process compensation's additions for the operator's panel: every reading without a
// deflection names its problem as a kind, and a new run continues from the offset the CNC holds.
#include <gtest/gtest.h>

#include "support/fake_boring_ports.h"
#include "core/control/in_process_compensation.h"

namespace tt::core {
namespace {

using test::FakeDrive;
using test::FakeOutput;
using test::FakeProbe;

ProbeSample sample(double t, double deflectionMm, bool linearised = true) {
    return test::probeSample(t, deflectionMm, linearised);
}

TEST(ReadingProblem, TheProbeSourceNamesWhyItHasNoDeflection) {
    FakeProbe probe;
    ProbeDeflectionSource source(probe, 0, std::nullopt, 2000.0, 0.5);
    probe.status = {DeviceState::Error, "no data"};
    const DeflectionReading silent = source.poll(0.0);
    EXPECT_EQ(silent.problem, ReadingProblem::SourceNotReady);
    EXPECT_EQ(silent.sourceHealth.state, DeviceState::Error);  // the device's own state and words, as data
    EXPECT_EQ(silent.sourceHealth.message, "no data");
    probe.status = {DeviceState::Ready, {}};
    probe.queue.push_back(sample(0.1, 0.05, false));  // a raw code and no table on the host
    EXPECT_EQ(source.poll(0.1).problem, ReadingProblem::NoTable);
    probe.queue.push_back(sample(0.2, -0.05));
    const DeflectionReading valid = source.poll(0.2);
    EXPECT_EQ(valid.problem, ReadingProblem::None);
    ASSERT_TRUE(valid.deflectionMm.has_value());
    const DeflectionReading quiet = source.poll(0.9);  // 0.7 s without a sample
    EXPECT_EQ(quiet.problem, ReadingProblem::NoRecentSample);
    EXPECT_DOUBLE_EQ(quiet.silenceLimitS, 0.5);  // the limit it passed, for the operator's words
}

TEST(ReadingProblem, TheCurrentSourceNamesTheEstimatorsRefusal) {
    FakeDrive drive;
    DitherEstimatorConfig config;
    config.currentToForceNPerA = 150.0;
    config.stiffnessNPerMm = 2000.0;
    CurrentDeflectionSource source(drive, config);
    EXPECT_EQ(source.poll(0.0).problem, ReadingProblem::WaitingForStrokes);
    source.estimator().setSegment(SegmentKind::Taper);  // refused from the next drive sample on
    drive.queue.push_back({0.02, 1.0, 0.1, 0.0});
    EXPECT_EQ(source.poll(0.02).problem, ReadingProblem::NotCylindrical);
    drive.status = {DeviceState::Disconnected, {}};
    EXPECT_EQ(source.poll(0.04).problem, ReadingProblem::SourceNotReady);
}

TEST(ReadingProblem, EveryKindHasAStableNameForTheCommandLine) {
    // `trueturn boring --json` prints last_hold_reason with these names.
    EXPECT_STREQ(toString(ReadingProblem::WindowTooShort), "window too short");
    EXPECT_STREQ(toString(ReadingProblem::SourceNotReady), "source not ready");
    EXPECT_STREQ(toString(OutputProblem::Refused), "refused");
    EXPECT_EQ(boringMethodFromString("probe"), BoringMethod::Probe);
    EXPECT_THROW(boringMethodFromString("laser"), std::invalid_argument);
}

TEST(InProcessCompensator, ResumesFromTheOffsetTheCncHolds) {
    FakeProbe probe;
    FakeOutput output;
    ProbeDeflectionSource source(probe, 0, std::nullopt, 2000.0, 0.5);
    InProcessCompensator compensator(source, output, {0.5, 0.05}, 0.02);
    compensator.resumeFrom(0.2);
    EXPECT_DOUBLE_EQ(compensator.offsetMm(), 0.2);
    probe.queue.push_back(sample(0.0, -0.25));  // target +0.25 mm
    const CompensationCycle c = compensator.cycle(0.0);
    ASSERT_TRUE(c.sent);
    // One rate-limited step up from 0.2 mm (0.05 mm/s × 20 ms), not from 0.
    EXPECT_NEAR(output.sent.back(), 0.201, 1e-12);
    // An offset beyond the range is taken back to the limit.
    InProcessCompensator other(source, output, {0.5, 0.05}, 0.02);
    other.resumeFrom(0.8);
    EXPECT_DOUBLE_EQ(other.offsetMm(), 0.5);
}

}  // namespace
}  // namespace tt::core
