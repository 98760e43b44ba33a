#include "core/control/arma_identification.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "core/model/shaping_filter.h"
#include "core/quality/distributions.h"

namespace tt::core {

namespace {

constexpr int kMaxIterations = 100;
constexpr double kRelativeTolerance = 1e-10;
constexpr double kStableRadius = 0.9999;

/// Roots of z^n + c_1 z^(n-1) + .. + c_n inside kStableRadius.
bool rootsInside(const std::vector<double>& tail) {
    if (tail.empty()) return true;
    std::vector<double> poly{1.0};
    poly.insert(poly.end(), tail.begin(), tail.end());
    for (const std::complex<double>& r : ShapingFilter::polynomialRoots(poly))
        if (std::abs(r) >= kStableRadius) return false;
    return true;
}

}  // namespace

bool armaAdmissible(const Eigen::VectorXd& theta, int p, int q) {
    std::vector<double> ar(static_cast<std::size_t>(p)), ma(static_cast<std::size_t>(q));
    for (int i = 0; i < p; ++i)
        ar[static_cast<std::size_t>(i)] = -theta(i);
    for (int j = 0; j < q; ++j)
        ma[static_cast<std::size_t>(j)] = theta(p + j);
    return theta.allFinite() && rootsInside(ar) && rootsInside(ma);
}

namespace {

/// Conditional residuals e(t) and, when wanted, their Jacobian de/dtheta (rows t, columns a then b).
double residuals(const std::vector<double>& y, const Eigen::VectorXd& theta, int p, int q, Eigen::VectorXd& e,
                 Eigen::MatrixXd* jacobian) {
    const auto n = static_cast<Eigen::Index>(y.size());
    e = Eigen::VectorXd::Zero(n);
    if (jacobian) *jacobian = Eigen::MatrixXd::Zero(n, p + q);
    for (Eigen::Index t = 0; t < n; ++t) {
        double v = y[static_cast<std::size_t>(t)];
        for (int i = 1; i <= p && t - i >= 0; ++i)
            v -= theta(i - 1) * y[static_cast<std::size_t>(t - i)];
        for (int j = 1; j <= q && t - j >= 0; ++j)
            v -= theta(p + j - 1) * e(t - j);
        e(t) = v;
        if (!jacobian) continue;
        for (int c = 0; c < p + q; ++c) {
            double d = 0.0;
            if (c < p && t - c - 1 >= 0) d = -y[static_cast<std::size_t>(t - c - 1)];
            if (c >= p && t - (c - p) - 1 >= 0) d = -e(t - (c - p) - 1);
            for (int j = 1; j <= q && t - j >= 0; ++j)
                d -= theta(p + j - 1) * (*jacobian)(t - j, c);
            (*jacobian)(t, c) = d;
        }
    }
    return e.squaredNorm();
}

}  // namespace

Eigen::VectorXd hannanRissanenStart(const std::vector<double>& y, int p, int q) {
    const auto n = static_cast<Eigen::Index>(y.size());
    Eigen::VectorXd theta = Eigen::VectorXd::Zero(p + q);
    if (p + q == 0) return theta;
    const int longOrder = std::min<int>(static_cast<int>(n / 4), std::max(10, 2 * (p + q) + 5));
    Eigen::VectorXd innovations = Eigen::VectorXd::Zero(n);
    if (q > 0) {
        Eigen::MatrixXd X(n - longOrder, longOrder);
        Eigen::VectorXd Y(n - longOrder);
        for (Eigen::Index t = longOrder; t < n; ++t) {
            Y(t - longOrder) = y[static_cast<std::size_t>(t)];
            for (int i = 1; i <= longOrder; ++i)
                X(t - longOrder, i - 1) = y[static_cast<std::size_t>(t - i)];
        }
        const Eigen::VectorXd phi = X.colPivHouseholderQr().solve(Y);
        innovations.tail(n - longOrder) = Y - X * phi;
    }
    const int start = longOrder + q;
    Eigen::MatrixXd X(n - start, p + q);
    Eigen::VectorXd Y(n - start);
    for (Eigen::Index t = start; t < n; ++t) {
        Y(t - start) = y[static_cast<std::size_t>(t)];
        for (int i = 1; i <= p; ++i)
            X(t - start, i - 1) = y[static_cast<std::size_t>(t - i)];
        for (int j = 1; j <= q; ++j)
            X(t - start, p + j - 1) = innovations(t - j);
    }
    theta = X.colPivHouseholderQr().solve(Y);
    if (!armaAdmissible(theta, p, q)) theta.setZero();
    return theta;
}

double ljungBoxStatistic(const std::vector<double>& residuals, int lags) {
    const std::size_t n = residuals.size();
    if (lags < 1 || static_cast<std::size_t>(lags) >= n) throw std::invalid_argument("Ljung-Box: 1 <= lags < n");
    const double mean = std::accumulate(residuals.begin(), residuals.end(), 0.0) / static_cast<double>(n);
    double c0 = 0.0;
    for (double r : residuals)
        c0 += (r - mean) * (r - mean);
    if (!(c0 > 0.0)) throw std::invalid_argument("Ljung-Box: the residuals are constant");
    double q = 0.0;
    for (int k = 1; k <= lags; ++k) {
        double ck = 0.0;
        for (std::size_t t = static_cast<std::size_t>(k); t < n; ++t)
            ck += (residuals[t] - mean) * (residuals[t - static_cast<std::size_t>(k)] - mean);
        const double r = ck / c0;
        q += r * r / static_cast<double>(n - static_cast<std::size_t>(k));
    }
    return static_cast<double>(n) * (static_cast<double>(n) + 2.0) * q;
}

ArmaFit fitArma(const std::vector<double>& values, ArmaOrders orders) {
    const int p = orders.ar;
    const int q = orders.ma;
    if (p < 0 || p > kMaxArmaOrder || q < 0 || q > kMaxArmaOrder)
        throw std::invalid_argument("the ARMA orders must be 0 .. " + std::to_string(kMaxArmaOrder) + ", got (" +
                                    std::to_string(p) + ", " + std::to_string(q) + ")");
    if (values.size() < kMinArmaValues || values.size() > kMaxArmaValues)
        throw std::invalid_argument("an ARMA fit needs " + std::to_string(kMinArmaValues) + " .. " +
                                    std::to_string(kMaxArmaValues) + " values, got " + std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw std::invalid_argument("value " + std::to_string(i + 1) + " of the series is not a finite number");
    ArmaFit fit;
    fit.values = values.size();
    fit.meanMm = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
    std::vector<double> y(values.size());
    std::transform(values.begin(), values.end(), y.begin(), [&](double v) { return v - fit.meanMm; });
    if (std::all_of(y.begin(), y.end(), [](double v) { return std::abs(v) < 1e-15; }))
        throw std::invalid_argument("the series is constant: there is no disturbance to identify");

    Eigen::VectorXd theta = hannanRissanenStart(y, p, q);
    Eigen::VectorXd e;
    Eigen::MatrixXd J;
    double cost = residuals(y, theta, p, q, e, &J);
    for (int it = 0; it < kMaxIterations && p + q > 0; ++it) {
        fit.iterations = it + 1;
        const Eigen::VectorXd step = -(J.transpose() * J).ldlt().solve(J.transpose() * e);
        double scale = 1.0;
        bool improved = false;
        for (int halving = 0; halving < 30; ++halving, scale *= 0.5) {
            const Eigen::VectorXd trial = theta + scale * step;
            if (!armaAdmissible(trial, p, q)) continue;
            Eigen::VectorXd eTrial;
            const double trialCost = residuals(y, trial, p, q, eTrial, nullptr);
            if (trialCost < cost) {
                const double gain = (cost - trialCost) / cost;
                theta = trial;
                cost = residuals(y, theta, p, q, e, &J);
                improved = gain > kRelativeTolerance;
                break;
            }
        }
        if (!improved) break;
    }
    const auto n = static_cast<double>(y.size());
    fit.noiseVarianceMm2 = cost / (n - p - q);
    const Eigen::MatrixXd cov =
        fit.noiseVarianceMm2 * (J.transpose() * J).ldlt().solve(Eigen::MatrixXd::Identity(p + q, p + q));
    for (int i = 0; i < p; ++i) {
        fit.ar.push_back(theta(i));
        fit.arStdErr.push_back(std::sqrt(std::max(0.0, cov(i, i))));
    }
    for (int j = 0; j < q; ++j) {
        fit.ma.push_back(theta(p + j));
        fit.maStdErr.push_back(std::sqrt(std::max(0.0, cov(p + j, p + j))));
    }
    const std::vector<double> res(e.data(), e.data() + e.size());
    fit.ljungBoxLags = std::min(20, static_cast<int>(y.size() / 5));
    fit.ljungBoxQ = ljungBoxStatistic(res, fit.ljungBoxLags);
    const int dof = std::max(1, fit.ljungBoxLags - p - q);
    fit.ljungBoxP = chiSquareUpperTail(fit.ljungBoxQ, dof);
    return fit;
}

DisturbanceModel ArmaFit::disturbanceModel() const {
    if (ar.empty() && ma.empty()) return DisturbanceModel({DisturbanceComponent::white(noiseVarianceMm2)});
    const std::size_t degree = std::max(ar.size(), ma.size());
    std::vector<double> numerator{1.0};
    numerator.insert(numerator.end(), ma.begin(), ma.end());
    numerator.resize(degree + 1, 0.0);
    std::vector<double> denominator{1.0};
    for (double a : ar)
        denominator.push_back(-a);
    denominator.resize(degree + 1, 0.0);
    return DisturbanceModel({DisturbanceComponent::shapingFilter(
        ShapingFilter::fromCoefficients(numerator, denominator), noiseVarianceMm2)});
}

}  // namespace tt::core
