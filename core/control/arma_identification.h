#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/model/disturbance_model.h"

namespace tt::core {

/// Orders of an ARMA(p, q) model: y(t) = a_1 y(t-1) + .. + a_p y(t-p) + e(t) + b_1 e(t-1) + .. + b_q e(t-q).
struct ArmaOrders {
    int ar = 1;  ///< p, 0 .. 4
    int ma = 1;  ///< q, 0 .. 4
};

/// Largest AR and MA order; fewest values a fit takes, and most.
inline constexpr int kMaxArmaOrder = 4;
inline constexpr std::size_t kMinArmaValues = 50;
inline constexpr std::size_t kMaxArmaValues = 10'000'000;

/// An ARMA model fitted to a part-to-part series (MATLAB `armax` without input; statsmodels ARIMA(p, 0, q)).
struct ArmaFit {
    std::vector<double> ar;         ///< a_1 .. a_p
    std::vector<double> ma;         ///< b_1 .. b_q
    std::vector<double> arStdErr;   ///< standard errors of a_i
    std::vector<double> maStdErr;   ///< standard errors of b_j
    double meanMm = 0.0;            ///< the series' mean, removed before the fit
    double noiseVarianceMm2 = 0.0;  ///< variance of e, mm^2 (sum of squared residuals / (n - p - q))
    double ljungBoxQ = 0.0;         ///< Ljung-Box statistic of the residuals
    int ljungBoxLags = 0;           ///< lags h in it (degrees of freedom h - p - q)
    double ljungBoxP = 0.0;         ///< its p-value (small: the residuals are not white, the model misses something)
    std::size_t values = 0;         ///< values fitted
    int iterations = 0;             ///< Gauss-Newton steps

    /// The fit as the presets' shaping filter W(z) = (z^q + b_1 z^(q-1) + ..) / (z^p - a_1 z^(p-1) - ..)
    /// (numerator padded to the denominator's degree) driven by the fitted noise variance; an ARMA(0, 0)
    /// is white noise. Throws std::invalid_argument when the AR part is not stable.
    DisturbanceModel disturbanceModel() const;
};

/// Fits ARMA(p, q) to `values` (mm) by the prediction-error method: the mean is removed, Hannan-Rissanen
/// (a long AR for the innovations, then least squares) gives the start, Gauss-Newton on the conditional
/// one-step prediction errors (e(t) = 0 before the first value) refines it, keeping the AR part stable
/// and the MA part invertible. Standard errors from sigma^2 (J'J)^-1; Ljung-Box on the residuals with
/// h = min(20, n / 5) lags. Throws std::invalid_argument for orders out of range, fewer than 50 or more than
/// 1e7 values, a non-finite value or a constant series.
ArmaFit fitArma(const std::vector<double>& values, ArmaOrders orders);

/// The parameters (a_1 .. a_p, b_1 .. b_q) describe a stable AR part (roots of z^p - a_1 z^(p-1) - .. inside
/// 0.9999) and an invertible MA part (roots of z^q + b_1 z^(q-1) + .. inside 0.9999), all finite.
bool armaAdmissible(const Eigen::VectorXd& theta, int p, int q);

/// Hannan-Rissanen start of an ARMA(p, q) fit of a zero-mean series (Hannan & Rissanen 1982): innovations from a
/// long AR by least squares, then y on its own lags and the innovations' lags; zeros when that is not admissible.
Eigen::VectorXd hannanRissanenStart(const std::vector<double>& y, int p, int q);

/// The Ljung-Box statistic Q = n (n + 2) sum_k r_k^2 / (n - k), k = 1 .. lags, of a series.
double ljungBoxStatistic(const std::vector<double>& residuals, int lags);

}  // namespace tt::core
