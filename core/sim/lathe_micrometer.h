#pragma once

#include <cstdint>

#include "core/sim/lathe_setup.h"

namespace tt::core {

/// The hand micrometer of the measuring station: Gaussian error with σ = error95 / 1.96, then rounded
/// to the display step (paper 000: 0.001 mm resolution, 0.001 mm at 95 %, variance 0.25e-6 mm²).
/// The noise of a reading is drawn from its own stream (part, point, attempt), so it is reproducible.
class LatheMicrometerModel {
public:
    /// Throws std::invalid_argument on a negative or non-finite resolution or error.
    LatheMicrometerModel(const LatheMicrometer& spec, std::uint64_t seed);

    /// The displayed reading of a true diameter, mm.
    double readMm(double trueDiameterMm, std::int64_t partNumber, int pointIndex, int attempt = 0) const;
    /// σ of the reading before rounding, mm.
    double sigmaMm() const { return m_sigma; }
    double resolutionMm() const { return m_resolution; }

private:
    double m_sigma;
    double m_resolution;
    std::uint64_t m_seed;
};

}  // namespace tt::core
