#include "core/model/polynomial_regression.h"

#include <Eigen/QR>
#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Boost.Math evaluates double quantiles in long double by default; double precision is ample
/// for a critical value and makes the fit about 7 times faster (see docs/DECISIONS.md).
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
using FisherF = boost::math::fisher_f_distribution<double, DoublePolicy>;
using StudentT = boost::math::students_t_distribution<double, DoublePolicy>;

/// Leverage at or above this counts as 1: the point cannot be predicted from the others.
constexpr double kLeverageOne = 1.0 - 1e-10;

Eigen::Index distinctCount(const Eigen::VectorXd& x) {
    std::vector<double> sorted(x.data(), x.data() + x.size());
    std::sort(sorted.begin(), sorted.end());
    return std::unique(sorted.begin(), sorted.end()) - sorted.begin();
}

void checkData(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    if (x.size() != y.size())
        throw std::invalid_argument("the regression needs as many values as positions (" + std::to_string(x.size()) +
                                    " positions, " + std::to_string(y.size()) + " values)");
    if (x.size() == 0) throw std::invalid_argument("the regression needs data points");
    for (Eigen::Index i = 0; i < x.size(); ++i)
        if (!std::isfinite(x(i)) || !std::isfinite(y(i)))
            throw std::invalid_argument("data point " + std::to_string(i + 1) + " is not a finite number");
    if (distinctCount(x) < 2)
        throw std::invalid_argument("all " + std::to_string(x.size()) +
                                    " points are at the same position: a profile needs at least two different x");
    if ((y.array() == y(0)).all())
        throw std::invalid_argument("all values are equal (" + std::to_string(y(0)) +
                                    "): there is no variation along x to fit");
}

void checkDegree(const Eigen::VectorXd& x, int degree) {
    if (degree < 1 || degree > kMaxRegressionDegree)
        throw std::invalid_argument("the polynomial degree must be 1 .. " + std::to_string(kMaxRegressionDegree) +
                                    " (got " + std::to_string(degree) + ")");
    const auto n = x.size();
    if (n < degree + 2)
        throw std::invalid_argument("degree " + std::to_string(degree) + " needs at least " +
                                    std::to_string(degree + 2) + " points (one more than its coefficients); got " +
                                    std::to_string(n));
    const auto distinct = distinctCount(x);
    if (distinct < degree + 1)
        throw std::invalid_argument("degree " + std::to_string(degree) + " needs at least " +
                                    std::to_string(degree + 1) + " different x positions; got " +
                                    std::to_string(distinct));
}

/// Rows 1, t, t^2, ..., t^D with t = (x - centre) / scale.
Eigen::MatrixXd vandermonde(const Eigen::VectorXd& x, int degree, double centre, double scale) {
    Eigen::MatrixXd v(x.size(), degree + 1);
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double t = (x(i) - centre) / scale;
        double power = 1.0;
        for (int k = 0; k <= degree; ++k) {
            v(i, k) = power;
            power *= t;
        }
    }
    return v;
}

}  // namespace

RegressionPrediction PolynomialRegression::predict(double x, double level) const {
    if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("the band level must lie strictly between 0 and 1");
    const double t = (x - polynomial.centre()) / polynomial.scale();
    Eigen::VectorXd v(degree + 1);
    double power = 1.0;
    for (int k = 0; k <= degree; ++k) {
        v(k) = power;
        power *= t;
    }
    const double leverage = std::max(0.0, v.dot(scaledCovarianceFactor * v));
    const StudentT student(static_cast<double>(residualDof));
    const double quantile = boost::math::quantile(student, 0.5 + 0.5 * level);
    RegressionPrediction p;
    p.x = x;
    p.value = polynomial.value(x);
    p.confidenceHalfWidth = quantile * residualSigma * std::sqrt(leverage);
    p.predictionHalfWidth = quantile * residualSigma * std::sqrt(1.0 + leverage);
    return p;
}

PolynomialRegression fitPolynomialRegression(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
    checkData(x, y);
    checkDegree(x, degree);
    const Eigen::Index n = x.size();
    const int p = degree + 1;
    const double centre = x.mean();
    const double scale = (x.array() - centre).abs().maxCoeff();
    const Eigen::MatrixXd v = vandermonde(x, degree, centre, scale);

    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(v);
    if (qr.rank() < p)
        throw std::invalid_argument("the x positions are too close together for degree " + std::to_string(degree));
    const Eigen::VectorXd c = qr.solve(y);

    // (V'V)^-1 = P R^-1 R^-T P' from V P = Q R; leverages h_i = |row i of V P R^-1|^2.
    const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(p, p).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd rInverse = r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p, p));
    const Eigen::MatrixXd permutedRInverse = qr.colsPermutation() * rInverse;
    const Eigen::VectorXd leverage = (v * permutedRInverse).rowwise().squaredNorm();

    PolynomialRegression fit;
    fit.polynomial = ScaledPolynomial(c, centre, scale);
    fit.degree = degree;
    fit.pointCount = static_cast<int>(n);
    fit.residualDof = static_cast<int>(n) - p;
    fit.scaledCovarianceFactor = permutedRInverse * permutedRInverse.transpose();

    const Eigen::VectorXd fitted = v * c;
    const Eigen::VectorXd residual = y - fitted;
    const double mean = y.mean();
    fit.residualSumOfSquares = residual.squaredNorm();
    fit.totalSumOfSquares = (y.array() - mean).square().sum();
    const double regressionSumOfSquares = (fitted.array() - mean).square().sum();
    const double dof = static_cast<double>(fit.residualDof);
    fit.r2 = 1.0 - fit.residualSumOfSquares / fit.totalSumOfSquares;
    fit.r2Adjusted = 1.0 - (1.0 - fit.r2) * static_cast<double>(n - 1) / dof;
    fit.fStatistic = fit.residualSumOfSquares > 0.0
                         ? (regressionSumOfSquares / degree) / (fit.residualSumOfSquares / dof)
                         : kInfinity;
    fit.fCritical95 = boost::math::quantile(FisherF(static_cast<double>(degree), dof), 0.95);
    fit.residualSigma = std::sqrt(fit.residualSumOfSquares / dof);

    fit.press = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (leverage(i) >= kLeverageOne) {
            fit.press = kInfinity;
            break;
        }
        fit.press += std::pow(residual(i) / (1.0 - leverage(i)), 2);
    }

    const Eigen::MatrixXd toPower = ScaledPolynomial::scaledToPowerMap(degree, centre, scale);
    fit.coefficients = toPower * c;
    const Eigen::MatrixXd covariance =
        fit.residualSigma * fit.residualSigma * toPower * fit.scaledCovarianceFactor * toPower.transpose();
    fit.coefficientStdErrors = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
    return fit;
}

DegreeSelection fitPolynomialRegressionAutoDegree(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int maxDegree) {
    checkData(x, y);
    if (maxDegree < 1 || maxDegree > kMaxRegressionDegree)
        throw std::invalid_argument("the highest degree to try must be 1 .. " + std::to_string(kMaxRegressionDegree));
    checkDegree(x, 1);  // names the problem when not even a straight line fits

    // PRESS values closer than this are equal: for data lying exactly on a polynomial every
    // higher degree also fits to rounding, and the simplest one must win.
    const double floor = static_cast<double>(x.size()) * std::pow(1e-9 * y.cwiseAbs().maxCoeff(), 2);

    DegreeSelection selection;
    std::optional<PolynomialRegression> best;
    const Eigen::Index distinct = distinctCount(x);
    for (int degree = 1; degree <= maxDegree; ++degree) {
        DegreeCandidate candidate{degree, kInfinity};
        if (x.size() >= degree + 2 && distinct >= degree + 1) {
            try {
                PolynomialRegression fit = fitPolynomialRegression(x, y, degree);
                candidate.press = fit.press;
                if (std::isfinite(fit.press) && (!best || fit.press < best->press - floor)) best = std::move(fit);
            } catch (const std::invalid_argument&) {
                // x too close together for this degree: it stays a candidate with infinite PRESS
            }
        }
        selection.candidates.push_back(candidate);
    }
    if (!best)
        throw std::invalid_argument(
            "leave-one-out cross-validation needs more points at different positions; choose the degree explicitly");
    selection.fit = std::move(*best);
    return selection;
}

}  // namespace tt::core
