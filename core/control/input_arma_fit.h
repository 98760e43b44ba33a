#pragma once

#include <optional>
#include <vector>

#include "core/control/arma_identification.h"

namespace tt::core {

/// A static gain from one input plus ARMA noise, fitted to a part-to-part series:
///   y(t) = g u(t) + mu + v(t),   v(t) = a_1 v(t-1) + .. + a_p v(t-p) + e(t) + b_1 e(t-1) + .. + b_q e(t-q)
/// (Ljung, System Identification, 2nd ed., 1999: the Box-Jenkins model with B = g, F = 1; the "direct
/// method" of closed-loop identification, sec. 13.4, consistent in closed loop when the noise model holds).
struct InputArmaFit {
    double gain = 0.0;        ///< g, output per unit input
    double gainStdErr = 0.0;  ///< its standard error (given the ARMA part when that was taken as known)
    /// Its standard error with the ARMA part free at the same parameters: how well the data alone tell the gain (in
    /// closed loop a gain change can look like a noise change; then this is much larger than gainStdErr).
    double gainStdErrJoint = 0.0;
    double meanMm = 0.0;            ///< mu, mm
    double meanStdErr = 0.0;        ///< its standard error
    ArmaFit noise;                  ///< the ARMA part (ar, ma, their standard errors, noise variance, Ljung-Box)
    std::vector<double> residuals;  ///< e(t), the one-step prediction errors (conditional: e = 0 before the start)
    /// Gaussian log-likelihood term n ln(sum e^2 / n) of the residuals after `skip` values (what the
    /// information criteria compare; the same `skip` for every model compared).
    double logLikelihoodTerm = 0.0;
    int parameters = 0;  ///< p + q + 2 (the gain and the mean); 2 when the ARMA part was taken as known
};

/// Fewest values fitInputArma takes.
inline constexpr std::size_t kMinInputArmaValues = 60;

/// Fits the model by the prediction-error method: the start from a long ARX by least squares (its coefficient
/// of u(t) estimates g consistently in closed loop, Ljung sec. 13.4) and Hannan-Rissanen for the ARMA part,
/// then Gauss-Newton with step halving on the conditional one-step prediction errors keeping the AR part stable
/// and the MA part invertible, also from `priorGain` when given (the better of the two is kept). Standard errors
/// from sigma^2 (J'J)^-1. The first `skip` residuals are left out of logLikelihoodTerm and of the Ljung-Box test.
/// Throws std::invalid_argument for orders out of 0 .. kMaxArmaOrder, series of different lengths, fewer than
/// kMinInputArmaValues values, a value that is not finite, or an input that never changes.
InputArmaFit fitInputArma(const std::vector<double>& y, const std::vector<double>& u, ArmaOrders orders,
                          std::optional<double> priorGain = std::nullopt, int skip = 0);

/// The model at given parameters without any search: its residuals, logLikelihoodTerm, the ARMA part with the
/// noise variance, and the standard errors from sigma^2 (J'J)^-1 at that point: of every parameter, or with
/// `noiseFixed` of the gain and the mean alone (the ARMA part taken as known: parameters = 2, no standard errors
/// of a and b). Throws as fitInputArma.
InputArmaFit evaluateInputArma(const std::vector<double>& y, const std::vector<double>& u, double gain, double meanMm,
                               const std::vector<double>& ar, const std::vector<double>& ma, int skip = 0,
                               bool noiseFixed = false);

}  // namespace tt::core
