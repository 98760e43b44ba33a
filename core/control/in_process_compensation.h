#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/calibration/probe_linearisation.h"
#include "core/control/deflection_compensator.h"
#include "core/control/dither_force_estimator.h"
#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"

namespace tt::core {

/// Where the in-process compensation takes the deflection from (paper 001): none, way 1 (the
/// cross-feed current with dither) or way 2 (the probe mandrel in the boring bar).
enum class BoringMethod { None, Current, Probe };

/// "none", "current", "probe".
const char* toString(BoringMethod method);
/// Parses "none" / "current" / "probe"; throws std::invalid_argument otherwise.
BoringMethod boringMethodFromString(const std::string& text);

/// Why a source has no valid deflection, so a user interface can say it in its own words.
enum class ReadingProblem {
    None,
    SourceNotReady,     ///< the device is disconnected, connecting or in error (e.g. silent)
    NoRecentSample,     ///< the probe sent nothing usable for longer than allowed
    NoTable,            ///< the probe sends raw ADC codes and no linearisation table is loaded
    NotCylindrical,     ///< current with dither: taper, contour or a feed motion
    SlideNotMoving,     ///< current with dither: the slide did not really move
    WindowTooShort,     ///< current with dither: too few samples at constant velocity
    WaitingForStrokes,  ///< current with dither: no forward and reverse stroke yet
};

/// Stable English name of a problem, for logs and the command line ("window too short").
const char* toString(ReadingProblem problem);

/// What a deflection source says for one PLC cycle. No sentence: the problem is a kind with its
/// data, worded by the user interface.
struct DeflectionReading {
    std::optional<double> deflectionMm;             ///< tool tip deflection along X, mm (negative: towards the axis)
    std::optional<double> forceN;                   ///< radial force pushing the tool towards the axis, N, when known
    bool fresh = false;                             ///< a new measurement arrived this cycle
    ReadingProblem problem = ReadingProblem::None;  ///< why there is no valid deflection; None when valid
    DeviceHealth sourceHealth;                      ///< SourceNotReady: the device's state and its own message
    double silenceLimitS = 0.0;                     ///< NoRecentSample: the silence allowed, s
};

/// Where the compensator gets the deflection from (paper 001: way 1 current, way 2 probe).
class DeflectionSource {
public:
    virtual ~DeflectionSource() = default;
    /// "current" or "probe".
    virtual std::string name() const = 0;
    /// Takes everything that arrived since the last poll (never blocks); `nowS` = Clock time.
    virtual DeflectionReading poll(double nowS) = 0;
    /// Told after each cycle how fast the offset just sent will move the slide during the next
    /// cycle (the CNC spreads it over the cycle), mm/s.
    virtual void offsetMoving(double /*offsetVelocityMmPerS*/) {}
};

/// Way 1: force from the cross-feed motor current with dither, deflection −P / k_st.
class CurrentDeflectionSource final : public DeflectionSource {
public:
    CurrentDeflectionSource(DriveCurrentReadout& readout, const DitherEstimatorConfig& config);
    std::string name() const override { return "current"; }
    DeflectionReading poll(double nowS) override;
    void offsetMoving(double offsetVelocityMmPerS) override { m_nextOffsetVelocity = offsetVelocityMmPerS; }
    DitherForceEstimator& estimator() { return m_estimator; }

private:
    DriveCurrentReadout& m_readout;
    DitherForceEstimator m_estimator;
    double m_nextOffsetVelocity = 0.0;  ///< offset speed during the cycle whose samples come next
};

/// Way 2: the probe mandrel's deflection in one bending plane, linearised by the mandrel's
/// own table or, for raw codes, by a host-side table. The samples of a cycle are averaged; a
/// reading older than `maxSilenceS` is not used.
class ProbeDeflectionSource final : public DeflectionSource {
public:
    /// `plane` 0 = X (radial), 1 = Y; `stiffnessNPerMm` > 0 also reports the force k·|δ|.
    ProbeDeflectionSource(DeflectionProbe& probe, int plane, std::optional<LinearisationTable> hostTable,
                          double stiffnessNPerMm = 0.0, double maxSilenceS = 0.5);
    std::string name() const override { return "probe"; }
    DeflectionReading poll(double nowS) override;

private:
    DeflectionProbe& m_probe;
    int m_plane;
    std::optional<LinearisationTable> m_hostTable;
    double m_stiffnessNPerMm;
    double m_maxSilenceS;
    std::optional<double> m_lastDeflectionMm;
    double m_lastSampleS = 0.0;
};

/// Why the offset did not reach the CNC in a cycle.
enum class OutputProblem {
    None,
    NotReady,  ///< the output is disconnected, connecting or in error: nothing was sent
    Refused,   ///< the output refused the write: the CNC keeps what it had
};

/// Stable English name of an output problem, for logs and the command line ("refused").
const char* toString(OutputProblem problem);

/// One PLC cycle of the in-process compensation, for logs and plots.
struct CompensationCycle {
    double timeS = 0.0;
    DeflectionReading reading;
    CompensationStep step;
    bool sent = false;                                  ///< the offset was written to the CNC
    OutputProblem outputProblem = OutputProblem::None;  ///< why not, when it was not for want of a reading
    DeviceHealth outputHealth;                          ///< NotReady: the output's state and its own message
    std::string outputMessage;                          ///< Refused: the output's own words (the device's text)
};

/// The in-process compensation loop (issue item 6): every PLC cycle it polls the source, limits
/// the offset (DeflectionCompensator) and writes it with CorrectionOutput::sendDynamicOffset.
/// A silent source or a failed write holds the last offset the CNC really has.
class InProcessCompensator {
public:
    /// `plcCycleS` must be within 0.01 .. 0.1 s (paper 001: the PLC period, 10..100 ms).
    InProcessCompensator(DeflectionSource& source, CorrectionOutput& output, const CompensatorLimits& limits,
                         double plcCycleS);
    /// Runs one cycle at Clock time `nowS`.
    CompensationCycle cycle(double nowS);
    /// Starts from the offset the CNC already holds (clamped to the range), mm, instead of 0, so
    /// a new run does not move the tool by the old offset at once. Call before the first cycle.
    void resumeFrom(double offsetMm);
    double offsetMm() const { return m_compensator.offsetMm(); }
    double plcCycleS() const { return m_cycleS; }
    const CompensatorLimits& limits() const { return m_compensator.limits(); }

private:
    DeflectionSource& m_source;
    CorrectionOutput& m_output;
    DeflectionCompensator m_compensator;
    double m_cycleS;
    double m_lastSentMm = 0.0;
};

}  // namespace tt::core
