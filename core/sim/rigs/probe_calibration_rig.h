#pragma once

#include <random>
#include <vector>

#include "core/calibration/probe_linearisation.h"
#include "core/sim/boring/boring_machine.h"
#include "core/sim/boring/inductive_probe.h"

namespace tt::core {

/// The calibration set-up of the probe mandrel on the simulator: a screw jack bends the bar at
/// the tool block to a chosen tip deflection in one plane; a dial indicator (resolution and
/// reading error) gives the reference; the mandrel's ADC is read several times and averaged.
class ProbeCalibrationRig {
public:
    /// Calibrates `plane` of `probe` (outlives the rig) against a reference of the given resolution and noise, µm.
    ProbeCalibrationRig(InductiveProbe& probe, int plane, double referenceResolutionUm, double referenceNoiseUm,
                        unsigned long long seed);

    /// Loads the bar to `tipDeflectionMm`, waits for the filter, reads `readings` codes.
    CalibrationPoint measure(double tipDeflectionMm, int readings);
    /// `config.points` loads evenly over ± spanFraction of the probe's full-scale deflection.
    std::vector<CalibrationPoint> sweep(const ProbeCalibrationConfig& config);
    /// The largest tip deflection the probe reads without saturating the bridge model's u = ±1, mm.
    double fullScaleTipDeflectionMm() const;

private:
    InductiveProbe& m_probe;
    int m_plane;
    double m_resolutionUm;
    double m_noiseUm;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    double m_timeS = 0.0;
};

}  // namespace tt::core
