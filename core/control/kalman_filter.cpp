#include "core/control/kalman_filter.h"

#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

#include "core/linalg/dare.h"

namespace tt::core {

KalmanDesign designKalman(const Eigen::MatrixXd& A, const Eigen::MatrixXd& C, const Eigen::MatrixXd& G,
                          const Eigen::MatrixXd& W, const Eigen::MatrixXd& V) {
    if (C.cols() != A.rows() || G.rows() != A.rows() || W.rows() != G.cols() || W.cols() != G.cols() ||
        V.rows() != C.rows() || V.cols() != C.rows())
        throw std::invalid_argument("Kalman filter: inconsistent sizes of A, C, G, W, V");
    Eigen::MatrixXd Qn = G * W * G.transpose();
    Qn = 0.5 * (Qn + Qn.transpose()).eval();
    DareSolution s;
    try {
        s = solveDare(A.transpose(), C.transpose(), Qn, V);
    } catch (const DareError& e) {
        switch (e.reason()) {
            case DareError::Reason::NotStabilisable:
                throw DareError(e.reason(), e.mode(),
                                "Kalman filter: not detectable: the mode at " + formatMode(e.mode()) +
                                    " (|lambda| >= 1) is not seen by any measurement");
            case DareError::Reason::UnobservedOnCircle:
                throw DareError(e.reason(), e.mode(),
                                "Kalman filter: the mode at " + formatMode(e.mode()) +
                                    " on the unit circle is not driven by any noise (zero disturbance variance?)");
            case DareError::Reason::NoConvergence:
                throw DareError(e.reason(), e.mode(), std::string("Kalman filter: ") + e.what());
        }
        throw;
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("Kalman filter: ") + e.what());
    }
    KalmanDesign k;
    k.P = s.P;
    const Eigen::MatrixXd innovationCov = C * s.P * C.transpose() + V;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(innovationCov);
    k.L = ldlt.solve(C * s.P).transpose();
    k.Z = s.P - k.L * C * s.P;
    k.Z = 0.5 * (k.Z + k.Z.transpose()).eval();
    k.predictorGain = A * k.L;
    k.iterations = s.iterations;
    k.relativeResidual = s.relativeResidual;
    return k;
}

}  // namespace tt::core
