#include "core/control/lq_regulator.h"

#include <stdexcept>
#include <string>

#include "core/linalg/dare.h"

namespace tt::core {

LqRegulator dlqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
                 const Eigen::MatrixXd& N) {
    try {
        const DareSolution s = solveDare(A, B, Q, R, N);
        return {s.K, s.P, s.iterations, s.relativeResidual};
    } catch (const DareError& e) {
        throw DareError(e.reason(), e.mode(), std::string("LQ regulator: ") + e.what());
    }
}

LqRegulator lqry(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                 const Eigen::MatrixXd& R1, const Eigen::MatrixXd& R2) {
    if (C.cols() != A.rows() || D.rows() != C.rows() || D.cols() != B.cols() || R1.rows() != C.rows() ||
        R1.cols() != C.rows() || R2.rows() != B.cols() || R2.cols() != B.cols())
        throw std::invalid_argument("lqry: inconsistent sizes of C, D, R1, R2");
    const Eigen::MatrixXd Q = C.transpose() * R1 * C;
    const Eigen::MatrixXd R = R2 + D.transpose() * R1 * D;
    const Eigen::MatrixXd N = C.transpose() * R1 * D;
    return dlqr(A, B, 0.5 * (Q + Q.transpose()), 0.5 * (R + R.transpose()), N);
}

}  // namespace tt::core
