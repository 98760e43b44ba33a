// The k_p calibration from known loads as a state machine, without a widget, against the
// simulator's known-load stand (core/sim/rigs: KnownLoadRig, the heavy-boring cross feed with its
// dither: true k_p 150 N/A, Coulomb friction 975 N, current noise 0.3 A) through the dither
// estimator's current difference: hold still, average the stroke pairs, next load, fit, verify.
#include "core/calibration/kp_procedure.h"

#include <gtest/gtest.h>

#include <deque>

#include "core/control/dither_current_difference.h"
#include "core/sim/rigs/known_load_rig.h"

namespace tt::core {
namespace {

class KpProcedureTest : public ::testing::Test {
protected:
    /// Lets the stand run for `seconds` in PLC cycles of 20 ms, the procedure taking the samples.
    void run(double seconds) {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.02) {
            rig.advance(0.02);
            procedure.pump(rig, 0.02);
        }
    }
    std::vector<KpEvent> measureAt(double loadN) {
        rig.setLoadN(loadN);
        procedure.measure(loadN);
        for (int i = 0; i < 1000 && procedure.measuring(); ++i)
            run(0.02);
        return procedure.takeEvents();
    }

    // The stand of the former built-in simulated cross feed: dither 0.01 mm, 0.5 s, 60 % at
    // constant velocity; one sample per 20 ms PLC cycle; seed 3.
    KnownLoadRig rig{CrossFeedDriveConfig{}, DitherConfig{0.01, 0.5, 0.6}, 0.02, 3};
    KpCalibrationProcedure procedure{std::make_unique<DitherCurrentDifference>()};
};

TEST_F(KpProcedureTest, HoldsStillThenAveragesTheStrokePairsOfEachLoad) {
    run(2.0);  // the dither runs before the first load
    ASSERT_TRUE(procedure.liveDifferenceA().has_value());
    rig.setLoadN(300.0);
    procedure.measure(300.0);
    EXPECT_FALSE(procedure.liveDifferenceA().has_value());  // the strokes under no load are forgotten
    run(0.9);
    EXPECT_EQ(procedure.phase(), KpCalibrationProcedure::Phase::HoldStill);  // the first second settles
    EXPECT_EQ(procedure.pairs(), 0);
    run(0.2);
    EXPECT_EQ(procedure.phase(), KpCalibrationProcedure::Phase::Averaging);
    for (int i = 0; i < 500 && procedure.measuring(); ++i)
        run(0.02);
    const auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, KpEvent::Kind::LoadMeasured);
    // 12 pairs at a 0.5 s dither period: six seconds of averaging.
    EXPECT_EQ(events[0].value.pairs, 12);
    // ΔI = (load − offset) / k_p: 2 A, give or take the 15 N of offset the four-load fit below
    // allows (0.1 A).
    EXPECT_NEAR(events[0].value.currentDifferenceA, 300.0 / 150.0, 0.1);
}

TEST_F(KpProcedureTest, RecoversTheTrueGainOfTheSimulatedDriveAndVerifiesIt) {
    EXPECT_FALSE(procedure.next());  // no load yet
    for (double load : {0.0, 200.0, 400.0, 600.0}) {
        const auto events = measureAt(load);
        ASSERT_EQ(events.size(), 1u);
        ASSERT_EQ(events[0].kind, KpEvent::Kind::LoadMeasured) << static_cast<int>(events[0].problem);
    }
    ASSERT_TRUE(procedure.next());
    ASSERT_TRUE(procedure.fitOutcome().fit.has_value());
    EXPECT_EQ(procedure.takeEvents().back().kind, KpEvent::Kind::Fitted);
    const KpFit& f = *procedure.fitOutcome().fit;
    // As KpCalibration.RecoversTheSimulatedDrivesGainThroughTheDitherEstimator: within 3 % of 150 N/A.
    EXPECT_NEAR(f.kpNPerA, 150.0, 150.0 * 0.03);
    EXPECT_NEAR(f.offsetN, 0.0, 15.0);
    EXPECT_GT(f.r2, 0.999);
    // Verification at 300 N, a load not used by the fit.
    rig.setLoadN(300.0);
    procedure.check(300.0);
    for (int i = 0; i < 1000 && procedure.measuring(); ++i)
        run(0.02);
    auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    ASSERT_TRUE(events[0].check);
    EXPECT_TRUE(events[0].check->passed) << events[0].check->deviationN << " N";
    EXPECT_NEAR(events[0].check->forceN, 300.0, events[0].check->toleranceN);
    // The gauge was misread (the jack pushes 300 N, 450 N was entered): the check fails.
    procedure.check(450.0);
    for (int i = 0; i < 1000 && procedure.measuring(); ++i)
        run(0.02);
    events = procedure.takeEvents();
    ASSERT_TRUE(events.at(0).check);
    EXPECT_FALSE(events[0].check->passed);
    EXPECT_FALSE(procedure.accept());
    // Back to the loads and forward again: the fit is made again and its checks start over.
    procedure.back();
    ASSERT_TRUE(procedure.next());
    EXPECT_TRUE(procedure.checks().empty());
    EXPECT_TRUE(procedure.accept());
    EXPECT_TRUE(procedure.accepted());
}

TEST_F(KpProcedureTest, RepeatsALoadAndStopsOnAbortOrAReadoutFault) {
    measureAt(0.0);
    measureAt(200.0);
    rig.setLoadN(0.0);
    procedure.repeatPoint(0);
    EXPECT_EQ(procedure.loadN(), 0.0);  // the load of the point repeated
    for (int i = 0; i < 1000 && procedure.measuring(); ++i)
        run(0.02);
    auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, KpEvent::Kind::LoadRepeated);
    EXPECT_EQ(events[0].point, 1);
    EXPECT_EQ(procedure.points().size(), 2u);

    procedure.measure(400.0);
    run(0.5);
    procedure.abort();
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, KpEvent::Kind::MeasureFailed);
    EXPECT_EQ(events[0].problem, KpMeasureProblem::Aborted);

    procedure.measure(400.0);  // the stand is stopped: no sample for 3 s of wall time
    for (int i = 0; i < 30; ++i)
        procedure.pump(rig, 0.1);
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].problem, KpMeasureProblem::NoSamples);
    EXPECT_EQ(procedure.points().size(), 2u);
}

/// A drive read-out that the test feeds by hand.
class ScriptedReadout final : public DriveCurrentReadout {
public:
    DeviceHealth health() const override { return state; }
    std::optional<DriveSample> takeSample() override {
        if (samples.empty()) return std::nullopt;
        const DriveSample s = samples.front();
        samples.pop_front();
        return s;
    }
    DeviceHealth state{DeviceState::Ready, {}};
    std::deque<DriveSample> samples;
};

TEST(KpProcedure, SaysWhyALoadGaveNoCurrentDifference) {
    KpCalibrationProcedure p(std::make_unique<DitherCurrentDifference>());
    ScriptedReadout readout;
    p.measure(100.0);
    // The dither is off: the slide stands still for 8 s of PLC cycles.
    for (int i = 0; i < 400; ++i)
        readout.samples.push_back({0.02 * i, 1.5, 0.0, 0.0});
    p.pump(readout, 8.0);
    auto events = p.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, KpEvent::Kind::MeasureFailed);
    EXPECT_EQ(events[0].problem, KpMeasureProblem::TooFewPairs);
    EXPECT_EQ(events[0].strokeProblem, StrokeProblem::SlideNotMoving);

    p.measure(100.0);
    readout.state = {DeviceState::Error, "no answer from the drive for 3 polls"};
    p.pump(readout, 0.1);
    events = p.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].problem, KpMeasureProblem::NotReady);
    EXPECT_EQ(events[0].deviceMessage, "no answer from the drive for 3 polls");
}

TEST(KpProcedure, RefusesLoadsThatFallWithTheCurrentAsAKindWithTheSlope) {
    KpCalibrationProcedure p(std::make_unique<DitherCurrentDifference>());
    p.typePoint(0.0, 1.0);
    p.typePoint(100.0, 0.5);
    EXPECT_FALSE(p.canFit());  // 3 loads at least
    p.typePoint(200.0, 0.0);
    ASSERT_TRUE(p.next());
    ASSERT_TRUE(p.fitOutcome().refusal.has_value());
    EXPECT_EQ(*p.fitOutcome().refusal, KpFitProblem::FallsWithLoad);
    EXPECT_NEAR(p.fitOutcome().slopeNPerA, -200.0, 1e-9);  // ΔI falls by 0.5 A per 100 N
    EXPECT_EQ(p.takeEvents().back().kind, KpEvent::Kind::FitRefused);
    EXPECT_FALSE(p.accept());
    EXPECT_THROW(p.measure(0.0), std::logic_error);  // loads are measured in the Capture step
    p.back();
    for (int i = 0; i < 3; ++i)
        p.removePoint(0);
    for (double load : {0.0, 100.0, 200.0})
        p.typePoint(load, load / 200.0);
    ASSERT_TRUE(p.next());
    EXPECT_NEAR(p.fitOutcome().fit->kpNPerA, 200.0, 1e-9);
}

}  // namespace
}  // namespace tt::core
