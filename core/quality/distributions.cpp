#include "core/quality/distributions.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

/// Boost.Math promotes double to long double by default; double precision is what the peers (scipy)
/// compute and is ample for limits and p-values (the same policy as the regression in core/model).
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
using Normal = boost::math::normal_distribution<double, DoublePolicy>;
using ChiSquared = boost::math::chi_squared_distribution<double, DoublePolicy>;

constexpr double kAsymptoticTailZ = -30.0;
constexpr double kMaxChiSquareDof = 1e9;

}  // namespace

double normalCdf(double z) {
    if (std::isnan(z)) throw std::invalid_argument("the normal distribution function needs a number");
    if (std::isinf(z)) return z > 0.0 ? 1.0 : 0.0;
    return boost::math::cdf(Normal(), z);
}

double logNormalCdf(double z) {
    if (!std::isfinite(z)) throw std::invalid_argument("ln Phi(z) needs a finite z");
    if (z > 0.0) return std::log1p(-boost::math::cdf(Normal(), -z));
    if (z >= kAsymptoticTailZ) return std::log(boost::math::cdf(Normal(), z));
    const double inverseSquare = 1.0 / (z * z);
    const double series =
        1.0 + inverseSquare * (-1.0 + inverseSquare * (3.0 + inverseSquare * (-15.0 + inverseSquare * 105.0)));
    return -0.5 * z * z - std::log(-z) - 0.5 * std::log(2.0 * std::numbers::pi) + std::log(series);
}

double normalQuantile(double p) {
    if (!(p > 0.0 && p < 1.0))
        throw std::invalid_argument("a normal quantile needs a probability strictly between 0 and 1 (got " +
                                    std::to_string(p) + ")");
    return boost::math::quantile(Normal(), p);
}

double chiSquareQuantile(double p, double dof) {
    if (!(p > 0.0 && p < 1.0))
        throw std::invalid_argument("a chi-square quantile needs a probability strictly between 0 and 1 (got " +
                                    std::to_string(p) + ")");
    if (!(dof > 0.0 && dof <= kMaxChiSquareDof))
        throw std::invalid_argument("a chi-square quantile needs 0 < degrees of freedom <= 1e9 (got " +
                                    std::to_string(dof) + ")");
    return boost::math::quantile(ChiSquared(dof), p);
}

double chiSquareUpperTail(double x, double dof) {
    if (!(dof > 0.0 && dof <= kMaxChiSquareDof))
        throw std::invalid_argument("a chi-square tail needs 0 < degrees of freedom <= 1e9 (got " +
                                    std::to_string(dof) + ")");
    if (!std::isfinite(x) || x < 0.0)
        throw std::invalid_argument("a chi-square tail needs a finite statistic >= 0 (got " + std::to_string(x) + ")");
    return boost::math::cdf(boost::math::complement(ChiSquared(dof), x));
}

double empiricalQuantile(std::span<const double> sortedValues, double p) {
    if (sortedValues.empty()) throw std::invalid_argument("a quantile needs at least one value");
    if (!(p >= 0.0 && p <= 1.0))
        throw std::invalid_argument("a quantile needs a probability from 0 to 1 (got " + std::to_string(p) + ")");
    const double h = static_cast<double>(sortedValues.size() - 1) * p;
    const double below = std::floor(h);
    const auto index = static_cast<std::size_t>(below);
    if (index + 1 >= sortedValues.size()) return sortedValues.back();
    return sortedValues[index] + (h - below) * (sortedValues[index + 1] - sortedValues[index]);
}

}  // namespace tt::core
