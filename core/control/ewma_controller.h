#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/control/correction_limits.h"
#include "core/control/run_to_run_controller.h"

namespace tt::core {

/// Options of the EWMA / mean-value controller, the industry baseline: what the measuring cycles of
/// CNC controls do (mean value over parts with weighting factor k = 1 / weight, a zone without
/// correction, a warning zone and an alarm zone).
struct EwmaOptions {
    double weight = 0.3;      ///< lambda in (0, 1]: offset(k) = lambda (m - k_i u) + (1 - lambda) offset(k-1)
    double deadBandMm = 0.0;  ///< no new correction while |predicted deviation| < this (diameter, mm)
    double warningMm = std::numeric_limits<double>::infinity();  ///< |measured deviation| >= this: warning
    double alarmMm = std::numeric_limits<double>::infinity();    ///< >= this: alarm, value not used
    int historyParts = 64;  ///< applied corrections kept to pair late measurements with their part
    /// lambda2 in [0, 1): 0 = EWMA; > 0 = double EWMA (Butler & Stefani 1994), which also tracks
    /// p(k) = lambda2 (m - k_i u - offset(k-1)) + (1 - lambda2) p(k-1) (D / lambda1 on a ramp of D per part)
    /// and corrects for offset + (1 + (driftHorizonParts - 1) lambda1) p: the next part, then the drift
    /// lambda1 p per further part of the transport delay.
    double driftWeight = 0.0;
    int driftHorizonParts = 1;  ///< parts the drift is extrapolated over (the delay z), 1 .. 8

    /// Throws std::invalid_argument for a weight outside (0, 1], negative bands, warning > alarm.
    void validate() const;
};

/// Where a point's last measured deviation fell.
enum class ToleranceBand { Ok, Warning, Alarm };

/// EWMA run-to-run controller per control point: estimates the offset the part would have without
/// correction, d(k) = m(k) - k_i u(k), from each measurement paired with the correction that part
/// really received (clamped), and commands u = -offset / k_i. Because the pairing uses the applied
/// correction, limits cause no wind-up.
class EwmaController final : public RunToRunController {
public:
    /// `gain`: k_i per point. Throws std::invalid_argument for invalid options or limits.
    EwmaController(const Eigen::VectorXd& gain, const CorrectionLimits& limits, const EwmaOptions& options);

    std::string name() const override { return m_options.driftWeight > 0.0 ? "dewma" : "ewma"; }
    int pointCount() const override { return static_cast<int>(m_gain.size()); }
    MeasurementVerdict addMeasurement(const PartMeasurement& measurement) override;
    Eigen::VectorXd nextCorrection(std::int64_t partNumber) override;
    /// The part's measurement is then paired with `appliedMm`, and the next step limit starts from it.
    void correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) override;
    ControllerState saveState() const override;
    void restoreState(const ControllerState& state) override;

    /// Band of each point's last accepted or alarmed measurement.
    const std::vector<ToleranceBand>& bands() const { return m_bands; }
    /// Estimated uncorrected deviation per point, mm of diameter.
    const Eigen::VectorXd& offsetMm() const { return m_offset; }
    /// Estimated drift per part and point (double EWMA; zero for EWMA), mm of diameter.
    const Eigen::VectorXd& driftMm() const { return m_drift; }
    /// The options the controller was made with.
    const EwmaOptions& options() const { return m_options; }

private:
    std::size_t slot(std::int64_t part) const;
    std::uint16_t fingerprint() const;

    Eigen::VectorXd m_gain;
    CorrectionLimits m_limits;
    EwmaOptions m_options;
    bool m_started = false;
    std::int64_t m_firstPart = 0;
    std::int64_t m_lastPart = 0;
    Eigen::VectorXd m_offset;
    Eigen::VectorXd m_drift;
    Eigen::VectorXd m_lastApplied;
    std::vector<ToleranceBand> m_bands;
    std::vector<std::int64_t> m_historyPart;      // ring: part number per slot (-1: empty)
    std::vector<double> m_historyApplied;         // ring: applied correction per slot and point
    std::vector<std::uint8_t> m_historyMeasured;  // ring: point already measured
};

/// Open loop: never corrects (the reference of k_eff). Accepts finite measurements and ignores them.
class OpenLoopController final : public RunToRunController {
public:
    /// Open loop over `pointCount` >= 1 control points; throws std::invalid_argument otherwise.
    explicit OpenLoopController(int pointCount);

    std::string name() const override { return "open"; }
    int pointCount() const override { return m_points; }
    MeasurementVerdict addMeasurement(const PartMeasurement& measurement) override;
    Eigen::VectorXd nextCorrection(std::int64_t partNumber) override;
    ControllerState saveState() const override;
    void restoreState(const ControllerState& state) override;

private:
    int m_points = 0;
    bool m_started = false;
    std::int64_t m_lastPart = 0;
};

}  // namespace tt::core
