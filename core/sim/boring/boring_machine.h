#pragma once

#include <deque>
#include <functional>
#include <string>

#include "core/calibration/probe_linearisation.h"
#include "core/control/deflection_compensator.h"
#include "core/control/dither_force_estimator.h"
#include "core/model/tool_stiffness.h"
#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"
#include "core/sim/boring/cross_feed_drive.h"
#include "core/sim/boring/dither_profile.h"
#include "core/sim/boring/inductive_probe.h"

namespace tt::core {

/// The finishing boring pass (paper 001): the tool enters the pre-bored hole and feeds along Z;
/// the radial cutting force P = K_r · f · a · hardness(z) · wear(z) pushes the tool towards the
/// axis, and the actual depth a falls by the deflection it causes (a = a_nom + x_tip).
struct BoringCutConfig {
    double boreLengthMm = 500.0;
    double feedMmPerRev = 0.3;
    double spindleRpm = 190.0;
    double radialSpecificForceNPerMm2 = 1000.0;  ///< K_r: radial force per mm² of chip section
    double tangentialToRadialRatio = 2.5;        ///< main (tangential) force / radial force
    double depthStartMm = 0.8;                   ///< radial stock at the bore entry, mm
    double depthEndMm = 1.2;                     ///< radial stock at the bore end (pre-bored hole tapered), mm
    double hardnessVariation = 0.1;              ///< ± share of the force from hardness along the bore
    double hardnessWavelengthMm = 150.0;
    double wearForceIncrease = 0.15;  ///< force grows by this share along the bore (flank wear)
    double approachMm = 3.0;          ///< air travel before the tool meets the face, mm
    double entryRampMm = 1.0;         ///< the nose enters the stock over this length, mm
    double gaugeMarginMm = 5.0;       ///< the bore is gauged from this far inside each end, mm
    double boreToleranceMm = 0.0;     ///< diameter tolerance of the finished bore, mm (0: not given)
};

/// How the simulated mandrel is calibrated before a probe run (a jack loads the bar tip; a dial
/// indicator gives the reference).
struct ProbeCalibrationConfig {
    int points = 21;
    int readingsPerPoint = 16;
    double spanFraction = 0.9;           ///< share of the probe's full-scale deflection covered, ±
    double referenceResolutionUm = 1.0;  ///< dial indicator division, µm
    double referenceNoiseUm = 0.3;       ///< reading error of the indicator, RMS µm
    int degree = kAutoDegree;
};

/// A complete boring scenario (the preset `heavy-boring` is one).
struct BoringScenario {
    std::string name;
    std::string description;
    ToolRecord tool;                   ///< what the tool table says (k_st and k_p used by the estimator)
    double trueStiffnessFactor = 1.0;  ///< real bar stiffness / tool-table stiffness (clamping compliance)
    BoringCutConfig cut;
    CrossFeedDriveConfig drive;
    DitherConfig dither;
    InductiveProbeConfig probe;
    ProbeCalibrationConfig calibration;
    DitherEstimatorConfig estimator;  ///< thresholds; k_p and k_st are taken from `tool`
    CompensatorLimits limits;
    double plcCycleS = 0.02;
    double simStepS = 1.0e-4;
    unsigned long long seed = 1;
};

/// The longest simulated boring pass (approach and bore at feed x spindle speed), s: 2 hours.
inline constexpr double kMaxBoringPassS = 7200.0;
/// The most simulation steps of one pass (heavy-boring needs 5.3e6).
inline constexpr double kMaxBoringSteps = 1e8;

/// Throws std::invalid_argument naming the first bad value of the scenario, and a pass longer than
/// kMaxBoringPassS or kMaxBoringSteps.
void validateScenario(const BoringScenario& scenario);

/// State of the tool at one instant of the simulation.
struct BoringState {
    double timeS = 0.0;
    double toolZMm = 0.0;       ///< axial position of the tool; 0 = bore entry face
    double radialForceN = 0.0;  ///< P, pushing the tool towards the axis, N
    double tangentialForceN = 0.0;
    double tipDeflectionXmm = 0.0;  ///< −P / k_true, mm
    double tipDeflectionYmm = 0.0;
    double radiusErrorMm = 0.0;  ///< machined radius minus nominal where the tool is, mm
    double slidePositionMm = 0.0;
    double appliedOffsetMm = 0.0;  ///< dynamic offset the PLC is applying, mm
    bool cutting = false;
};

/// The simulated lathe for one boring pass, with the ports the engine uses: the cross-feed drive
/// read-out (one sample per PLC cycle), the probe mandrel (samples at its rate, linearised by its
/// table when one is loaded) and the correction output (dynamic offset applied from the next PLC
/// cycle, spread over it by the interpolator).
class BoringMachine {
public:
    /// `dither` switches on the cross-feed oscillation (needed by the current method only).
    BoringMachine(const BoringScenario& scenario, bool dither);

    /// Called at every simulation step while the tool is in the bore.
    using SurfaceObserver = std::function<void(const BoringState&)>;
    /// Sets the observer (replaces the previous one; empty: none).
    void setSurfaceObserver(SurfaceObserver observer) { m_observer = std::move(observer); }

    /// Advances by one PLC cycle (many simulation steps) and queues the port samples.
    void advanceCycle();
    /// The tool has left the far end of the bore.
    bool finished() const;
    /// The machine's state after the last step.
    const BoringState& state() const { return m_state; }
    /// The PLC cycle of the scenario, s.
    double plcCycleS() const { return m_scenario.plcCycleS; }
    /// True radial bar stiffness, N/mm.
    double trueStiffnessNPerMm() const { return m_stiffnessX; }

    /// The drive-current read-out port (what the compensation from current reads).
    DriveCurrentReadout& driveReadout() { return m_drivePort; }
    /// The probe-mandrel port (what the compensation from the probe reads).
    DeflectionProbe& probe() { return m_probePort; }
    /// The CNC output port (the cross slide's dynamic offset).
    CorrectionOutput& output() { return m_outputPort; }
    /// The simulated sensor behind the probe port (its table can be loaded).
    InductiveProbe& probeSensor() { return m_probe; }
    /// The simulated cross-feed drive.
    CrossFeedDrive& drive() { return m_drive; }

    /// Switches the drive read-out into a fault (tests of holding the last safe correction).
    void setDriveHealth(DeviceHealth health) { m_drivePort.status = std::move(health); }
    /// Switches the probe port into a fault likewise.
    void setProbeHealth(DeviceHealth health) { m_probePort.status = std::move(health); }

private:
    struct DrivePort final : DriveCurrentReadout {
        DeviceHealth status{DeviceState::Ready, {}};
        std::deque<DriveSample> queue;
        core::DeviceHealth health() const override { return status; }
        std::optional<DriveSample> takeSample() override;
    };
    struct ProbePort final : DeflectionProbe {
        DeviceHealth status{DeviceState::Ready, {}};
        std::deque<ProbeSample> queue;
        core::DeviceHealth health() const override { return status; }
        std::optional<ProbeSample> takeSample() override;
    };
    struct OutputPort final : CorrectionOutput {
        double pendingOffsetMm = 0.0;
        core::DeviceHealth health() const override { return {DeviceState::Ready, {}}; }
        OutputResult sendPartCorrection(const PartCorrection& correction) override;
        OutputResult sendDynamicOffset(double xOffsetMm) override;
    };

    void step(double dtS, double offsetStartMm, double offsetRateMmPerS, double cycleStartS);
    double radialForce(double zMm, double slideMm) const;
    void sampleProbe();

    BoringScenario m_scenario;
    bool m_dither;
    DitherProfile m_ditherProfile;
    CrossFeedDrive m_drive;
    InductiveProbe m_probe;
    double m_stiffnessX;
    double m_stiffnessY;
    double m_axialSpeedMmPerS;
    double m_appliedOffsetMm = 0.0;
    double m_nextProbeS = 0.0;
    BoringState m_state;
    SurfaceObserver m_observer;
    DrivePort m_drivePort;
    ProbePort m_probePort;
    OutputPort m_outputPort;
};

}  // namespace tt::core
