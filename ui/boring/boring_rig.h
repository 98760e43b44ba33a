#pragma once

#include <optional>

#include "core/control/deflection_compensator.h"
#include "core/control/dither_force_estimator.h"
#include "core/control/in_process_compensation.h"
#include "core/ports/correction_output.h"

namespace tt::ui {

/// Where the deflection comes from (paper 001): way 1, the cross-feed current with dither; way 2,
/// the probe mandrel in the boring bar.
enum class BoringSource { Current, Probe };

/// What the operator chose for one in-process compensation run.
struct BoringRunSettings {
    BoringSource source = BoringSource::Current;
    int plane = 0;                          ///< probe: the mandrel's plane that lies along X (0 or 1)
    double stiffnessNPerMm = 0.0;           ///< k_st of the tool (tool table), N/mm
    double currentToForceNPerA = 0.0;       ///< k_p of the cross feed (tool table), N/A
    core::CompensatorLimits limits;         ///< range and rate of the dynamic X offset
    double plcCycleS = 0.02;                ///< the PLC cycle the compensation runs at, 0.01 .. 0.1 s
    core::DitherEstimatorConfig estimator;  ///< thresholds; k_p and k_st are taken from above
};

/// What the built-in simulated station knows and a machine does not: the truth, for the plots.
struct StationTruth {
    double zMm = 0.0;                   ///< tool position along the bore (0 = entry face), mm
    bool cutting = false;               ///< the tool is in the bore
    double deflectionMm = 0.0;          ///< the bar's real tip deflection along X, mm
    double forceN = 0.0;                ///< the real radial cutting force, N
    double diameterErrorMm = 0.0;       ///< bore diameter minus nominal where the tool cuts, mm
    double uncompensatedErrorMm = 0.0;  ///< the same on the same pass without compensation, mm
};

/// One PLC cycle as the panel shows it.
struct BoringCycleView {
    core::CompensationCycle cycle;
    std::optional<StationTruth> truth;  ///< simulated station only
};

/// The machine the panel's compensation runs on, one PLC cycle at a time (in the GUI thread, where
/// the devices live): the built-in simulated boring station or the configured devices.
class BoringRig {
public:
    virtual ~BoringRig() = default;
    /// Runs one PLC cycle: the simulator first moves its machine on by one cycle; then the
    /// compensator reads the source, limits the offset and writes it to the CNC.
    virtual BoringCycleView cycle() = 0;
    /// The PLC cycle, s.
    virtual double plcCycleS() const = 0;
    /// The simulated bore is finished (a machine never finishes by itself).
    virtual bool finished() const { return false; }
    /// What the part program cuts now (the force from current is refused on tapers and contours).
    virtual void setSegment(core::SegmentKind kind) = 0;
    /// The offset the CNC holds, mm.
    virtual double offsetMm() const = 0;
    /// Writes an offset of 0 to the CNC (tool out of the bore); the CNC's answer.
    virtual core::OutputResult zeroOffset() = 0;
};

}  // namespace tt::ui
