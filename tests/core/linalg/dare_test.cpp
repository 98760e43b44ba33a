#include "core/linalg/dare.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "core/control/lq_regulator.h"

namespace tt::core {
namespace {

using Eigen::MatrixXd;

MatrixXd M(std::initializer_list<std::initializer_list<double>> rows) {
    MatrixXd m(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.begin()->size()));
    Eigen::Index r = 0;
    for (const auto& row : rows) {
        Eigen::Index c = 0;
        for (double v : row)
            m(r, c++) = v;
        ++r;
    }
    return m;
}

double relativeError(const MatrixXd& a, const MatrixXd& b) {
    return (a - b).norm() / b.norm();
}

// Scalar DARE x = a^2 x - a^2 b^2 x^2 / (r + b^2 x) + q. Multiplying by (r + b^2 x) gives the quadratic
// b^2 x^2 + (r (1 - a^2) - q b^2) x - q r = 0, whose positive root is the stabilising solution.
TEST(Dare, ScalarMatchesClosedForm) {
    const double a = 1.2, b = 0.5, q = 2.0, r = 0.3;
    const double p = r * (1 - a * a) - q * b * b;
    const double expected = (-p + std::sqrt(p * p + 4 * b * b * q * r)) / (2 * b * b);
    const DareSolution s = solveDare(M({{a}}), M({{b}}), M({{q}}), M({{r}}));
    EXPECT_NEAR(s.P(0, 0), expected, 1e-12 * expected);
    EXPECT_LT(s.relativeResidual, 1e-10);
    EXPECT_LT(std::abs(a - b * s.K(0, 0)), 1.0) << "closed loop stable";
}

// DAREX example 1 (Benner, Laub & Mehrmann, "A Collection of Benchmark Examples for the Numerical
// Solution of Algebraic Riccati Equations II: Discrete-Time Case", TU Chemnitz SPC 95_23, 1995;
// darex(1)): exact solution X = (1 + sqrt 5)/2 * Q.
TEST(Dare, DarexExample1ExactSolution) {
    const MatrixXd Q = M({{9, 6}, {6, 4}});
    const DareSolution s = solveDare(M({{4, 3}, {-4.5, -3.5}}), M({{1}, {-1}}), Q, M({{1}}));
    EXPECT_LT(relativeError(s.P, (1 + std::sqrt(5.0)) / 2 * Q), 1e-12);
    EXPECT_LT(s.relativeResidual, 1e-10);
}

// Same collection, darex(5): A = [0 1; 0 0] (a delay chain), X = [1 2; 2 2 + sqrt 5].
TEST(Dare, DarexExample5ExactSolution) {
    const DareSolution s = solveDare(M({{0, 1}, {0, 0}}), M({{0}, {1}}), M({{1, 2}, {2, 4}}), M({{1}}));
    EXPECT_LT(relativeError(s.P, M({{1, 2}, {2, 2 + std::sqrt(5.0)}})), 1e-12);
    EXPECT_LT(s.relativeResidual, 1e-10);
}

// Same collection, darex(13) (parameter d): X = d U diag(1, (1+sqrt 5)/2, (9+sqrt 85)/2) U,
// U = I - (2/3) ones(3); checked at d = 1 and the default d = 1e6 (badly scaled R and Q).
TEST(Dare, DarexExample13ExactSolutionAtTwoScales) {
    const MatrixXd U = MatrixXd::Identity(3, 3) - (2.0 / 3.0) * MatrixXd::Ones(3, 3);
    const MatrixXd A = U * Eigen::Vector3d(0, 1, 3).asDiagonal() * U;
    for (double d : {1.0, 1e6}) {
        const DareSolution s =
            solveDare(A, MatrixXd::Identity(3, 3), d * MatrixXd::Identity(3, 3), d * MatrixXd::Identity(3, 3));
        const MatrixXd X =
            d * U * Eigen::Vector3d(1, (1 + std::sqrt(5.0)) / 2, (9 + std::sqrt(85.0)) / 2).asDiagonal() * U;
        EXPECT_LT(relativeError(s.P, X), 1e-10) << "d = " << d;
        EXPECT_LT(s.relativeResidual, 1e-10) << "d = " << d;
    }
}

// Same collection, darex(15): a 100-state shift register (the structure of the run-to-run delay
// chains), B = e_n, Q = I, R = 1; X = diag(1, 2, ..., n).
TEST(Dare, DarexExample15ShiftRegisterOf100States) {
    const int n = 100;
    MatrixXd A = MatrixXd::Zero(n, n);
    for (int i = 0; i + 1 < n; ++i)
        A(i, i + 1) = 1.0;
    MatrixXd B = MatrixXd::Zero(n, 1);
    B(n - 1, 0) = 1.0;
    const DareSolution s = solveDare(A, B, MatrixXd::Identity(n, n), M({{1}}));
    MatrixXd X = MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
        X(i, i) = i + 1;
    EXPECT_LT(relativeError(s.P, X), 1e-12);
    EXPECT_LT(s.relativeResidual, 1e-10);
}

// Altair Compose documentation, dlqr example: A = [9 0.2; 0 8], B = [0; 1], Q = [2 1; 1 2], R = 1
// -> K = [394.61003 16.76761], X = [1.04036e7 2.34349e5; 2.34349e5 5.34387e3], closed-loop poles
// 0.11073, 0.12166 (published to the digits shown; an unstable plant).
TEST(Dare, DlqrMatchesPublishedUnstablePlantExample) {
    const LqRegulator lq = dlqr(M({{9, 0.2}, {0, 8}}), M({{0}, {1}}), M({{2, 1}, {1, 2}}), M({{1}}));
    EXPECT_NEAR(lq.K(0, 0), 394.61003, 5e-5);
    EXPECT_NEAR(lq.K(0, 1), 16.76761, 5e-6);
    EXPECT_NEAR(lq.S(0, 0), 1.04036e7, 5e1);
    EXPECT_NEAR(lq.S(0, 1), 2.34349e5, 0.5);
    EXPECT_NEAR(lq.S(1, 1), 5.34387e3, 5e-3);
    EXPECT_LT(lq.relativeResidual, 1e-10);
}

TEST(Dare, CrossTermEqualsTheShiftedProblem) {
    // With N, the same solution as the problem without N after u = v - R^-1 N' x (textbook identity).
    const MatrixXd A = M({{0.9, 0.3}, {-0.2, 1.1}});
    const MatrixXd B = M({{0.5}, {1.0}});
    const MatrixXd Q = M({{2, 0.5}, {0.5, 1}});
    const MatrixXd R = M({{0.7}});
    const MatrixXd N = M({{0.3}, {-0.2}});
    const DareSolution withN = solveDare(A, B, Q, R, N);
    const DareSolution shifted =
        solveDare(A - B * R.inverse() * N.transpose(), B, Q - N * R.inverse() * N.transpose(), R);
    EXPECT_LT(relativeError(withN.P, shifted.P), 1e-12);
    EXPECT_LT(relativeError(withN.K, shifted.K + R.inverse() * N.transpose()), 1e-12);
    EXPECT_LT(withN.relativeResidual, 1e-10);
}

TEST(Dare, RefusesANonStabilisablePairNamingTheMode) {
    try {
        solveDare(M({{1.2, 0}, {0, 0.5}}), M({{0}, {1}}), MatrixXd::Identity(2, 2), M({{1}}));
        FAIL() << "expected DareError";
    } catch (const DareError& e) {
        EXPECT_EQ(e.reason(), DareError::Reason::NotStabilisable);
        EXPECT_NEAR(e.mode().real(), 1.2, 1e-9);
        EXPECT_NE(std::string(e.what()).find("not stabilisable: the mode at 1.2"), std::string::npos) << e.what();
    }
}

TEST(Dare, RefusesAnUnobservedUnitCircleMode) {
    // x+ = x + u with no state cost: the optimum is u = 0, which leaves the mode at 1 unstabilised.
    try {
        solveDare(M({{1.0}}), M({{1}}), M({{0}}), M({{1}}));
        FAIL() << "expected DareError";
    } catch (const DareError& e) {
        EXPECT_EQ(e.reason(), DareError::Reason::UnobservedOnCircle);
        EXPECT_NE(std::string(e.what()).find("not detectable"), std::string::npos) << e.what();
    }
}

TEST(Dare, RefusesBadInput) {
    const MatrixXd A = M({{0.5}});
    EXPECT_THROW(solveDare(A, M({{1}}), M({{1}}), M({{0}})), std::invalid_argument);   // R not > 0
    EXPECT_THROW(solveDare(A, M({{1}}), M({{1}}), M({{-1}})), std::invalid_argument);  // R < 0
    EXPECT_THROW(solveDare(M({{0.5, 1}, {0, 0.5}}), M({{1}, {0}}), M({{1, 1}, {0, 1}}), M({{1}})),
                 std::invalid_argument);                                                   // Q not symmetric
    EXPECT_THROW(solveDare(A, M({{1}, {1}}), M({{1}}), M({{1}})), std::invalid_argument);  // sizes
    EXPECT_THROW(solveDare(M({{std::nan("")}}), M({{1}}), M({{1}}), M({{1}})), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
