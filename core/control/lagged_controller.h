#pragma once

#include <memory>

#include <Eigen/Core>

#include "core/control/run_to_run_controller.h"

namespace tt::core {

/// A run-to-run controller for a plant whose corrections act `lagParts` parts after they are sent (a plant
/// delay z + lag with the loop's measurement delay z), and whose points' innovations are correlated. The inner
/// controller is designed for the delay z + lag and numbers parts by the part its correction acts on: the
/// correction sent for part p is the inner controller's for part p + lag, so it is computed from the
/// measurements up to part p - z, which the loop has. Measurements pass unchanged. The innovations carry the
/// lag and the correlation for the loop's mismatch monitor.
class LaggedController final : public RunToRunController {
public:
    /// Throws std::invalid_argument for a null controller, a lag outside 0 .. 8 or a correlation matrix that
    /// is neither empty nor points x points.
    LaggedController(std::unique_ptr<RunToRunController> inner, int lagParts, Eigen::MatrixXd innovationCorrelation);

    std::string name() const override { return m_inner->name(); }
    int pointCount() const override { return m_inner->pointCount(); }
    MeasurementVerdict addMeasurement(const PartMeasurement& measurement) override;
    Eigen::VectorXd nextCorrection(std::int64_t partNumber) override;
    void correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) override;
    ControllerState saveState() const override { return m_inner->saveState(); }
    void restoreState(const ControllerState& state) override { m_inner->restoreState(state); }
    std::optional<Innovation> lastInnovation() const override;

    /// The actuation lag, parts.
    int lagParts() const { return m_lag; }
    /// The controller designed for delay z + lag.
    const RunToRunController& inner() const { return *m_inner; }

private:
    std::unique_ptr<RunToRunController> m_inner;
    int m_lag = 0;
    Eigen::MatrixXd m_correlation;
};

}  // namespace tt::core
