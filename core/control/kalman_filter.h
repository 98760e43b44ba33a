#pragma once

#include <Eigen/Core>

namespace tt::core {

/// A steady-state Kalman filter in current-estimator form (MATLAB `kalman`, discrete):
///   measurement update  x(k|k)   = x(k|k-1) + L (y(k) - C x(k|k-1) - D u(k))
///   time update         x(k+1|k) = A x(k|k) + B u(k)
/// for x+ = Ax + Bu + Gw, y = Cx + Du + v, cov(w) = W, cov(v) = V, w and v independent.
struct KalmanDesign {
    Eigen::MatrixXd L;              ///< innovation gain P C'(C P C' + V)^-1 (MATLAB's M), states x outputs
    Eigen::MatrixXd P;              ///< a-priori steady-state error covariance E[(x - x(k|k-1))(...)']
    Eigen::MatrixXd Z;              ///< a-posteriori error covariance E[(x - x(k|k))(...)'] = (I - L C) P
    Eigen::MatrixXd predictorGain;  ///< A L: the one-step predictor gain (MATLAB's L)
    int iterations = 0;             ///< doubling steps of the Riccati solver
    double relativeResidual = 0.0;  ///< relative DARE residual
};

/// Designs the steady-state filter from the filter Riccati equation
/// P = A P A' - A P C'(C P C' + V)^-1 C P A' + G W G'. Throws std::invalid_argument (a DareError) with
/// "Kalman filter: ..." when the disturbance is not detectable from the measurements or V is not
/// positive definite.
KalmanDesign designKalman(const Eigen::MatrixXd& A, const Eigen::MatrixXd& C, const Eigen::MatrixXd& G,
                          const Eigen::MatrixXd& W, const Eigen::MatrixXd& V);

}  // namespace tt::core
