#pragma once

#include <span>

namespace tt::core {

/// Phi(z), the standard normal distribution function (Boost.Math normal distribution, double precision).
double normalCdf(double z);

/// ln Phi(z) without underflow: ln of Boost.Math's Phi for z >= -30, log1p(-Phi(-z)) above 0, and below -30
/// the asymptotic (Mills-ratio) series ln Phi(z) = -z^2/2 - ln(-z) - ln(2 pi)/2 + ln(1 - 1/z^2 + 3/z^4 -
/// 15/z^6 + 105/z^8) (Abramowitz & Stegun 26.2.12), whose truncation error there is below 1e-12. Finite for
/// every finite z.
double logNormalCdf(double z);

/// Phi^-1(p), the standard normal quantile for 0 < p < 1 (Boost.Math). Throws std::invalid_argument
/// otherwise.
double normalQuantile(double p);

/// The lower-tail p quantile of the chi-square distribution with `dof` degrees of freedom: the x with
/// P(X <= x) = p (Boost.Math, inverse of the regularised incomplete gamma function). Needs 0 < p < 1 and
/// 0 < dof <= 1e9; throws std::invalid_argument otherwise.
double chiSquareQuantile(double p, double dof);

/// The upper tail P(X > x) of the chi-square distribution with `dof` degrees of freedom (Boost.Math,
/// complement of the distribution function): the p-value of a chi-square statistic x >= 0. Needs 0 < dof
/// <= 1e9 and a finite x >= 0; throws std::invalid_argument otherwise.
double chiSquareUpperTail(double x, double dof);

/// The empirical p quantile of ascending `sortedValues` by definition 7 of Hyndman & Fan (1996), "Sample
/// quantiles in statistical packages", Am. Stat. 50(4): h = (n - 1) p, Q(p) = x[floor h] + (h - floor h)
/// (x[floor h + 1] - x[floor h]) with x zero-based (R type 7, numpy's default "linear", Excel
/// PERCENTILE.INC). Needs 0 <= p <= 1 and at least one value; throws std::invalid_argument otherwise.
/// The values must already be sorted (not checked: the callers sort them).
double empiricalQuantile(std::span<const double> sortedValues, double p);

}  // namespace tt::core
