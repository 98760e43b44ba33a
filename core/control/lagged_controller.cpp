#include "core/control/lagged_controller.h"

#include <stdexcept>
#include <string>

#include "core/control/run_to_run_plant.h"

namespace tt::core {

LaggedController::LaggedController(std::unique_ptr<RunToRunController> inner, int lagParts,
                                   Eigen::MatrixXd innovationCorrelation)
    : m_inner(std::move(inner)), m_lag(lagParts), m_correlation(std::move(innovationCorrelation)) {
    if (!m_inner) throw std::invalid_argument("the lagged controller needs a controller");
    if (m_lag < 0 || m_lag > kMaxDelay)
        throw std::invalid_argument("the actuation lag must be 0 .. " + std::to_string(kMaxDelay) + " parts, got " +
                                    std::to_string(m_lag));
    const auto m = static_cast<Eigen::Index>(m_inner->pointCount());
    if (m_correlation.size() != 0 && (m_correlation.rows() != m || m_correlation.cols() != m))
        throw std::invalid_argument("the innovation correlation must be " + std::to_string(m) + " x " +
                                    std::to_string(m));
}

MeasurementVerdict LaggedController::addMeasurement(const PartMeasurement& measurement) {
    return m_inner->addMeasurement(measurement);
}

Eigen::VectorXd LaggedController::nextCorrection(std::int64_t partNumber) {
    return m_inner->nextCorrection(partNumber + m_lag);
}

void LaggedController::correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) {
    m_inner->correctionApplied(partNumber + m_lag, appliedMm);
}

std::optional<Innovation> LaggedController::lastInnovation() const {
    std::optional<Innovation> innovation = m_inner->lastInnovation();
    if (!innovation) return innovation;
    innovation->correlation = m_correlation;
    innovation->lagParts = m_lag;
    return innovation;
}

}  // namespace tt::core
