#pragma once

#include <optional>
#include <vector>

#include "core/control/in_process_compensation.h"
#include "core/sim/boring/simulated_boring_pass.h"

namespace tt::core {

/// One PLC cycle of a boring run, for plots.
struct BoringTracePoint {
    double timeS = 0.0;
    double zMm = 0.0;
    double diameterErrorMm = 0.0;  ///< bore diameter minus nominal where the tool is, mm
    double deflectionMm = 0.0;     ///< true tip deflection along X, mm
    double offsetMm = 0.0;         ///< dynamic offset applied, mm
    double forceN = 0.0;           ///< true radial force, N
    double estimatedForceN = 0.0;  ///< the source's force estimate, N (NaN when none)
};

/// Result of one simulated boring pass (issue 6, `trueturn boring`).
struct BoringResult {
    BoringMethod method = BoringMethod::None;
    double boreErrorMaxMm = 0.0;  ///< max |diameter error| over the gauged length, mm
    double boreErrorRmsMm = 0.0;  ///< RMS diameter error over the gauged length, mm
    double boreErrorMaxFullLengthMm = 0.0;
    double gaugedFromMm = 0.0;
    double gaugedToMm = 0.0;
    double deflectionMaxMm = 0.0;  ///< max |tip deflection| over the gauged length, mm
    double forceMeanN = 0.0;
    double forceMaxN = 0.0;
    std::optional<double> forceEstimateErrorPct;     ///< RMS of (estimate − true) / true over the gauged length
    std::optional<double> forceEstimateErrorMaxPct;  ///< largest |estimate − true| / true there
    int estimates = 0;                               ///< PLC cycles with a fresh measurement
    int holdingCycles = 0;                           ///< PLC cycles in the bore without a valid measurement
    ReadingProblem lastHoldProblem = ReadingProblem::None;  ///< why the last of them held
    double stiffnessUsedNPerMm = 0.0;                       ///< k_st from the tool table
    double trueStiffnessNPerMm = 0.0;
    std::optional<ProbeCalibrationSummary> calibration;
    std::vector<BoringTracePoint> trace;  ///< one point per PLC cycle in the bore
};

/// Runs one boring pass of `scenario` with the given compensation: none; current (dither on,
/// DitherForceEstimator through CurrentDeflectionSource); probe (the mandrel is first calibrated
/// on the rig, linearised, its table image encoded, checked and loaded into the mandrel, then
/// ProbeDeflectionSource). The pass is a SimulatedBoringPass and the run comes from the one run
/// builder (buildBoringRun with the scenario's choices), one PLC cycle at a time in lock-step.
/// Deterministic for a scenario seed.
BoringResult runBoring(const BoringScenario& scenario, BoringMethod method);

}  // namespace tt::core
