#pragma once

#include <Eigen/Core>

namespace tt::core {

/// Solves the Stein (discrete Sylvester) equation `X = A X B + Q` by Smith's doubling
/// (X = sum_k A^k Q B^k, summed 2^j terms at a time). Requires rho(A) * rho(B) < 1; a unit-circle
/// mode in one factor is fine when the other is strictly stable (random-walk feed-forward).
/// Throws std::invalid_argument on inconsistent sizes or when the series does not converge
/// (the equation has no bounded solution).
Eigen::MatrixXd solveStein(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q);

/// The discrete Lyapunov equation `X = A X A' + Q`: the stationary covariance of x+ = A x + w,
/// cov(w) = Q. Throws std::invalid_argument when A is not strictly stable.
Eigen::MatrixXd solveDiscreteLyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q);

/// Largest |eigenvalue| of a square matrix.
double spectralRadius(const Eigen::MatrixXd& A);

}  // namespace tt::core
