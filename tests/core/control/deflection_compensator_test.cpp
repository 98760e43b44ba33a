// In-process compensation (issue 6, item 6): rate and range limits, holding the last safe offset,
// and the PLC cycle through the CorrectionOutput port.
#include "core/control/deflection_compensator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "core/control/in_process_compensation.h"

namespace tt::core {
namespace {

TEST(DeflectionCompensator, RampsAtTheRateLimitToMinusTheDeflection) {
    DeflectionCompensator c({0.5, 0.2});
    // 20 ms cycles at 0.2 mm/s: at most 0.004 mm per cycle, so 0.1 mm takes 25 cycles.
    for (int i = 1; i <= 24; ++i) {
        const CompensationStep s = c.step(0.02, -0.1);
        EXPECT_TRUE(s.rateLimited);
        EXPECT_NEAR(s.offsetMm, 0.004 * i, 1e-12);
        EXPECT_DOUBLE_EQ(s.targetMm, 0.1);
    }
    const CompensationStep last = c.step(0.02, -0.1);
    EXPECT_NEAR(last.offsetMm, 0.1, 1e-12);
    EXPECT_FALSE(c.step(0.02, -0.1).rateLimited);
}

TEST(DeflectionCompensator, ClampsToTheRange) {
    DeflectionCompensator c({0.5, 100.0});
    const CompensationStep s = c.step(0.02, -0.8);
    EXPECT_TRUE(s.rangeLimited);
    EXPECT_DOUBLE_EQ(s.offsetMm, 0.5);
    EXPECT_DOUBLE_EQ(c.step(0.02, 0.9).offsetMm, -0.5);
}

TEST(DeflectionCompensator, HoldsTheLastOffsetWithoutAValidDeflection) {
    DeflectionCompensator c({0.5, 100.0});
    c.step(0.02, -0.12);
    CompensationStep s = c.step(0.02, std::nullopt);
    EXPECT_TRUE(s.holding);
    EXPECT_DOUBLE_EQ(s.targetMm, 0.12);  // no new target: the last offset
    EXPECT_DOUBLE_EQ(s.offsetMm, 0.12);
    s = c.step(0.02, std::nan(""));
    EXPECT_TRUE(s.holding);
    EXPECT_DOUBLE_EQ(s.offsetMm, 0.12);
    EXPECT_THROW(c.step(0.0, -0.1), std::invalid_argument);
    EXPECT_THROW(DeflectionCompensator({0.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(DeflectionCompensator({1.0, -1.0}), std::invalid_argument);
}

struct FakeSource final : DeflectionSource {
    std::deque<DeflectionReading> readings;
    std::vector<double> offsetSpeeds;
    std::string name() const override { return "fake"; }
    DeflectionReading poll(double) override {
        DeflectionReading r = readings.front();
        if (readings.size() > 1) readings.pop_front();
        return r;
    }
    void offsetMoving(double v) override { offsetSpeeds.push_back(v); }
};

struct FakeOutput final : CorrectionOutput {
    DeviceHealth status{DeviceState::Ready, {}};
    bool refuse = false;
    std::vector<double> sent;
    DeviceHealth health() const override { return status; }
    OutputResult sendPartCorrection(const PartCorrection&) override { return {false, "unused"}; }
    OutputResult sendDynamicOffset(double x) override {
        if (refuse) return {false, "PLC register write not acknowledged"};
        sent.push_back(x);
        return {true, {}};
    }
};

DeflectionReading deflection(double mm) {
    DeflectionReading r;
    r.deflectionMm = mm;
    r.fresh = true;
    return r;
}

TEST(InProcessCompensator, SendsTheLimitedOffsetEveryCycleAndTellsTheSourceItsSpeed) {
    FakeSource source;
    source.readings = {deflection(-0.01)};
    FakeOutput output;
    InProcessCompensator comp(source, output, {0.5, 0.2}, 0.02);
    for (int i = 0; i < 4; ++i)
        comp.cycle(0.02 * i);
    // 0.004, 0.008, 0.01, 0.01: the last equal value is sent again (the PLC register is refreshed).
    ASSERT_EQ(output.sent.size(), 4u);
    EXPECT_NEAR(output.sent[0], 0.004, 1e-12);
    EXPECT_NEAR(output.sent[2], 0.01, 1e-12);
    EXPECT_NEAR(source.offsetSpeeds[0], 0.2, 1e-9);  // 0.004 mm in 20 ms
    EXPECT_NEAR(source.offsetSpeeds[3], 0.0, 1e-9);
}

TEST(InProcessCompensator, HoldsWhatTheCncHasWhenAWriteFailsOrTheOutputIsDown) {
    FakeSource source;
    source.readings = {deflection(-0.1)};
    FakeOutput output;
    InProcessCompensator comp(source, output, {0.5, 1.0}, 0.02);
    comp.cycle(0.0);  // 0.02 sent
    output.refuse = true;
    CompensationCycle c = comp.cycle(0.02);
    EXPECT_FALSE(c.sent);
    EXPECT_EQ(c.outputProblem, OutputProblem::Refused);
    EXPECT_EQ(c.outputMessage, "PLC register write not acknowledged");  // the output's own words, passed on
    EXPECT_TRUE(c.step.holding);
    EXPECT_NEAR(comp.offsetMm(), 0.02, 1e-12);
    output.refuse = false;
    output.status = {DeviceState::Error, "no answer from the PLC for 0.5 s"};
    c = comp.cycle(0.04);
    EXPECT_EQ(c.outputProblem, OutputProblem::NotReady);
    EXPECT_EQ(c.outputHealth.state, DeviceState::Error);
    EXPECT_EQ(c.outputHealth.message, "no answer from the PLC for 0.5 s");
    EXPECT_TRUE(c.step.holding);
    EXPECT_NEAR(comp.offsetMm(), 0.02, 1e-12);
    output.status = {DeviceState::Ready, {}};
    EXPECT_NEAR(comp.cycle(0.06).step.offsetMm, 0.04, 1e-12);  // resumes from what the CNC holds
}

TEST(InProcessCompensator, AcceptsOnlyPlcCyclesOfTenToAHundredMilliseconds) {
    FakeSource source;
    source.readings = {deflection(0.0)};
    FakeOutput output;
    EXPECT_THROW(InProcessCompensator(source, output, {}, 0.005), std::invalid_argument);
    EXPECT_THROW(InProcessCompensator(source, output, {}, 0.2), std::invalid_argument);
    EXPECT_NO_THROW(InProcessCompensator(source, output, {}, 0.01));
    EXPECT_NO_THROW(InProcessCompensator(source, output, {}, 0.1));
}

}  // namespace
}  // namespace tt::core
