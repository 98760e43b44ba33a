#pragma once

#include <complex>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

namespace tt::core {

/// The stabilising solution of a discrete algebraic Riccati equation
/// `P = A'PA - (A'PB + N)(R + B'PB)^-1 (B'PA + N') + Q` and its gain `K = (R + B'PB)^-1 (B'PA + N')`.
struct DareSolution {
    Eigen::MatrixXd P;              ///< the stabilising solution (symmetric, n x n)
    Eigen::MatrixXd K;              ///< the optimal gain (m x n): A - B K is stable
    int iterations = 0;             ///< doubling steps taken
    double relativeResidual = 0.0;  ///< ||residual||_F / ||P||_F (absolute when P = 0)
};

/// Why a DARE has no stabilising solution. Wrappers (LQ regulator, Kalman filter) rephrase the
/// message in their own terms from `reason` and `mode`.
class DareError : public std::invalid_argument {
public:
    /// Why the equation has no usable solution.
    enum class Reason {
        NotStabilisable,     ///< a mode with |lambda| >= 1 cannot be reached by the inputs (PBH test)
        UnobservedOnCircle,  ///< a mode on the unit circle is not seen by the cost Q
        NoConvergence,       ///< the doubling did not converge (ill-posed or badly scaled data)
    };
    /// `mode`: the eigenvalue of A that makes the problem ill-posed (NaN when none applies).
    DareError(Reason reason, std::complex<double> mode, const std::string& message)
        : std::invalid_argument(message), m_reason(reason), m_mode(mode) {}
    /// Why the solver refused.
    Reason reason() const { return m_reason; }
    /// The offending eigenvalue of A (NaN when not applicable).
    std::complex<double> mode() const { return m_mode; }

private:
    Reason m_reason;
    std::complex<double> m_mode;
};

/// Solves the DARE above with the structure-preserving doubling algorithm (SDA; Chu, Fan, Lin & Wang,
/// "Structure-preserving algorithms for periodic discrete-time algebraic Riccati equations", Int. J.
/// Control 77(8), 2004; convergence: Lin & Xu, SIAM J. Matrix Anal. Appl. 28(1), 2006). The cross
/// term N is removed first (A <- A - B R^-1 N', Q <- Q - N R^-1 N'). Converges quadratically; A may be
/// singular (delay chains). `N` may be an empty matrix (= 0).
/// Throws std::invalid_argument for inconsistent sizes, non-symmetric Q/R or R not positive definite,
/// and DareError when no stabilising solution exists (naming the offending mode).
DareSolution solveDare(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R, const Eigen::MatrixXd& N = Eigen::MatrixXd());

/// The DARE residual `A'PA - P - (A'PB + N)(R + B'PB)^-1 (B'PA + N') + Q` (Frobenius norm) divided by
/// ||P||_F (absolute when P = 0). Used to report and test solutions.
double dareRelativeResidual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                            const Eigen::MatrixXd& R, const Eigen::MatrixXd& N, const Eigen::MatrixXd& P);

/// Formats a (possibly complex) eigenvalue for messages: "1.0029", "0.5+0.8i".
std::string formatMode(std::complex<double> mode);

}  // namespace tt::core
