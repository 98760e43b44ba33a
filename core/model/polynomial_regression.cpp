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
#include <utility>

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

/// The least-squares core shared by every fit: QR with column pivoting of X, the coefficients,
/// (X'X)^-1, the leverages and the statistics. Empty when X has not full column rank.
std::optional<LinearRegression> solveLeastSquares(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
    const Eigen::Index n = x.rows();
    const auto p = static_cast<int>(x.cols());
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x);
    if (qr.rank() < p) return std::nullopt;
    LinearRegression fit;
    fit.coefficients = qr.solve(y);

    // (X'X)^-1 = P R^-1 R^-T P' from X P = Q R; leverages h_i = |row i of X P R^-1|^2.
    const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(p, p).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd rInverse = r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p, p));
    const Eigen::MatrixXd permutedRInverse = qr.colsPermutation() * rInverse;
    const Eigen::VectorXd leverage = (x * permutedRInverse).rowwise().squaredNorm();

    fit.pointCount = static_cast<int>(n);
    fit.termCount = p;
    fit.residualDof = static_cast<int>(n) - p;
    fit.covarianceFactor = permutedRInverse * permutedRInverse.transpose();

    const Eigen::VectorXd fitted = x * fit.coefficients;
    const Eigen::VectorXd residual = y - fitted;
    const double mean = y.mean();
    fit.residualSumOfSquares = residual.squaredNorm();
    fit.totalSumOfSquares = (y.array() - mean).square().sum();
    const double regressionSumOfSquares = (fitted.array() - mean).square().sum();
    const double dof = static_cast<double>(fit.residualDof);
    const double modelDof = static_cast<double>(p - 1);
    fit.r2 = 1.0 - fit.residualSumOfSquares / fit.totalSumOfSquares;
    fit.r2Adjusted = 1.0 - (1.0 - fit.r2) * static_cast<double>(n - 1) / dof;
    fit.fStatistic = fit.residualSumOfSquares > 0.0
                         ? (regressionSumOfSquares / modelDof) / (fit.residualSumOfSquares / dof)
                         : kInfinity;
    fit.fCritical95 = boost::math::quantile(FisherF(modelDof, dof), 0.95);
    fit.tCritical95 = boost::math::quantile(StudentT(dof), 0.975);
    fit.residualSigma = std::sqrt(fit.residualSumOfSquares / dof);

    fit.press = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (leverage(i) >= kLeverageOne) {
            fit.press = kInfinity;
            break;
        }
        fit.press += std::pow(residual(i) / (1.0 - leverage(i)), 2);
    }

    const double variance = fit.residualSigma * fit.residualSigma;
    fit.coefficientStdErrors = (variance * fit.covarianceFactor.diagonal()).cwiseMax(0.0).cwiseSqrt();
    fit.tValues.resize(p);
    for (int k = 0; k < p; ++k) {
        const double se = fit.coefficientStdErrors(k);
        fit.tValues(k) = se > 0.0 ? fit.coefficients(k) / se : std::copysign(kInfinity, fit.coefficients(k));
    }
    return fit;
}

/// Index of the first column of X that depends linearly on the columns before it.
Eigen::Index firstDependentColumn(const Eigen::MatrixXd& x) {
    for (Eigen::Index k = 1; k < x.cols(); ++k) {
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x.leftCols(k + 1));
        if (qr.rank() < k + 1) return k;
    }
    return x.cols() - 1;
}

void checkDesign(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
    if (x.rows() != y.size())
        throw std::invalid_argument("the regression needs one value per row of terms (" + std::to_string(x.rows()) +
                                    " rows, " + std::to_string(y.size()) + " values)");
    if (x.cols() < 1) throw std::invalid_argument("the regression needs at least the intercept term");
    if (x.rows() < x.cols() + 1)
        throw std::invalid_argument(std::to_string(x.cols()) + " terms need at least " + std::to_string(x.cols() + 1) +
                                    " points (one more than the terms); got " + std::to_string(x.rows()));
    if (!x.allFinite()) throw std::invalid_argument("a term of the regression is not a finite number");
    for (Eigen::Index i = 0; i < y.size(); ++i)
        if (!std::isfinite(y(i)))
            throw std::invalid_argument("value " + std::to_string(i + 1) + " is not a finite number");
    if (!(x.col(0).array() == 1.0).all())
        throw std::invalid_argument("the first term of the regression must be the intercept (all ones)");
    if ((y.array() == y(0)).all())
        throw std::invalid_argument("all values are equal (" + std::to_string(y(0)) + "): there is nothing to fit");
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
    const double centre = x.mean();
    const double scale = (x.array() - centre).abs().maxCoeff();
    const Eigen::MatrixXd v = vandermonde(x, degree, centre, scale);
    std::optional<LinearRegression> solved = solveLeastSquares(v, y);
    if (!solved)
        throw std::invalid_argument("the x positions are too close together for degree " + std::to_string(degree));
    LinearRegression& ls = *solved;

    PolynomialRegression fit;
    fit.polynomial = ScaledPolynomial(ls.coefficients, centre, scale);
    fit.degree = degree;
    fit.pointCount = ls.pointCount;
    fit.residualDof = ls.residualDof;
    fit.scaledCovarianceFactor = std::move(ls.covarianceFactor);
    fit.residualSumOfSquares = ls.residualSumOfSquares;
    fit.totalSumOfSquares = ls.totalSumOfSquares;
    fit.r2 = ls.r2;
    fit.r2Adjusted = ls.r2Adjusted;
    fit.fStatistic = ls.fStatistic;
    fit.fCritical95 = ls.fCritical95;
    fit.residualSigma = ls.residualSigma;
    fit.press = ls.press;

    const Eigen::MatrixXd toPower = ScaledPolynomial::scaledToPowerMap(degree, centre, scale);
    fit.coefficients = toPower * ls.coefficients;
    const Eigen::MatrixXd covariance =
        fit.residualSigma * fit.residualSigma * toPower * fit.scaledCovarianceFactor * toPower.transpose();
    fit.coefficientStdErrors = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
    return fit;
}

namespace {

/// t(0.5 + level / 2; n - p) and row' (X'X)^-1 row, after checking the level and the row's size.
std::pair<double, double> quantileAndLeverage(const LinearRegression& fit, const Eigen::VectorXd& row, double level) {
    if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("the band level must lie strictly between 0 and 1");
    if (row.size() != fit.covarianceFactor.rows())
        throw std::invalid_argument("a prediction needs one value per term (" +
                                    std::to_string(fit.covarianceFactor.rows()) + "), got " +
                                    std::to_string(row.size()));
    const double leverage = std::max(0.0, row.dot(fit.covarianceFactor * row));
    const StudentT student(static_cast<double>(fit.residualDof));
    return {boost::math::quantile(student, 0.5 + 0.5 * level), leverage};
}

}  // namespace

double LinearRegression::predictionHalfWidth(const Eigen::VectorXd& row, double level) const {
    const auto [t, leverage] = quantileAndLeverage(*this, row, level);
    return t * residualSigma * std::sqrt(1.0 + leverage);
}

double LinearRegression::confidenceHalfWidth(const Eigen::VectorXd& row, double level) const {
    const auto [t, leverage] = quantileAndLeverage(*this, row, level);
    return t * residualSigma * std::sqrt(leverage);
}

LinearRegression fitLinearRegression(const Eigen::MatrixXd& design, const Eigen::VectorXd& y) {
    checkDesign(design, y);
    std::optional<LinearRegression> fit = solveLeastSquares(design, y);
    if (!fit) {
        const Eigen::Index column = firstDependentColumn(design);
        throw std::invalid_argument("term " + std::to_string(column + 1) + " of " + std::to_string(design.cols()) +
                                    " is a combination of the terms before it on these data: the points do not "
                                    "separate the terms (add levels or choose fewer terms)");
    }
    return std::move(*fit);
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
