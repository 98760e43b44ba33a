// The probe-mandrel linearisation as a state machine, without a widget, against the simulator's
// calibration stand (core/sim/rigs: ProbeCalibrationRig, the 12-bit inductive probe of paper 001
// with its RC filter, ratiometric ADC and noise): capture with hold-still and averaging, points
// repeated, aborted and refused, saturated points flagged and left out of the fit, the fit and its
// refusals as kinds, verification points, and the upload with read-back of the CRC.
#include "core/calibration/probe_procedure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/calibration/linearisation_image.h"
#include "core/sim/rigs/probe_calibration_rig.h"

namespace tt::core {
namespace {

class ProbeProcedureTest : public ::testing::Test {
protected:
    /// Lets the rig run for `seconds` in steps of 50 ms, the procedure taking its samples.
    void run(double seconds) {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.05) {
            rig.advance(0.05);
            procedure.pumpProbe(rig, 0.05);
        }
    }
    /// Bends the bar to `um`, reads the dial indicator and captures; returns the events.
    std::vector<ProbeEvent> captureAt(double um) {
        rig.setJackMm(um / 1000.0);
        procedure.loadChanged();
        procedure.capture(rig.dialIndicatorUm());
        for (int i = 0; i < 100 && procedure.capturing(); ++i)
            run(0.05);
        return procedure.takeEvents();
    }
    void captureSweep() {
        for (int i = 0; i <= 20; ++i) {
            const auto events = captureAt(-450.0 + 45.0 * i);
            ASSERT_EQ(events.size(), 1u);
            ASSERT_EQ(events[0].kind, ProbeEvent::Kind::PointCaptured);
        }
    }

    InductiveProbe probe{InductiveProbeConfig{}, 5};  // 12 bits, ±588 µm full scale at the tip
    ProbeCalibrationRig rig{probe, 0, 1.0, 0.3, 6};   // dial indicator: 1 µm division, 0.3 µm RMS
    ProbeLinearisationProcedure procedure{ProbeProcedureConfig{}};
};

TEST_F(ProbeProcedureTest, HoldsStillThenAveragesFiftySamplesPerPoint) {
    rig.setJackMm(0.3);
    procedure.loadChanged();
    procedure.capture(300.0);
    EXPECT_EQ(procedure.sampling().phase(), ProbeCapture::Phase::HoldStill);
    run(0.05);  // within the 0.1 s settling: nothing is averaged yet
    EXPECT_EQ(procedure.sampling().phase(), ProbeCapture::Phase::HoldStill);
    run(0.1);
    EXPECT_EQ(procedure.sampling().phase(), ProbeCapture::Phase::Averaging);
    run(0.6);  // 100 conversions per second
    ASSERT_FALSE(procedure.capturing());
    const auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ProbeEvent::Kind::PointCaptured);
    EXPECT_EQ(events[0].point, 1);
    const ProbePoint& p = procedure.points().at(0);
    EXPECT_EQ(p.samples, 50);
    EXPECT_FALSE(p.saturated);
    // The mean of 50 settled codes against the static characteristic: amplifier noise 0.05 % of
    // the half range (≈ 1 code RMS) averages to ≈ 0.15 code; the ratiometric ADC cancels the supply.
    EXPECT_NEAR(p.adcCode, probe.staticCode(0.3), 1.0);
    EXPECT_LE(p.lowestCode, p.adcCode);
    EXPECT_GE(p.highestCode, p.adcCode);
}

TEST_F(ProbeProcedureTest, CapturesASweepAndFitsTheOddCubicWithDegreeThree) {
    EXPECT_FALSE(procedure.next());  // fewer than 5 points
    captureSweep();
    ASSERT_TRUE(procedure.canFit());
    ASSERT_TRUE(procedure.next());
    EXPECT_EQ(procedure.step(), ProbeLinearisationProcedure::Step::Fit);
    const auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ProbeEvent::Kind::Fitted);
    const ProbeFitOutcome& fit = procedure.fitOutcome();
    ASSERT_TRUE(fit.usable());
    // The bridge is an odd cubic in the gap (r = 0.8 u + 0.15 u³): cross-validation picks 3, as
    // ProbeCalibrationRig.LinearisesTheSimulatedMandrelWithDegreeThree finds from whole sweeps.
    EXPECT_EQ(fit.fit->degree, 3);
    EXPECT_TRUE(fit.fit->chosenAutomatically);
    EXPECT_TRUE(fit.leftOut.empty());
    EXPECT_LT(fit.linearisation->maxTableErrorUm, 2.0);
}

TEST_F(ProbeProcedureTest, FlagsSaturatedPointsAndLeavesThemOutOfTheFit) {
    captureSweep();
    // Beyond full scale (588 µm at the tip) the 12-bit ADC reads 4095: the point is flagged.
    auto events = captureAt(700.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_TRUE(events[0].value.saturated);
    EXPECT_EQ(events[0].value.highestCode, 4095);
    // A typed code at the ADC's lower limit is saturated too.
    procedure.typePoint(-650.0, 0.0);
    EXPECT_TRUE(procedure.points().back().saturated);
    ASSERT_TRUE(procedure.next());
    const ProbeFitOutcome& fit = procedure.fitOutcome();
    EXPECT_EQ(fit.leftOut, (std::vector<int>{22, 23}));
    ASSERT_TRUE(fit.usable());
    EXPECT_EQ(fit.fit->degree, 3);  // the clipped codes would have bent the curve
    EXPECT_DOUBLE_EQ(fit.fit->calibratedMaxUm, procedure.points()[20].referenceUm);
}

TEST_F(ProbeProcedureTest, RepeatsAPointAndStopsOnAbortALoadChangeOrAProbeFault) {
    captureAt(100.0);
    captureAt(200.0);
    // Point 1 again at another load: the new reading replaces it.
    rig.setJackMm(0.15);
    procedure.loadChanged();
    procedure.repeatPoint(0, 150.0);
    run(1.0);
    auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ProbeEvent::Kind::PointRepeated);
    EXPECT_EQ(events[0].point, 1);
    ASSERT_EQ(procedure.points().size(), 2u);
    EXPECT_EQ(procedure.points()[0].referenceUm, 150.0);
    EXPECT_NEAR(procedure.points()[0].adcCode, probe.staticCode(0.15), 1.0);

    procedure.capture(150.0);
    procedure.abort();
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ProbeEvent::Kind::CaptureFailed);
    EXPECT_EQ(events[0].problem, CaptureProblem::Aborted);

    procedure.capture(150.0);
    run(0.2);
    procedure.loadChanged();  // the jack moved while the point was read
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].problem, CaptureProblem::LoadChanged);

    procedure.capture(150.0);
    rig.setDisconnected(true);
    run(0.1);
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].problem, CaptureProblem::NotReady);
    EXPECT_EQ(events[0].deviceMessage, "the simulated mandrel does not answer");
    rig.setDisconnected(false);

    procedure.capture(150.0);  // the stand is stopped: no sample for 3 s of wall time
    for (int i = 0; i < 30; ++i)
        procedure.pumpProbe(rig, 0.1);
    events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].problem, CaptureProblem::NoSamples);
    EXPECT_EQ(procedure.points().size(), 2u);  // none of these made a point
}

TEST_F(ProbeProcedureTest, RefusesAFitWithItsKindAndData) {
    for (int i = 0; i < 5; ++i)
        procedure.typePoint(100.0, 2300.0 + i);  // one reference only
    ASSERT_TRUE(procedure.next());
    EXPECT_EQ(procedure.fitOutcome().refusal, ProbeFitRefusal::TooFewReferences);
    EXPECT_EQ(procedure.fitOutcome().needed, 4);  // degree 2: its 3 coefficients and one more
    EXPECT_EQ(procedure.fitOutcome().got, 1);
    EXPECT_EQ(procedure.takeEvents().back().kind, ProbeEvent::Kind::FitRefused);
    EXPECT_FALSE(procedure.accept());

    // A cubic that turns at ±288.7 µm (code = 2047.5 + 3 d − 1.2e-5 d³), fitted with degree 3.
    procedure.back();
    for (int i = 0; i < 5; ++i)
        procedure.removePoint(0);
    for (int i = 0; i <= 20; ++i) {
        const double um = -450.0 + 45.0 * i;
        procedure.typePoint(um, 2047.5 + 3.0 * um - 1.2e-5 * um * um * um);
    }
    procedure.setDegree(3);
    ASSERT_TRUE(procedure.next());
    const ProbeFitOutcome& fit = procedure.fitOutcome();
    EXPECT_EQ(fit.refusal, ProbeFitRefusal::NonMonotonic);
    ASSERT_TRUE(fit.fit && fit.fit->monotonicity.turningDeflectionUm);
    EXPECT_TRUE(fit.fit->monotonicity.insideCalibratedRange);
    EXPECT_NEAR(std::abs(*fit.fit->monotonicity.turningDeflectionUm), 288.7, 0.5);
}

TEST_F(ProbeProcedureTest, VerifiesTheTableAtACheckPointAndRefusesAcceptanceWhenACheckFails) {
    captureSweep();
    ASSERT_TRUE(procedure.next());
    procedure.takeEvents();
    // A check at 123 µm, between the points: the table reads it within the tolerance
    // (half a division + 3 × the fit's residual RMS + the table's step).
    rig.setJackMm(0.123);
    procedure.loadChanged();
    procedure.check(rig.dialIndicatorUm());
    run(1.0);
    auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    ASSERT_EQ(events[0].kind, ProbeEvent::Kind::CheckDone);
    ASSERT_TRUE(events[0].check);
    EXPECT_TRUE(events[0].check->passed) << events[0].check->deviationUm << " µm";
    EXPECT_NEAR(events[0].check->readingUm, 123.0, events[0].check->toleranceUm);
    // The operator read the dial wrong by 20 µm: the check fails and the table is not accepted.
    procedure.check(rig.dialIndicatorUm() + 20.0);
    run(1.0);
    events = procedure.takeEvents();
    ASSERT_TRUE(events.at(0).check);
    EXPECT_FALSE(events[0].check->passed);
    EXPECT_FALSE(procedure.accept());
    EXPECT_EQ(procedure.takeEvents().back().kind, ProbeEvent::Kind::AcceptRefused);
    // Another degree is another table: its checks start again.
    procedure.setDegree(4);
    EXPECT_TRUE(procedure.checks().empty());
    EXPECT_TRUE(procedure.accept());
    EXPECT_EQ(procedure.step(), ProbeLinearisationProcedure::Step::Accepted);
}

TEST_F(ProbeProcedureTest, UploadsTheTableAndVerifiesItsReadBackThenTheMandrelLinearises) {
    captureSweep();
    ASSERT_TRUE(procedure.next());
    ASSERT_TRUE(procedure.accept());
    ASSERT_TRUE(procedure.next());
    ASSERT_EQ(procedure.step(), ProbeLinearisationProcedure::Step::Upload);
    TableImageInfo info;
    info.version = 7;
    std::vector<std::uint8_t> image = encodeTableImage(procedure.fitOutcome().linearisation->table, info);
    procedure.takeEvents();
    procedure.startUpload(rig, image, 7);
    EXPECT_EQ(procedure.upload().phase(), TableUploadProcedure::Phase::Sending);
    for (int i = 0; i < 200 && procedure.upload().running(); ++i) {
        rig.advance(0.1);
        procedure.pumpUpload(rig, 0.1);
    }
    ASSERT_EQ(procedure.upload().phase(), TableUploadProcedure::Phase::Verified);
    EXPECT_EQ(procedure.takeEvents().back().kind, ProbeEvent::Kind::UploadVerified);
    ASSERT_TRUE(procedure.upload().readback());
    EXPECT_EQ(procedure.upload().readback()->version, 7);
    EXPECT_EQ(procedure.upload().readback()->crc32c, tableUploadCrc(image));
    // The mandrel now reads deflections through the uploaded table (3 µm: the fit and the
    // table's step on a 12-bit ADC).
    rig.setJackMm(0.2);
    rig.advance(0.5);
    std::optional<ProbeSample> last;
    while (auto s = rig.takeSample())
        last = s;
    ASSERT_TRUE(last && last->linearised);
    EXPECT_NEAR(last->deflectionMm[0], 0.2, 0.003);
}

TEST_F(ProbeProcedureTest, AFaultyFlashFailsTheReadBackAndARefusedUploadSaysWhy) {
    captureSweep();
    ASSERT_TRUE(procedure.next() && procedure.accept() && procedure.next());
    const std::vector<std::uint8_t> image =
        encodeTableImage(procedure.fitOutcome().linearisation->table, TableImageInfo{});
    rig.setFaultyFlash(true);
    procedure.takeEvents();
    procedure.startUpload(rig, image, 1);
    for (int i = 0; i < 200 && procedure.upload().running(); ++i) {
        rig.advance(0.1);
        procedure.pumpUpload(rig, 0.1);
    }
    EXPECT_EQ(procedure.upload().phase(), TableUploadProcedure::Phase::Mismatch);
    EXPECT_EQ(procedure.upload().problem(), TableUploadProcedure::Problem::ReadbackDiffers);
    ASSERT_TRUE(procedure.upload().readback());
    EXPECT_FALSE(procedure.upload().readback()->valid);  // the firmware refused the corrupt image
    const auto events = procedure.takeEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ProbeEvent::Kind::UploadFailed);

    rig.setDisconnected(true);
    procedure.startUpload(rig, image, 2);
    EXPECT_EQ(procedure.upload().phase(), TableUploadProcedure::Phase::Failed);
    EXPECT_EQ(procedure.upload().problem(), TableUploadProcedure::Problem::Refused);
    EXPECT_EQ(procedure.upload().deviceMessage(), "the mandrel does not answer");
}

TEST(ProbeProcedure, KeepsItsPointsWhenGoingBackAndRefusesActionsOutOfStep) {
    ProbeLinearisationProcedure p;
    for (int i = 0; i < 5; ++i)
        p.typePoint(-200.0 + 100.0 * i, 2047.0 + 3.0 * (-200.0 + 100.0 * i));
    ASSERT_TRUE(p.next());
    EXPECT_THROW(p.typePoint(0.0, 2047.0), std::logic_error);  // points change only while capturing
    EXPECT_THROW(p.configure(1, 12, 1.0), std::logic_error);
    p.back();
    EXPECT_EQ(p.step(), ProbeLinearisationProcedure::Step::Capture);
    EXPECT_EQ(p.points().size(), 5u);
    EXPECT_THROW(p.check(0.0), std::logic_error);
    EXPECT_THROW(p.typePoint(0.0, 4096.0), std::invalid_argument);  // beyond a 12-bit ADC
    EXPECT_THROW(p.configure(2, 12, 1.0), std::invalid_argument);
    EXPECT_THROW(p.configure(0, 17, 1.0), std::invalid_argument);
    p.configure(1, 16, 0.5);
    EXPECT_EQ(p.config().adcBits, 16);
    EXPECT_EQ(p.points().size(), 5u);
}

}  // namespace
}  // namespace tt::core
