#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/sim/shaft/lathe_disturbance.h"
#include "core/sim/shaft/lathe_part_process.h"

namespace tt::core {

/// The controller's own design model as a machine (paper 000, eq. (2)): at control point i the diameter
/// error of part k is k_i u_i(k) + f_i(k), with u the radial corrections the CNC received and f the
/// disturbance model's output; the gauge adds the measurement noise. Only the control points exist:
/// the part's profile is given there and drawn straight between them.
class LatheStatisticalProcess final : public LathePartProcess {
public:
    /// Throws std::invalid_argument on mismatched sizes, non-increasing points or non-positive sizes.
    LatheStatisticalProcess(std::vector<double> pointZMm, Eigen::VectorXd gains, LatheDisturbanceModel disturbance,
                            double nominalDiameterMm, double partLengthMm, std::uint64_t seed);

    /// Uses correction.pointCorrectionMm (one per point; none = no correction); the path is ignored.
    TurnedPart machine(const PartCorrection& correction) override;
    double nominalDiameterMm() const override { return m_nominal; }
    double partLengthMm() const override { return m_length; }

private:
    std::vector<double> m_pointZ;
    Eigen::VectorXd m_gains;
    LatheDisturbance m_disturbance;
    double m_nominal;
    double m_length;
};

}  // namespace tt::core
