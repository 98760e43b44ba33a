#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "core/calibration/probe_linearisation.h"

namespace tt::core {

/// The probe mandrel's inductive sensor (paper 001, way 2, figs. 2–4): an inner tube fixed at
/// the clamped end carries four coils near the tool block; opposite pairs form a differential
/// bridge per bending plane, fed at 20..50 Hz; a differential amplifier, synchronous detector
/// and RC filter feed the microcontroller's ADC, whose reference is rectified from the bridge
/// supply (ratiometric). The static characteristic is a polynomial in the normalised gap change
/// u = gap / fullScaleGapMm: bridge ratio r(u) = Σ c_i u^i (degree 2..4; odd terms only for
/// a perfectly symmetric bridge), ADC code = (1 + r) / 2 · (2^bits − 1).
struct InductiveProbeConfig {
    int adcBits = 12;                                                 ///< 10..16
    double fullScaleGapMm = 0.5;                                      ///< gap change at u = ±1, mm
    std::vector<double> bridgeCoefficients = {0.0, 0.80, 0.0, 0.15};  ///< c_0 .. c_n, n = 2..4
    double noiseRms = 0.0005;       ///< amplifier noise as a fraction of the nominal half range
    double supplyVariation = 0.05;  ///< relative swing of the bridge supply (cancelled by the ratiometric ADC)
    double supplyVariationPeriodS = 7.0;
    double filterTimeConstantS = 0.005;   ///< RC filter after the synchronous detector, s
    double crossTalk = 0.01;              ///< share of the other plane's gap seen by a bridge
    double sensorPositionFraction = 0.9;  ///< where along the overhang the coils sit (0 clamp .. 1 tip)
    double sampleRateHz = 100.0;          ///< conversions per second
};

/// Gap change at the sensor for a tip deflection of a cantilever loaded at its tip:
/// w(sL) / w(L) = s² (3 − s) / 2 (Euler–Bernoulli; s = sensor position / overhang).
double sensorToTipRatio(double sensorPositionFraction);

/// Simulated sensor and microcontroller of one probe mandrel (two planes); deterministic for a seed.
class InductiveProbe {
public:
    /// Throws std::invalid_argument for bits outside 10..16, a degree outside 2..4, or
    /// non-positive scale, rate or time constant.
    InductiveProbe(const InductiveProbeConfig& config, unsigned long long seed);

    /// Bridge ratio r(u) of the static characteristic (no noise), clamped to [−1, 1].
    double bridgeRatio(double u) const;
    /// Static ADC code (real-valued, no noise, no filter) for a tip deflection along the plane, mm.
    double staticCode(double tipDeflectionMm) const;
    /// Advances the analog chain (RC filter) by dtS with the tip deflections of both planes, mm.
    void advance(double dtS, double tipDeflectionXmm, double tipDeflectionYmm);
    /// Settles the filter at the given deflections (calibration rig between loads).
    void settle(double tipDeflectionXmm, double tipDeflectionYmm);
    /// One ADC conversion of both planes at Clock time `timeS` (supply variation, noise).
    std::array<std::int32_t, 2> convert(double timeS);

    /// Loads or clears the microcontroller's table of one plane (what an upload does).
    void setTable(int plane, std::optional<LinearisationTable> table);
    /// The table of `plane` (0 or 1), if one is loaded.
    const std::optional<LinearisationTable>& table(int plane) const;
    /// The probe's parameters.
    const InductiveProbeConfig& config() const { return m_config; }
    /// The largest ADC code, 2^bits - 1.
    double fullScaleCode() const;

private:
    double normalisedGap(double tipDeflectionMm) const;

    InductiveProbeConfig m_config;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    std::array<double, 2> m_filtered{};  ///< filtered bridge ratio per plane
    std::array<std::optional<LinearisationTable>, 2> m_tables;
};

}  // namespace tt::core
