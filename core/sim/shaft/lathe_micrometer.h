#pragma once

#include <cstdint>
#include <vector>

#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// The hand micrometer of the measuring station: Gaussian error with σ = error95 / 1.96, then rounded
/// to the display step (paper 000: 0.001 mm resolution, 0.001 mm at 95 %, variance 0.25e-6 mm²).
/// The noise of a reading is drawn from its own stream (part, point, attempt), so it is reproducible.
class LatheMicrometerModel {
public:
    /// Throws std::invalid_argument on a negative or non-finite resolution or error.
    LatheMicrometerModel(const LatheMicrometer& spec, std::uint64_t seed);
    /// A gauge with its own noise σ per control point (the statistical plant's gauge noise variances,
    /// σ_i = sqrt(V_ii)), rounded to `resolutionMm` (0 = no rounding).
    LatheMicrometerModel(std::vector<double> sigmaPerPointMm, double resolutionMm, std::uint64_t seed);

    /// The displayed reading of a true diameter, mm.
    double readMm(double trueDiameterMm, std::int64_t partNumber, int pointIndex, int attempt = 0) const;
    /// σ of a reading at point `pointIndex` before rounding, mm.
    double sigmaMm(int pointIndex = 0) const;
    /// The reading is rounded to this, mm (0: not rounded).
    double resolutionMm() const { return m_resolution; }

private:
    double m_sigma;
    std::vector<double> m_pointSigma;
    double m_resolution;
    std::uint64_t m_seed;
};

}  // namespace tt::core
