#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/control/correction_limits.h"
#include "core/control/lqg_design.h"
#include "core/control/run_to_run_controller.h"

namespace tt::core {

/// Options of the LQG run-to-run controller.
struct LqgControllerOptions {
    double gateSigma = 5.0;  ///< innovation gate: a value more than this many sigma off is rejected
    int historyParts = 64;   ///< how far back a late measurement can still be placed (parts)

    /// Throws std::invalid_argument unless gateSigma > 0 and historyParts is 1 .. 4096.
    void validate() const;
};

/// The paper's multichannel LQG regulator (paper 000, "Рег1") as a run-to-run controller: a steady-state
/// Kalman filter in current form over the part index plus the LQ output feedback u = -K x(k|k).
///
/// Timing: the correction for part p is computed from the measurements of parts up to p - z (delay z).
/// nextCorrection(p) filters step k = p - z with whatever measurement of part k has arrived (a missing
/// point -> time update only for it), computes u(k) = -K x(k|k), applies the limits and propagates the
/// estimate with the correction really applied (clamped), so the estimator never winds up.
/// A measurement that arrives late (its step already filtered) is placed at its part index and the
/// steps since are filtered again from the stored history; one that arrives early waits for its step.
///
/// Gating: every value is compared with its predicted innovation sigma. The controller tracks the
/// actual error covariance of its estimate (steady-state gain, Joseph form) while it differs from the
/// steady state - at start-up and after missing measurements - so the gate widens when the estimate is
/// uncertain and a gap in the measurements cannot lock the filter out. In steady state the tracking
/// costs nothing.
class LqgController final : public RunToRunController {
public:
    /// Throws std::invalid_argument for a design that does not match the plant, a plant with a
    /// feed-through D, or invalid limits/options.
    LqgController(const RunToRunPlant& plant, const LqgDesign& design, const CorrectionLimits& limits,
                  const LqgControllerOptions& options = {});

    std::string name() const override { return "lqg"; }
    int pointCount() const override { return m_points; }
    MeasurementVerdict addMeasurement(const PartMeasurement& measurement) override;
    Eigen::VectorXd nextCorrection(std::int64_t partNumber) override;
    /// Replaces u(k) of the last step in the estimate (the delay chain holds known inputs, so the change is
    /// exact: x(k+1|k) moves by B du) and in the stored history.
    void correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) override;
    ControllerState saveState() const override;
    void restoreState(const ControllerState& state) override;
    std::optional<Innovation> lastInnovation() const override { return m_lastInnovation; }

    /// Which points the limits clipped in the last nextCorrection().
    const Eigen::Array<bool, Eigen::Dynamic, 1>& lastLimited() const { return m_lastLimited; }
    /// The last applied corrections, mm (zeros before the first part).
    const Eigen::VectorXd& lastCorrectionMm() const { return m_lastApplied; }
    /// Predicted diameter deviation of the next part to be filtered, mm.
    Eigen::VectorXd predictedDeviationMm() const;
    /// Predicted deviation of the next part to be filtered as it would be without any correction (the
    /// estimated disturbance C_d x_d), mm.
    Eigen::VectorXd predictedUncorrectedDeviationMm() const;
    /// Predicted innovation sigma of the next part to be filtered, per point, mm.
    Eigen::VectorXd predictedSigmaMm() const;

private:
    // A block of the design and where it sits in the state vector and the covariance storage.
    struct Block : LqgBlock {
        Eigen::Index offset = 0;  // into the state vector
        Eigen::Index size = 0;
        std::size_t covOffset = 0;       // into the flat covariance storage
        Eigen::MatrixXd steadyVariance;  // row lead 0 .. z-1: diag(C P_lead C' + V) from the steady state
    };
    /// Estimate and its error covariance at one step (a priori).
    struct Estimate {
        Eigen::VectorXd x;
        std::vector<double> cov;           // per block, size x size, column-major
        std::vector<std::uint8_t> steady;  // per block: cov equals the steady state
    };

    void measurementUpdate(Estimate& e, const double* values, const std::uint8_t* has) const;
    void timeUpdate(Estimate& e, const double* applied);
    Eigen::VectorXd innovationVariance(const Estimate& e, int lead) const;
    Eigen::VectorXd predictOutputs(const Eigen::VectorXd& x, int lead) const;
    void refilterFrom(std::int64_t step);
    std::size_t historySlot(std::int64_t step) const;
    std::size_t pendingSlot(std::int64_t step) const;
    void storeHistory(std::size_t slot, const Estimate& e);
    void loadHistory(std::size_t slot, Estimate& e) const;
    std::uint16_t fingerprint() const;

    int m_points = 0;
    int m_delay = 1;
    Eigen::Index m_states = 0;
    std::size_t m_covSize = 0;
    std::vector<Block> m_blocks;
    CorrectionLimits m_limits;
    LqgControllerOptions m_options;

    bool m_started = false;
    std::int64_t m_firstPart = 0;
    std::int64_t m_lastPart = 0;
    std::int64_t m_nextStep = 0;  // next filter step (= part whose measurement it uses)
    Estimate m_prior;             // estimate of step m_nextStep before its measurement
    Eigen::VectorXd m_scratch;
    Eigen::VectorXd m_lastApplied;
    Eigen::Array<bool, Eigen::Dynamic, 1> m_lastLimited;
    std::optional<Innovation> m_lastInnovation;  // of the last measurement offered at lead 0

    // Pending (not yet filtered) measurements of steps nextStep .. nextStep + z - 1: z slots of m values
    // with a presence mask. History of filtered steps: estimates, measurements and applied corrections.
    std::vector<std::int64_t> m_pendingStep;
    std::vector<double> m_pendingValue;
    std::vector<std::uint8_t> m_pendingHas;
    std::vector<std::int64_t> m_historyStep;
    std::vector<double> m_historyX;
    std::vector<double> m_historyCov;
    std::vector<std::uint8_t> m_historySteady;
    std::vector<double> m_historyValue;
    std::vector<std::uint8_t> m_historyHas;
    std::vector<double> m_historyApplied;
};

}  // namespace tt::core
