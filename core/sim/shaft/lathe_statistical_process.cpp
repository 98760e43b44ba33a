#include "core/sim/shaft/lathe_statistical_process.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

LatheStatisticalProcess::LatheStatisticalProcess(std::vector<double> pointZMm, Eigen::VectorXd gains,
                                                 LatheDisturbanceModel disturbance, double nominalDiameterMm,
                                                 double partLengthMm, std::uint64_t seed)
    : m_pointZ(std::move(pointZMm)),
      m_gains(std::move(gains)),
      m_disturbance(std::move(disturbance), seed),
      m_nominal(nominalDiameterMm),
      m_length(partLengthMm) {
    if (!std::isfinite(m_nominal) || m_nominal <= 0.0)
        throw std::invalid_argument("the nominal diameter must be a positive number of millimetres");
    if (!std::isfinite(m_length) || m_length <= 0.0)
        throw std::invalid_argument("the part length must be a positive number of millimetres");
    const auto n = static_cast<Eigen::Index>(m_pointZ.size());
    if (n < 1 || m_gains.size() != n || m_disturbance.pointCount() != n)
        throw std::invalid_argument(
            "the statistical plant needs one gain and one disturbance channel per control point");
    if (!m_gains.allFinite()) throw std::invalid_argument("the plant gains are not finite");
    for (std::size_t i = 1; i < m_pointZ.size(); ++i)
        if (!(m_pointZ[i] > m_pointZ[i - 1]))
            throw std::invalid_argument("the control points must be strictly increasing along the part");
}

TurnedPart LatheStatisticalProcess::machine(const PartCorrection& correction) {
    const auto n = m_pointZ.size();
    if (!correction.pointCorrectionMm.empty() && correction.pointCorrectionMm.size() != n)
        throw std::invalid_argument("the correction has " + std::to_string(correction.pointCorrectionMm.size()) +
                                    " points, the plant " + std::to_string(n));
    const Eigen::VectorXd f = m_disturbance.diameterMm(correction.partNumber);
    TurnedPart part;
    part.partNumber = correction.partNumber;
    part.zMm = m_pointZ;
    part.diameterMm.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = correction.pointCorrectionMm.empty() ? 0.0 : correction.pointCorrectionMm[i];
        part.diameterMm[i] = m_nominal + m_gains(static_cast<Eigen::Index>(i)) * u + f(static_cast<Eigen::Index>(i));
    }
    return part;
}

}  // namespace tt::core
