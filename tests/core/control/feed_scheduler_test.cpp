// The feed scheduling of paper 004 (Fig. 2) step by step on a model whose every number can be done by
// hand, and every request it must refuse.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/control/feed_scheduler.h"

namespace tt::core {
namespace {

/// Y = 100 a f (1 + 0.01 z) µm (natural units: the coding is the identity, valid for a 0.5..2 mm,
/// f 0.05..0.5 mm/rev, z 0..100 mm): Y falls as the tool travels from z = 100 to z = 0.
DeformationModel handModel(double slopePerMm = 0.01, double offset = 1.0) {
    const std::array<FactorCoding, 3> identity = {FactorCoding{0.0, 1.0, 0.5, 2.0}, FactorCoding{0.0, 1.0, 0.05, 0.5},
                                                  FactorCoding{0.0, 1.0, 0.0, 100.0}};
    Eigen::VectorXd b(3);
    b << 0.0, 100.0 * offset, 100.0 * slopePerMm;
    return DeformationModel(identity, {{0, 0, 0}, {1, 1, 0}, {1, 1, 1}}, b);
}

FeedScheduleRequest handRequest() {
    FeedScheduleRequest r;
    r.depthMm = 1.0;
    r.feedMinMmPerRev = 0.1;
    r.feedMaxMmPerRev = 0.4;
    r.feedStepMmPerRev = 0.05;
    r.zStartMm = 100.0;
    r.zEndMm = 0.0;
    r.levelFraction = 0.5;
    return r;
}

void expectSegment(const FeedSegment& s, double from, double to, double feed, double yFrom, double yTo) {
    EXPECT_NEAR(s.zFromMm, from, 1e-9);
    EXPECT_NEAR(s.zToMm, to, 1e-9);
    EXPECT_NEAR(s.feedMmPerRev, feed, 1e-12);
    EXPECT_NEAR(s.yFromUm, yFrom, 1e-9);
    EXPECT_NEAR(s.yToUm, yTo, 1e-9);
}

std::string refusal(const DeformationModel& model, const FeedScheduleRequest& r) {
    try {
        scheduleFeed(model, r);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    ADD_FAILURE() << "the request was accepted";
    return {};
}

// By hand: Y1 = Y(1, 0.1, 100) = 100 * 0.1 * 2 = 20 µm; Y2 = Y(1, 0.4, 0) = 40 µm; Yc = 20 + 0.5 * 20 = 30.
// Start feed: 100 f 2 = 30 -> 0.15; end feed: 100 f 1 = 30 -> 0.3. Steps of 0.05 (eq. (2)):
// f = 0.20: 20 (1 + 0.01 z) = 30 -> z = 50;  f = 0.25: 25 (1 + 0.01 z) = 30 -> z = 20;  f = 0.30 >= f_end -> z = 0.
TEST(FeedScheduler, FollowsThePapersStepsOnAHandModel) {
    const FeedSchedule s = scheduleFeed(handModel(), handRequest());
    EXPECT_NEAR(s.y1Um, 20.0, 1e-12);
    EXPECT_NEAR(s.y2Um, 40.0, 1e-12);
    EXPECT_NEAR(s.levelUm, 30.0, 1e-12);
    EXPECT_NEAR(s.feedStartMmPerRev, 0.15, 1e-14);
    EXPECT_NEAR(s.feedEndMmPerRev, 0.30, 1e-14);
    ASSERT_EQ(s.segments.size(), 3U);
    // Each segment starts at Yc and falls below it: Y(f, z_to) = 100 f (1 + 0.01 z_to).
    expectSegment(s.segments[0], 100.0, 50.0, 0.15, 30.0, 22.5);
    expectSegment(s.segments[1], 50.0, 20.0, 0.20, 30.0, 24.0);
    expectSegment(s.segments[2], 20.0, 0.0, 0.25, 30.0, 25.0);
    EXPECT_EQ(s.skippedShort, 0);
    EXPECT_DOUBLE_EQ(s.feedAtMm(75.0), 0.15);
    EXPECT_DOUBLE_EQ(s.feedAtMm(50.0), 0.20);  // the later feed at a breakpoint
    EXPECT_DOUBLE_EQ(s.feedAtMm(0.0), 0.25);
}

// The centred switch on the same model: the feed f_{i-1} hands over to f_i where the mean of the two is Yc,
// 100 (f_{i-1} + f_i) / 2 (1 + 0.01 z) = 30: 0.15 -> 0.20 at 1 + 0.01 z = 30 / 17.5 (z = 71.428571),
// 0.20 -> 0.25 at 30 / 22.5 (z = 33.333333), 0.25 -> 0.30 at 30 / 27.5 (z = 9.090909); 0.30 -> 0.35 would be at
// 30 / 32.5 < 1 (z < 0, beyond the end): 0.30 runs to z = 0. The sawtooth straddles Yc: each switch jumps from
// 30 (1 - 0.05 / 0.35) = 25.714 to 30 (1 + 0.05 / 0.35) = 34.286 µm, +-14.29 % against the paper's 25 % below.
TEST(FeedScheduler, CentredSwitchStraddlesTheLevelWithHalfTheDeviation) {
    FeedScheduleRequest r = handRequest();
    r.switchRule = FeedSwitchRule::Centred;
    const FeedSchedule s = scheduleFeed(handModel(), r);
    EXPECT_NEAR(s.levelUm, 30.0, 1e-12);
    ASSERT_EQ(s.segments.size(), 4U);
    expectSegment(s.segments[0], 100.0, 100.0 * (30.0 / 17.5 - 1.0), 0.15, 30.0, 15.0 * 30.0 / 17.5);
    expectSegment(s.segments[1], 100.0 * (30.0 / 17.5 - 1.0), 100.0 * (30.0 / 22.5 - 1.0), 0.20, 20.0 * 30.0 / 17.5,
                  20.0 * 30.0 / 22.5);
    expectSegment(s.segments[2], 100.0 * (30.0 / 22.5 - 1.0), 100.0 * (30.0 / 27.5 - 1.0), 0.25, 25.0 * 30.0 / 22.5,
                  25.0 * 30.0 / 27.5);
    expectSegment(s.segments[3], 100.0 * (30.0 / 27.5 - 1.0), 0.0, 0.30, 30.0 * 30.0 / 27.5, 30.0);
    EXPECT_NEAR(s.modelDeviationPct(), 100.0 * 0.05 / 0.35, 1e-9);
    EXPECT_NEAR(scheduleFeed(handModel(), handRequest()).modelDeviationPct(), 25.0, 1e-9);  // 22.5 against 30
    EXPECT_STREQ(feedSwitchRuleName(FeedSwitchRule::Centred), "centred");
    EXPECT_EQ(feedSwitchRuleFromName("level"), FeedSwitchRule::AtLevel);
    EXPECT_THROW(feedSwitchRuleFromName("middle"), std::invalid_argument);
}

TEST(FeedScheduler, MachiningTimesAgainstConstantFeeds) {
    // t = 60 L / (f n) at 600 rpm: 50/0.15 + 30/0.2 + 20/0.25 = 333.33 + 150 + 80 revolutions
    // -> 33.333 + 15 + 8 = 56.333 s; constant 0.1: 100 s; constant 0.4: 25 s.
    const FeedSchedule s = scheduleFeed(handModel(), handRequest());
    const MachiningTimes t = machiningTimes(s, handRequest(), 600.0);
    EXPECT_NEAR(t.scheduleS, 56.0 + 1.0 / 3.0, 1e-9);
    EXPECT_NEAR(t.feedMinS, 100.0, 1e-12);
    EXPECT_NEAR(t.feedMaxS, 25.0, 1e-12);
    EXPECT_NEAR(t.savedVsFeedMinPct(), 100.0 - (56.0 + 1.0 / 3.0), 1e-9);
    EXPECT_THROW(machiningTimes(s, handRequest(), 0.0), std::invalid_argument);
}

TEST(FeedScheduler, LevelGivenInMicrometres) {
    FeedScheduleRequest r = handRequest();
    r.levelFraction.reset();
    r.levelUm = 20.0;  // = Y1: start at fmin, 100 f 1 = 20 at the end -> f_end = 0.2
    const FeedSchedule s = scheduleFeed(handModel(), r);
    EXPECT_NEAR(s.feedStartMmPerRev, 0.1, 1e-14);
    EXPECT_NEAR(s.feedEndMmPerRev, 0.2, 1e-14);
    ASSERT_EQ(s.segments.size(), 2U);
    // f = 0.15: 15 (1 + 0.01 z) = 20 -> z = 33.33; f = 0.2 >= f_end -> end.
    expectSegment(s.segments[0], 100.0, 100.0 / 3.0, 0.1, 20.0, 10.0 * (1.0 + 1.0 / 3.0));
    expectSegment(s.segments[1], 100.0 / 3.0, 0.0, 0.15, 20.0, 15.0);
}

TEST(FeedScheduler, SkipsSegmentsShorterThanTheMinimumLength) {
    FeedScheduleRequest r = handRequest();
    r.minLengthMm = 35.0;
    // f = 0.20 -> z = 50 (50 mm, kept); f = 0.25 -> z = 20 (30 mm < 35: skipped, the next step is tried
    // from z = 50); f = 0.30 >= f_end -> the end: one segment 50 .. 0 at 0.20.
    const FeedSchedule s = scheduleFeed(handModel(), r);
    ASSERT_EQ(s.segments.size(), 2U);
    expectSegment(s.segments[0], 100.0, 50.0, 0.15, 30.0, 22.5);
    expectSegment(s.segments[1], 50.0, 0.0, 0.20, 30.0, 20.0);
    EXPECT_EQ(s.skippedShort, 1);
}

TEST(FeedScheduler, JoinsAShortLastSegmentToTheOneBefore) {
    FeedScheduleRequest r = handRequest();
    r.minLengthMm = 25.0;
    // 100 .. 50 and 50 .. 20 are long enough; the last, 20 .. 0, is 20 mm < 25 and joins 50 .. 20,
    // which keeps its lower feed 0.20 to the end (Y there 20 µm, below Yc).
    const FeedSchedule s = scheduleFeed(handModel(), r);
    ASSERT_EQ(s.segments.size(), 2U);
    expectSegment(s.segments[1], 50.0, 0.0, 0.20, 30.0, 20.0);
    EXPECT_EQ(s.skippedShort, 1);
    // A minimum length longer than the pass leaves one segment at the start feed.
    r.minLengthMm = 150.0;
    const FeedSchedule one = scheduleFeed(handModel(), r);
    ASSERT_EQ(one.segments.size(), 1U);
    expectSegment(one.segments[0], 100.0, 0.0, 0.15, 30.0, 15.0);
}

TEST(FeedScheduler, ClampsAtBothEndsInEitherDirection) {
    // The same physics mirrored: Y = 100 a f (2 - 0.01 z) falls as z grows, so the pass runs 0 -> 100.
    FeedScheduleRequest r = handRequest();
    r.zStartMm = 0.0;
    r.zEndMm = 100.0;
    const FeedSchedule s = scheduleFeed(handModel(-0.01, 2.0), r);
    ASSERT_EQ(s.segments.size(), 3U);
    EXPECT_DOUBLE_EQ(s.segments.front().zFromMm, 0.0);
    EXPECT_DOUBLE_EQ(s.segments.back().zToMm, 100.0);
    expectSegment(s.segments[0], 0.0, 50.0, 0.15, 30.0, 22.5);
    expectSegment(s.segments[1], 50.0, 80.0, 0.20, 30.0, 24.0);
    // A feed step larger than the feed range: one step reaches f_end, one segment to the end.
    r.feedStepMmPerRev = 0.3;
    const FeedSchedule big = scheduleFeed(handModel(-0.01, 2.0), r);
    ASSERT_EQ(big.segments.size(), 1U);
    EXPECT_DOUBLE_EQ(big.segments[0].zToMm, 100.0);
}

TEST(FeedScheduler, RefusesEveryInfeasibleRequestNamingTheValue) {
    const DeformationModel m = handModel();
    FeedScheduleRequest r = handRequest();
    r.levelFraction.reset();
    r.levelUm = 45.0;
    EXPECT_NE(refusal(m, r).find("the level Yc = 45 µm is outside [Y1, Y2] = [20, 40] µm"), std::string::npos);
    r.levelUm = 15.0;
    EXPECT_NE(refusal(m, r).find("Yc = 15 µm is outside"), std::string::npos);
    r.levelFraction = 0.5;
    EXPECT_NE(refusal(m, r).find("not both"), std::string::npos);
    r = handRequest();
    r.levelFraction = 1.5;
    EXPECT_NE(refusal(m, r).find("the level fraction 1.5 is outside 0 .. 1"), std::string::npos);

    r = handRequest();
    r.feedStepMmPerRev = 0.0;
    EXPECT_NE(refusal(m, r).find("the feed step f_mm 0 mm/rev must be above 0"), std::string::npos);
    r.feedStepMmPerRev = -0.01;
    EXPECT_NE(refusal(m, r).find("f_mm -0.01 mm/rev must be above 0"), std::string::npos);
    r.feedStepMmPerRev = 1e-6;
    EXPECT_NE(refusal(m, r).find("too fine"), std::string::npos);

    r = handRequest();
    r.zEndMm = 100.0;
    EXPECT_NE(refusal(m, r).find("z_start and z_end are both 100 mm"), std::string::npos);
    r = handRequest();
    r.minLengthMm = -1.0;
    EXPECT_NE(refusal(m, r).find("L_min -1 mm must not be negative"), std::string::npos);
    r = handRequest();
    r.feedMinMmPerRev = 0.0;
    EXPECT_NE(refusal(m, r).find("fmin 0 mm/rev must be above 0"), std::string::npos);
    r = handRequest();
    r.feedMaxMmPerRev = 0.1;
    EXPECT_NE(refusal(m, r).find("fmax 0.1 mm/rev must be above fmin 0.1 mm/rev"), std::string::npos);
    r = handRequest();
    r.depthMm = std::nan("");
    EXPECT_NE(refusal(m, r).find("the depth of cut is not a finite number"), std::string::npos);

    // Outside the fitted range of the model.
    r = handRequest();
    r.depthMm = 3.0;
    EXPECT_NE(refusal(m, r).find("the depth of cut 3 mm is outside the model's range 0.5 .. 2 mm"), std::string::npos);
    r = handRequest();
    r.feedMaxMmPerRev = 0.6;
    EXPECT_NE(refusal(m, r).find("fmax 0.6 mm/rev is outside the model's range 0.05 .. 0.5 mm/rev"), std::string::npos);
    r = handRequest();
    r.zStartMm = 120.0;
    EXPECT_NE(refusal(m, r).find("z_start 120 mm is outside the model's range 0 .. 100 mm"), std::string::npos);

    // Y1 > Y2: fmin at the start deforms more than fmax at the end (2 * 0.1 > 1 * 0.15).
    r = handRequest();
    r.feedMaxMmPerRev = 0.15;
    EXPECT_NE(refusal(m, r).find("no level can be held"), std::string::npos);
    EXPECT_NE(refusal(m, r).find("Y1 = Y(fmin, z_start) = 20 µm is above Y2 = Y(fmax, z_end) = 15 µm"),
              std::string::npos);

    // The pass run the wrong way (deformation rising along it): z 0 -> 100. Y1 = 10, Y2 = 80.
    r = handRequest();
    r.zStartMm = 0.0;
    r.zEndMm = 100.0;
    // Yc = 45 (fraction 0.5) needs f = 0.45 at z = 0, above fmax: no root in range.
    EXPECT_NE(refusal(m, r).find("no feed between fmin 0.1 and fmax 0.4 mm/rev gives Yc = 45 µm at z_start = 0 mm"),
              std::string::npos);
    // Yc = 20: f = 0.2 at the start but 0.1 at the end: the feed would have to fall.
    r.levelFraction.reset();
    r.levelUm = 20.0;
    EXPECT_NE(refusal(m, r).find("the deformation does not fall from z_start = 0 mm to z_end = 100 mm"),
              std::string::npos);
}

TEST(FeedScheduler, FeedAtNeedsASchedule) {
    EXPECT_THROW(FeedSchedule{}.feedAtMm(1.0), std::logic_error);
}

}  // namespace
}  // namespace tt::core
