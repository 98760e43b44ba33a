// Every reason the in-process compensation holds the offset, and every refusal of the run builder,
// has its own plain words, made here from the engine's kinds and data (the engine sends no
// sentence); only a device's own message is passed on, as the detail.
#include "ui/boring/hold_reason.h"

#include <gtest/gtest.h>

namespace tt::ui {
namespace {

core::CompensationCycle holding(core::ReadingProblem problem) {
    core::CompensationCycle c;
    c.reading.problem = problem;
    c.reading.silenceLimitS = 0.5;
    c.step.holding = true;
    c.step.offsetMm = 0.1234;
    return c;
}

TEST(HoldReason, EachProblemIsSaidPlainlyWithTheHeldOffset) {
    const struct {
        core::ReadingProblem problem;
        core::BoringMethod method;
        const char* words;
    } cases[] = {
        {core::ReadingProblem::NotCylindrical, core::BoringMethod::Current, "Taper or contour"},
        {core::ReadingProblem::SlideNotMoving, core::BoringMethod::Current, "does not move with the dither"},
        {core::ReadingProblem::WindowTooShort, core::BoringMethod::Current, "too short for this PLC cycle"},
        {core::ReadingProblem::WaitingForStrokes, core::BoringMethod::Current, "forward and a reverse dither stroke"},
        {core::ReadingProblem::SourceNotReady, core::BoringMethod::Current, "drive current read-out is silent"},
        {core::ReadingProblem::SourceNotReady, core::BoringMethod::Probe, "probe mandrel is silent"},
        {core::ReadingProblem::NoRecentSample, core::BoringMethod::Probe,
         "No data from the probe mandrel for more "
         "than 500 ms"},
        {core::ReadingProblem::NoTable, core::BoringMethod::Probe, "without a linearisation table"},
    };
    for (const auto& c : cases) {
        const CycleWords w = describeCycle(holding(c.problem), c.method);
        EXPECT_TRUE(w.holding);
        EXPECT_EQ(w.headline, QStringLiteral("Holding the offset at 0.123 mm"));
        EXPECT_TRUE(w.reason.contains(QString::fromUtf8(c.words))) << w.reason.toStdString();
    }
}

TEST(HoldReason, ASilentDevicesOwnWordsAreTheDetail) {
    core::CompensationCycle c = holding(core::ReadingProblem::SourceNotReady);
    c.reading.sourceHealth = {core::DeviceState::Error, "no answer from the simulated drive for 3 polls"};
    const CycleWords w = describeCycle(c, core::BoringMethod::Current);
    EXPECT_EQ(w.detail, QStringLiteral("The device reports: no answer from the simulated drive for 3 polls"));
    c.reading.sourceHealth = {core::DeviceState::Disconnected, {}};
    EXPECT_EQ(describeCycle(c, core::BoringMethod::Current).detail, QStringLiteral("The device reports: disconnected"));
    EXPECT_TRUE(
        describeCycle(holding(core::ReadingProblem::WindowTooShort), core::BoringMethod::Current).detail.isEmpty());
}

TEST(HoldReason, ACncNotReadyOrRefusingTheOffsetIsNamed) {
    core::CompensationCycle refused = holding(core::ReadingProblem::None);
    refused.outputProblem = core::OutputProblem::Refused;
    refused.outputMessage = "read-back 0.0990 mm differs from 0.1000 mm";
    const CycleWords w = describeCycle(refused, core::BoringMethod::Probe);
    EXPECT_TRUE(w.holding);
    EXPECT_TRUE(w.reason.contains(QStringLiteral("CNC does not take the offset: read-back"))) << w.reason.toStdString();
    core::CompensationCycle busy = holding(core::ReadingProblem::None);
    busy.outputProblem = core::OutputProblem::NotReady;
    busy.outputHealth = {core::DeviceState::Connecting, {}};  // a relay whose device has not taken the offset yet
    const CycleWords b = describeCycle(busy, core::BoringMethod::Current);
    EXPECT_EQ(b.reason, QStringLiteral("The CNC output is not answering yet."));
    EXPECT_TRUE(b.detail.isEmpty());
}

TEST(HoldReason, CompensatingSaysWhetherALimitIsReached) {
    core::CompensationCycle c;
    c.step.offsetMm = 0.05;
    EXPECT_FALSE(describeCycle(c, core::BoringMethod::Current).holding);
    EXPECT_EQ(describeCycle(c, core::BoringMethod::Current).headline, QStringLiteral("Compensating"));
    c.step.rateLimited = true;
    EXPECT_TRUE(describeCycle(c, core::BoringMethod::Current).reason.contains(QStringLiteral("rate limit")));
    c.step.rangeLimited = true;
    EXPECT_TRUE(describeCycle(c, core::BoringMethod::Current).reason.contains(QStringLiteral("range limit")));
}

TEST(HoldReason, TheRunBuildersRefusalsAreWordedWithTheirValues) {
    using R = core::BoringRunRefusal;
    EXPECT_TRUE(describeRefusal(core::BoringRunRefused(R::NoStiffness)).contains(QStringLiteral("Tools page")));
    EXPECT_TRUE(describeRefusal(core::BoringRunRefused(R::NoCurrentGain)).contains(QStringLiteral("Calibration page")));
    EXPECT_EQ(describeRefusal(core::BoringRunRefused(R::HeldOffsetBeyondLimit, 0.3, -0.2, 0.2)),
              QStringLiteral("The CNC holds an offset of 0.300 mm, more than the limit of 0.200 mm: zero the offset "
                             "first (tool out of the bore)."));
    EXPECT_EQ(describeRefusal(core::BoringRunRefused(R::PlcCycleOutOfRange, 0.2, 0.01, 0.1)),
              QStringLiteral("The PLC cycle of 200 ms is outside 10 to 100 ms."));
}

}  // namespace
}  // namespace tt::ui
