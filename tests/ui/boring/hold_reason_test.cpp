// Every reason the in-process compensation holds the offset has its own plain words.
#include "ui/boring/hold_reason.h"

#include <gtest/gtest.h>

namespace tt::ui {
namespace {

core::CompensationCycle holding(core::ReadingProblem problem, const std::string& engine = "engine words") {
    core::CompensationCycle c;
    c.reading.problem = problem;
    c.reading.reason = engine;
    c.step.holding = true;
    c.step.reason = engine;
    c.step.offsetMm = 0.1234;
    return c;
}

TEST(HoldReason, EachProblemIsSaidPlainlyWithTheHeldOffset) {
    const struct {
        core::ReadingProblem problem;
        BoringSource source;
        const char* words;
    } cases[] = {
        {core::ReadingProblem::NotCylindrical, BoringSource::Current, "Taper or contour"},
        {core::ReadingProblem::SlideNotMoving, BoringSource::Current, "does not move with the dither"},
        {core::ReadingProblem::WindowTooShort, BoringSource::Current, "too short for this PLC cycle"},
        {core::ReadingProblem::WaitingForStrokes, BoringSource::Current, "forward and a reverse dither stroke"},
        {core::ReadingProblem::SourceNotReady, BoringSource::Current, "drive current read-out is silent"},
        {core::ReadingProblem::SourceNotReady, BoringSource::Probe, "probe mandrel is silent"},
        {core::ReadingProblem::NoRecentSample, BoringSource::Probe, "No data from the probe mandrel"},
        {core::ReadingProblem::NoTable, BoringSource::Probe, "without a linearisation table"},
    };
    for (const auto& c : cases) {
        const CycleWords w = describeCycle(holding(c.problem), c.source);
        EXPECT_TRUE(w.holding);
        EXPECT_EQ(w.headline, QStringLiteral("Holding the offset at 0.123 mm"));
        EXPECT_TRUE(w.reason.contains(QString::fromUtf8(c.words))) << w.reason.toStdString();
        EXPECT_EQ(w.detail, QStringLiteral("engine words"));  // the engine's sentence, for the engineer
    }
}

TEST(HoldReason, ACncRefusingTheOffsetIsNamedAndAnUnknownReasonFallsBackToTheEnginesWords) {
    core::CompensationCycle refused = holding(core::ReadingProblem::None);
    refused.outputError = "read-back 0.0990 mm differs from 0.1000 mm";
    const CycleWords w = describeCycle(refused, BoringSource::Probe);
    EXPECT_TRUE(w.holding);
    EXPECT_TRUE(w.reason.contains(QStringLiteral("CNC does not take the offset: read-back"))) << w.reason.toStdString();
    const CycleWords other = describeCycle(holding(core::ReadingProblem::None, "something new"), BoringSource::Current);
    EXPECT_EQ(other.reason, QStringLiteral("something new"));
}

TEST(HoldReason, CompensatingSaysWhetherALimitIsReached) {
    core::CompensationCycle c;
    c.step.offsetMm = 0.05;
    EXPECT_FALSE(describeCycle(c, BoringSource::Current).holding);
    EXPECT_EQ(describeCycle(c, BoringSource::Current).headline, QStringLiteral("Compensating"));
    c.step.rateLimited = true;
    EXPECT_TRUE(describeCycle(c, BoringSource::Current).reason.contains(QStringLiteral("rate limit")));
    c.step.rangeLimited = true;
    EXPECT_TRUE(describeCycle(c, BoringSource::Current).reason.contains(QStringLiteral("range limit")));
}

}  // namespace
}  // namespace tt::ui
