#include "core/sim/lathe_micrometer.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sim/lathe_random.h"

namespace tt::core {

LatheMicrometerModel::LatheMicrometerModel(const LatheMicrometer& spec, std::uint64_t seed)
    : m_sigma(spec.error95Mm / 1.96), m_resolution(spec.resolutionMm), m_seed(seed) {
    if (!std::isfinite(spec.error95Mm) || spec.error95Mm < 0.0)
        throw std::invalid_argument("the micrometer error must be zero or a positive number of millimetres (got " +
                                    std::to_string(spec.error95Mm) + ")");
    if (!std::isfinite(spec.resolutionMm) || spec.resolutionMm < 0.0)
        throw std::invalid_argument("the micrometer resolution must be zero or a positive number of millimetres (got " +
                                    std::to_string(spec.resolutionMm) + ")");
}

double LatheMicrometerModel::readMm(double trueDiameterMm, std::int64_t partNumber, int pointIndex, int attempt) const {
    auto g = latheGenerator(m_seed, LatheStream::Micrometer, static_cast<std::uint64_t>(partNumber),
                            (static_cast<std::uint64_t>(pointIndex) << 16) ^ static_cast<std::uint64_t>(attempt));
    const double value = trueDiameterMm + m_sigma * standardNormal(g);
    if (m_resolution <= 0.0) return value;
    return std::round(value / m_resolution) * m_resolution;
}

}  // namespace tt::core
