#include "core/sim/shaft/lathe_micrometer.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sim/shaft/lathe_random.h"

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

LatheMicrometerModel::LatheMicrometerModel(std::vector<double> sigmaPerPointMm, double resolutionMm, std::uint64_t seed)
    : m_sigma(0.0), m_pointSigma(std::move(sigmaPerPointMm)), m_resolution(resolutionMm), m_seed(seed) {
    for (double s : m_pointSigma)
        if (!std::isfinite(s) || s < 0.0)
            throw std::invalid_argument("a gauge noise sigma must be zero or a positive number of millimetres");
    if (!std::isfinite(resolutionMm) || resolutionMm < 0.0)
        throw std::invalid_argument("the gauge resolution must be zero or a positive number of millimetres");
}

double LatheMicrometerModel::sigmaMm(int pointIndex) const {
    if (m_pointSigma.empty()) return m_sigma;
    return m_pointSigma.at(static_cast<std::size_t>(pointIndex));
}

double LatheMicrometerModel::readMm(double trueDiameterMm, std::int64_t partNumber, int pointIndex, int attempt) const {
    NormalStream normals =
        latheNormals(m_seed, LatheStream::Micrometer, static_cast<std::uint64_t>(partNumber),
                     (static_cast<std::uint64_t>(pointIndex) << 16) ^ static_cast<std::uint64_t>(attempt));
    const double value = trueDiameterMm + sigmaMm(pointIndex) * normals.next();
    if (m_resolution <= 0.0) return value;
    return std::round(value / m_resolution) * m_resolution;
}

}  // namespace tt::core
