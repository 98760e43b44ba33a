#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/sim/boring/boring_machine.h"

namespace tt::core {

/// Where the in-process compensation takes the deflection from (paper 001).
enum class BoringMethod { None, Current, Probe };

/// "none", "current", "probe".
const char* toString(BoringMethod method);
/// Parses "none" / "current" / "probe"; throws std::invalid_argument otherwise.
BoringMethod boringMethodFromString(const std::string& text);

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

/// The probe calibration done on the simulator before a probe run.
struct ProbeCalibrationSummary {
    int points = 0;
    int degree = 0;
    double rmsResidualUm = 0.0;
    double maxTableErrorUm = 0.0;
    std::uint32_t imageCrc = 0;  ///< CRC-32C the loaded table image carries (format 2)
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
    std::string lastHoldReason;
    double stiffnessUsedNPerMm = 0.0;  ///< k_st from the tool table
    double trueStiffnessNPerMm = 0.0;
    std::optional<ProbeCalibrationSummary> calibration;
    std::vector<BoringTracePoint> trace;  ///< one point per PLC cycle in the bore
};

/// Calibrates the probe mandrel of `machine` on the simulated stand (`scenario.calibration`: loads
/// on the bar tip against a dial indicator), linearises it, and loads the table into the mandrel
/// the way an upload does: the image is encoded, then decoded with its CRC checked on the
/// mandrel's side. Throws core::LinearisationRefused when the calibration cannot be fitted.
ProbeCalibrationSummary calibrateMandrel(BoringMachine& machine, const BoringScenario& scenario);

/// Runs one boring pass of `scenario` with the given compensation: none; current (dither on,
/// DitherForceEstimator through CurrentDeflectionSource); probe (the mandrel is first calibrated
/// on the rig, linearised, its table image encoded, checked and loaded into the mandrel, then
/// ProbeDeflectionSource). The compensation runs in InProcessCompensator every PLC cycle and
/// writes the offset through the machine's CorrectionOutput. Deterministic for a scenario seed.
BoringResult runBoring(const BoringScenario& scenario, BoringMethod method);

}  // namespace tt::core
