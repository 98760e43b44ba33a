#include "core/linalg/dare.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace tt::core {

namespace {

constexpr int kMaxIterations = 80;
constexpr double kConvergenceTolerance = 1e-13;

std::string sizeText(const Eigen::MatrixXd& m) {
    return std::to_string(m.rows()) + "x" + std::to_string(m.cols());
}

void requireFinite(const Eigen::MatrixXd& m, const char* name) {
    if (!m.allFinite())
        throw std::invalid_argument(std::string("Riccati equation: ") + name + " has a NaN or Inf entry");
}

void requireSymmetric(const Eigen::MatrixXd& m, const char* name) {
    const double scale = std::max(1.0, m.norm());
    if ((m - m.transpose()).norm() > 1e-10 * scale)
        throw std::invalid_argument(std::string("Riccati equation: ") + name + " must be symmetric");
}

void validate(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q, const Eigen::MatrixXd& R,
              const Eigen::MatrixXd& N) {
    const Eigen::Index n = A.rows();
    if (n == 0 || A.cols() != n)
        throw std::invalid_argument("Riccati equation: A must be square and non-empty, got " + sizeText(A));
    if (B.rows() != n || B.cols() == 0)
        throw std::invalid_argument("Riccati equation: B must have " + std::to_string(n) + " rows, got " + sizeText(B));
    const Eigen::Index m = B.cols();
    if (Q.rows() != n || Q.cols() != n)
        throw std::invalid_argument("Riccati equation: Q must be " + std::to_string(n) + "x" + std::to_string(n) +
                                    ", got " + sizeText(Q));
    if (R.rows() != m || R.cols() != m)
        throw std::invalid_argument("Riccati equation: R must be " + std::to_string(m) + "x" + std::to_string(m) +
                                    ", got " + sizeText(R));
    if (N.size() != 0 && (N.rows() != n || N.cols() != m))
        throw std::invalid_argument("Riccati equation: N must be " + std::to_string(n) + "x" + std::to_string(m) +
                                    ", got " + sizeText(N));
    requireFinite(A, "A");
    requireFinite(B, "B");
    requireFinite(Q, "Q");
    requireFinite(R, "R");
    requireFinite(N, "N");
    requireSymmetric(Q, "Q");
    requireSymmetric(R, "R");
}

double smallestSingularValue(const Eigen::MatrixXcd& m) {
    Eigen::BDCSVD<Eigen::MatrixXcd> svd(m);
    return svd.singularValues().minCoeff();
}

/// PBH diagnosis after the doubling failed: names the first mode that makes the problem ill-posed.
[[noreturn]] void diagnoseAndThrow(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Ahat,
                                   const Eigen::MatrixXd& Qhat) {
    const Eigen::Index n = A.rows();
    const double scaleAB = std::max(1.0, std::sqrt(A.squaredNorm() + B.squaredNorm()));
    Eigen::EigenSolver<Eigen::MatrixXd> eigA(A, false);
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::complex<double> lambda = eigA.eigenvalues()(i);
        if (std::abs(lambda) < 1.0 - 1e-9) continue;
        Eigen::MatrixXcd pencil(n, n + B.cols());
        pencil << A.cast<std::complex<double>>() - lambda * Eigen::MatrixXcd::Identity(n, n),
            B.cast<std::complex<double>>();
        if (smallestSingularValue(pencil) <= 1e-7 * scaleAB)
            throw DareError(DareError::Reason::NotStabilisable, lambda,
                            "not stabilisable: the mode at " + formatMode(lambda) +
                                " (|lambda| >= 1) cannot be moved by any input");
    }
    const double scaleAQ = std::max(1.0, std::sqrt(Ahat.squaredNorm() + Qhat.squaredNorm()));
    Eigen::EigenSolver<Eigen::MatrixXd> eigAhat(Ahat, false);
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::complex<double> lambda = eigAhat.eigenvalues()(i);
        if (std::abs(std::abs(lambda) - 1.0) > 1e-7) continue;
        Eigen::MatrixXcd pencil(2 * n, n);
        pencil << Ahat.cast<std::complex<double>>() - lambda * Eigen::MatrixXcd::Identity(n, n),
            Qhat.cast<std::complex<double>>();
        if (smallestSingularValue(pencil) <= 1e-7 * scaleAQ)
            throw DareError(
                DareError::Reason::UnobservedOnCircle, lambda,
                "not detectable: the mode at " + formatMode(lambda) + " on the unit circle is not seen by the cost");
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    throw DareError(DareError::Reason::NoConvergence, {nan, nan},
                    "the Riccati iteration did not converge in " + std::to_string(kMaxIterations) +
                        " doubling steps (badly scaled or nearly ill-posed data)");
}

Eigen::MatrixXd gainFrom(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& R,
                         const Eigen::MatrixXd& N, const Eigen::MatrixXd& P) {
    const Eigen::MatrixXd PB = P * B;
    Eigen::MatrixXd rhs = PB.transpose() * A;
    if (N.size() != 0) rhs += N.transpose();
    const Eigen::MatrixXd S = R + B.transpose() * PB;
    return Eigen::LDLT<Eigen::MatrixXd>(S).solve(rhs);
}

}  // namespace

std::string formatMode(std::complex<double> mode) {
    if (std::isnan(mode.real())) return "n/a";
    std::ostringstream out;
    out << std::setprecision(5) << mode.real();
    if (std::abs(mode.imag()) > 1e-12 * std::max(1.0, std::abs(mode.real())))
        out << (mode.imag() >= 0 ? "+" : "-") << std::setprecision(5) << std::abs(mode.imag()) << "i";
    return out.str();
}

double dareRelativeResidual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                            const Eigen::MatrixXd& R, const Eigen::MatrixXd& N, const Eigen::MatrixXd& P) {
    const Eigen::MatrixXd PB = P * B;
    Eigen::MatrixXd cross = A.transpose() * PB;
    if (N.size() != 0) cross += N;
    const Eigen::MatrixXd S = R + B.transpose() * PB;
    const Eigen::MatrixXd residual =
        A.transpose() * P * A - P - cross * Eigen::LDLT<Eigen::MatrixXd>(S).solve(cross.transpose()) + Q;
    const double scale = P.norm();
    return scale > 0.0 ? residual.norm() / scale : residual.norm();
}

DareSolution solveDare(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R, const Eigen::MatrixXd& N) {
    validate(A, B, Q, R, N);
    const Eigen::Index n = A.rows();
    Eigen::LLT<Eigen::MatrixXd> rChol(R);
    if (rChol.info() != Eigen::Success || (R.diagonal().array() <= 0.0).any())
        throw std::invalid_argument("Riccati equation: R must be positive definite (every input needs a cost)");

    // Remove the cross term: u = v - R^-1 N' x.
    Eigen::MatrixXd Ahat = A;
    Eigen::MatrixXd Qhat = Q;
    if (N.size() != 0) {
        Ahat -= B * rChol.solve(N.transpose());
        Qhat -= N * rChol.solve(N.transpose());
        Qhat = 0.5 * (Qhat + Qhat.transpose()).eval();
    }

    // SDA: A_{k+1} = A_k W^-1 A_k, G_{k+1} = G_k + A_k W^-1 G_k A_k', H_{k+1} = H_k + A_k' H_k W^-1 A_k,
    // W = I + G_k H_k; H_k -> P quadratically when a stabilising solution exists.
    Eigen::MatrixXd Ak = Ahat;
    Eigen::MatrixXd Gk = B * rChol.solve(B.transpose());
    Gk = 0.5 * (Gk + Gk.transpose()).eval();
    Eigen::MatrixXd Hk = Qhat;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
    int iterations = 0;
    bool converged = false;
    for (; iterations < kMaxIterations && !converged;) {
        ++iterations;
        Eigen::PartialPivLU<Eigen::MatrixXd> W(I + Gk * Hk);
        const Eigen::MatrixXd WinvA = W.solve(Ak);
        const Eigen::MatrixXd WinvG = W.solve(Gk);
        Eigen::MatrixXd Hnext = Hk + Ak.transpose() * Hk * WinvA;
        Hnext = 0.5 * (Hnext + Hnext.transpose()).eval();
        Gk += Ak * WinvG * Ak.transpose();
        Gk = 0.5 * (Gk + Gk.transpose()).eval();
        Ak = (Ak * WinvA).eval();
        if (!Hnext.allFinite() || !Gk.allFinite() || !Ak.allFinite()) break;
        const double change = (Hnext - Hk).norm();
        const double size = Hnext.norm();
        Hk = std::move(Hnext);
        converged = change <= kConvergenceTolerance * size;
    }
    if (!converged) diagnoseAndThrow(A, B, Ahat, Qhat);

    DareSolution solution;
    solution.P = Hk;
    solution.K = gainFrom(A, B, R, N, Hk);
    solution.iterations = iterations;
    // A_k ~ (A - BK)^(2^k): when it has not vanished, confirm stability of the closed loop explicitly.
    if (Ak.norm() > 1e-4 * std::max(1.0, A.norm())) {
        Eigen::EigenSolver<Eigen::MatrixXd> eig(A - B * solution.K, false);
        if (eig.eigenvalues().cwiseAbs().maxCoeff() >= 1.0) diagnoseAndThrow(A, B, Ahat, Qhat);
    }
    solution.relativeResidual = dareRelativeResidual(A, B, Q, R, N, solution.P);
    return solution;
}

}  // namespace tt::core
