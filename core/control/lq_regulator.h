#pragma once

#include <Eigen/Core>

namespace tt::core {

/// A steady-state LQ regulator `u = -K x` and its Riccati solution.
struct LqRegulator {
    Eigen::MatrixXd K;              ///< gain, inputs x states
    Eigen::MatrixXd S;              ///< Riccati solution
    int iterations = 0;             ///< doubling steps of the Riccati solver
    double relativeResidual = 0.0;  ///< relative DARE residual
};

/// Discrete LQ regulator as MATLAB `dlqr`: minimises sum x'Qx + u'Ru + 2x'Nu for x+ = Ax + Bu.
/// Throws std::invalid_argument (a DareError) with "LQ regulator: ..." when no stabilising gain exists.
LqRegulator dlqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                 const Eigen::MatrixXd& N = Eigen::MatrixXd());

/// Output LQ regulator as MATLAB `lqry` for a discrete plant (A, B, C, D): minimises
/// sum y'R1y + u'R2u with y = Cx + Du, i.e. dlqr with Q = C'R1C, R = R2 + D'R1D, N = C'R1D
/// (paper 000, criterion (3)).
LqRegulator lqry(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                 const Eigen::MatrixXd& R1, const Eigen::MatrixXd& R2);

}  // namespace tt::core
