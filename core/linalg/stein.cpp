#include "core/linalg/stein.h"

#include <Eigen/Eigenvalues>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

constexpr int kMaxDoublings = 100;

}  // namespace

Eigen::MatrixXd solveStein(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q) {
    if (A.rows() != A.cols() || B.rows() != B.cols() || Q.rows() != A.rows() || Q.cols() != B.rows())
        throw std::invalid_argument("Stein equation X = A X B + Q: inconsistent sizes");
    if (!A.allFinite() || !B.allFinite() || !Q.allFinite())
        throw std::invalid_argument("Stein equation X = A X B + Q: NaN or Inf in the data");
    Eigen::MatrixXd X = Q;
    Eigen::MatrixXd Ak = A;
    Eigen::MatrixXd Bk = B;
    for (int j = 0; j < kMaxDoublings; ++j) {
        // Sum of the next 2^j terms: A^(2^j) X_j B^(2^j).
        X += Ak * X * Bk;
        const double factor = Ak.norm() * Bk.norm();
        if (!X.allFinite() || factor > 1e150)
            throw std::invalid_argument("Stein equation X = A X B + Q has no bounded solution (rho(A) rho(B) >= 1)");
        if (factor <= 1e-17) return X;
        Ak = (Ak * Ak).eval();
        Bk = (Bk * Bk).eval();
    }
    throw std::invalid_argument("Stein equation X = A X B + Q did not converge (rho(A) rho(B) too close to 1)");
}

Eigen::MatrixXd solveDiscreteLyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q) {
    if (A.rows() != A.cols()) throw std::invalid_argument("Lyapunov equation: A must be square");
    if (A.rows() > 0 && spectralRadius(A) >= 1.0)
        throw std::invalid_argument("Lyapunov equation: the system is not stable (an eigenvalue has |lambda| >= 1)");
    Eigen::MatrixXd X = solveStein(A, A.transpose(), Q);
    return 0.5 * (X + X.transpose());
}

double spectralRadius(const Eigen::MatrixXd& A) {
    if (A.size() == 0) return 0.0;
    Eigen::EigenSolver<Eigen::MatrixXd> eig(A, false);
    return eig.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace tt::core
