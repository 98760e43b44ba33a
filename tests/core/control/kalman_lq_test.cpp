#include <gtest/gtest.h>

#include "core/control/kalman_filter.h"
#include "core/control/lq_regulator.h"
#include "core/linalg/dare.h"

namespace tt::core {
namespace {

using Eigen::MatrixXd;

// MathWorks Control System Toolbox documentation, example "Kalman Filtering" (steady-state design with
// kalman): A = [1.1269 -0.4940 0.1129; 1 0 0; 0 1 0], B = G = [-0.3832; 0.5919; 0.5191], C = [1 0 0],
// Q = 2.3, R = 1 -> innovation gain M = [0.5345; 0.0101; -0.4776] (4 decimals). Our L is MATLAB's M.
TEST(Kalman, MatchesTheMatlabDocumentationExample) {
    MatrixXd A(3, 3), G(3, 1), C(1, 3);
    A << 1.1269, -0.4940, 0.1129, 1, 0, 0, 0, 1, 0;
    G << -0.3832, 0.5919, 0.5191;
    C << 1, 0, 0;
    const KalmanDesign k = designKalman(A, C, G, MatrixXd::Constant(1, 1, 2.3), MatrixXd::Constant(1, 1, 1.0));
    EXPECT_NEAR(k.L(0, 0), 0.5345, 5e-5);
    EXPECT_NEAR(k.L(1, 0), 0.0101, 5e-5);
    EXPECT_NEAR(k.L(2, 0), -0.4776, 5e-5);
    EXPECT_LT(k.relativeResidual, 1e-10);
    // Definitions: L = P C'(C P C' + V)^-1, Z = (I - L C) P, predictor gain = A L.
    EXPECT_LT((k.L - k.P * C.transpose() / ((C * k.P * C.transpose())(0, 0) + 1.0)).norm(), 1e-12);
    EXPECT_LT((k.Z - (MatrixXd::Identity(3, 3) - k.L * C) * k.P).norm(), 1e-12);
    EXPECT_LT((k.predictorGain - A * k.L).norm(), 1e-12);
}

// Scalar filter for a random walk observed in noise, x+ = x + w, y = x + v: the a-priori variance
// solves p = p - p^2/(p + r) + q, i.e. p^2 - q p - q r = 0, p = (q + sqrt(q^2 + 4 q r)) / 2
// (textbook local-level model, e.g. Harvey, Forecasting, Structural Time Series Models and the
// Kalman Filter, 1989, sec. 3.3.3 steady state of the local level model).
TEST(Kalman, LocalLevelModelClosedForm) {
    const double q = 0.3, r = 2.0;
    const KalmanDesign k = designKalman(MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1),
                                        MatrixXd::Constant(1, 1, q), MatrixXd::Constant(1, 1, r));
    const double p = (q + std::sqrt(q * q + 4 * q * r)) / 2;
    EXPECT_NEAR(k.P(0, 0), p, 1e-12);
    EXPECT_NEAR(k.L(0, 0), p / (p + r), 1e-12);
}

TEST(Kalman, RefusesAnUndetectableUnstableMode) {
    MatrixXd A(2, 2), C(1, 2);
    A << 1.1, 0, 0, 0.5;
    C << 0, 1;
    try {
        designKalman(A, C, MatrixXd::Identity(2, 2), MatrixXd::Identity(2, 2), MatrixXd::Ones(1, 1));
        FAIL() << "expected an error";
    } catch (const DareError& e) {
        EXPECT_NE(std::string(e.what()).find("Kalman filter: not detectable: the mode at 1.1"), std::string::npos)
            << e.what();
    }
}

TEST(Kalman, RefusesAUnitCircleModeWithoutNoise) {
    // A random walk with zero step variance: the mode at 1 is never excited.
    try {
        designKalman(MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Zero(1, 1),
                     MatrixXd::Ones(1, 1));
        FAIL() << "expected an error";
    } catch (const DareError& e) {
        EXPECT_NE(std::string(e.what()).find("not driven by any noise"), std::string::npos) << e.what();
    }
}

// MATLAB lqry: Q = C'R1C, R = R2 + D'R1D, N = C'R1D; checked against dlqr on those matrices, and on
// a scalar case where the optimum is known: y = x + d u, x+ = a x + u, R1 = 1, R2 -> the DARE of
// (a, 1, 1, R2 + d^2, d).
TEST(Lqry, EqualsDlqrWithTheOutputWeights) {
    MatrixXd A(2, 2), B(2, 1), C(2, 2), D(2, 1), R1(2, 2), R2(1, 1);
    A << 0.9, 0.2, 0.0, 0.7;
    B << 0.0, 1.0;
    C << 1.0, 0.0, 0.5, 1.0;
    D << 0.2, 0.1;
    R1 << 2.0, 0.3, 0.3, 1.0;
    R2 << 0.5;
    const LqRegulator y = lqry(A, B, C, D, R1, R2);
    const LqRegulator x = dlqr(A, B, C.transpose() * R1 * C, R2 + D.transpose() * R1 * D, C.transpose() * R1 * D);
    EXPECT_LT((y.K - x.K).norm(), 1e-13);
    EXPECT_LT((y.S - x.S).norm(), 1e-12);
    EXPECT_LT(y.relativeResidual, 1e-10);
}

// A pure one-step delay y(k) = 2 u(k-1) with R2 -> 0: the LQ output regulator is deadbeat, K x = y/2 of
// the next step; here with the state x = u(k-1): A = 0, B = 1, C = 2 -> K = 0 for any R2 > 0
// (nothing to regulate once the input is applied) and S = 4 (cost of a unit state: y^2 = 4).
TEST(Lqry, DelayChainCostsAreExact) {
    const LqRegulator lq = lqry(MatrixXd::Zero(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Constant(1, 1, 2.0),
                                MatrixXd::Zero(1, 1), MatrixXd::Ones(1, 1), MatrixXd::Constant(1, 1, 0.01));
    EXPECT_NEAR(lq.S(0, 0), 4.0, 1e-14);
    EXPECT_NEAR(lq.K(0, 0), 0.0, 1e-14);
}

}  // namespace
}  // namespace tt::core
