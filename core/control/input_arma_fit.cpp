#include "core/control/input_arma_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "core/quality/distributions.h"

namespace tt::core {

namespace {

constexpr int kMaxIterations = 100;
constexpr double kRelativeTolerance = 1e-10;
/// Orders of the long ARX that starts the fit.
constexpr int kLongArxOrder = 10;

/// Where the parameters sit in theta: a_1..a_p, b_1..b_q, g, mu.
struct Layout {
    int p = 0, q = 0;
    int gain() const { return p + q; }
    int mean() const { return p + q + 1; }
    int size() const { return p + q + 2; }
};

/// Conditional residuals e(t) of the model and, when wanted, their Jacobian de/dtheta. Returns sum e^2.
double residuals(const std::vector<double>& y, const std::vector<double>& u, const Eigen::VectorXd& theta,
                 const Layout& l, Eigen::VectorXd& e, Eigen::MatrixXd* jacobian) {
    const auto n = static_cast<Eigen::Index>(y.size());
    const double g = theta(l.gain());
    const double mu = theta(l.mean());
    Eigen::VectorXd w(n);
    for (Eigen::Index t = 0; t < n; ++t)
        w(t) = y[static_cast<std::size_t>(t)] - g * u[static_cast<std::size_t>(t)] - mu;
    e = Eigen::VectorXd::Zero(n);
    if (jacobian) *jacobian = Eigen::MatrixXd::Zero(n, l.size());
    for (Eigen::Index t = 0; t < n; ++t) {
        double v = w(t);
        for (int i = 1; i <= l.p && t - i >= 0; ++i)
            v -= theta(i - 1) * w(t - i);
        for (int j = 1; j <= l.q && t - j >= 0; ++j)
            v -= theta(l.p + j - 1) * e(t - j);
        e(t) = v;
        if (!jacobian) continue;
        Eigen::MatrixXd& J = *jacobian;
        for (int i = 1; i <= l.p; ++i)
            J(t, i - 1) = t - i >= 0 ? -w(t - i) : 0.0;
        for (int j = 1; j <= l.q; ++j)
            J(t, l.p + j - 1) = t - j >= 0 ? -e(t - j) : 0.0;
        double dg = -u[static_cast<std::size_t>(t)];
        double dmu = -1.0;
        for (int i = 1; i <= l.p && t - i >= 0; ++i) {
            dg += theta(i - 1) * u[static_cast<std::size_t>(t - i)];
            dmu += theta(i - 1);
        }
        J(t, l.gain()) = dg;
        J(t, l.mean()) = dmu;
        for (int j = 1; j <= l.q && t - j >= 0; ++j)
            J.row(t) -= theta(l.p + j - 1) * J.row(t - j);
    }
    return e.squaredNorm();
}

/// The gain of a long ARX y(t) = c + g u(t) + sum alpha_i y(t-i) + sum beta_i u(t-i) by least squares.
double longArxGain(const std::vector<double>& y, const std::vector<double>& u) {
    const auto n = static_cast<Eigen::Index>(y.size());
    const int na = std::min<int>(kLongArxOrder, static_cast<int>(n / 10));
    const Eigen::Index rows = n - na;
    Eigen::MatrixXd X(rows, 2 + 2 * na);
    Eigen::VectorXd Y(rows);
    for (Eigen::Index t = na; t < n; ++t) {
        const Eigen::Index r = t - na;
        Y(r) = y[static_cast<std::size_t>(t)];
        X(r, 0) = 1.0;
        X(r, 1) = u[static_cast<std::size_t>(t)];
        for (int i = 1; i <= na; ++i) {
            X(r, 1 + i) = y[static_cast<std::size_t>(t - i)];
            X(r, 1 + na + i) = u[static_cast<std::size_t>(t - i)];
        }
    }
    return X.colPivHouseholderQr().solve(Y)(1);
}

/// The start for a given gain: the mean of y - g u and Hannan-Rissanen on the rest.
Eigen::VectorXd startFrom(const std::vector<double>& y, const std::vector<double>& u, double gain, const Layout& l) {
    std::vector<double> w(y.size());
    for (std::size_t t = 0; t < y.size(); ++t)
        w[t] = y[t] - gain * u[t];
    const double mean = std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(w.size());
    for (double& v : w)
        v -= mean;
    Eigen::VectorXd theta(l.size());
    theta.head(l.p + l.q) = hannanRissanenStart(w, l.p, l.q);
    theta(l.gain()) = gain;
    theta(l.mean()) = mean;
    return theta;
}

/// Gauss-Newton with step halving from `theta`; returns the final cost, theta, e and J updated.
double gaussNewton(const std::vector<double>& y, const std::vector<double>& u, const Layout& l, Eigen::VectorXd& theta,
                   Eigen::VectorXd& e, Eigen::MatrixXd& J, int& iterations) {
    double cost = residuals(y, u, theta, l, e, &J);
    for (int it = 0; it < kMaxIterations; ++it) {
        iterations = it + 1;
        const Eigen::VectorXd step = -(J.transpose() * J).ldlt().solve(J.transpose() * e);
        if (!step.allFinite()) break;
        double scale = 1.0;
        bool improved = false;
        for (int halving = 0; halving < 30; ++halving, scale *= 0.5) {
            const Eigen::VectorXd trial = theta + scale * step;
            if (!armaAdmissible(trial.head(l.p + l.q), l.p, l.q) || !trial.allFinite()) continue;
            Eigen::VectorXd eTrial;
            const double trialCost = residuals(y, u, trial, l, eTrial, nullptr);
            if (trialCost < cost) {
                const double gain = (cost - trialCost) / cost;
                theta = trial;
                cost = residuals(y, u, theta, l, e, &J);
                improved = gain > kRelativeTolerance;
                break;
            }
        }
        if (!improved) break;
    }
    return cost;
}

void checkInput(const std::vector<double>& y, const std::vector<double>& u, ArmaOrders orders, int skip) {
    if (orders.ar < 0 || orders.ar > kMaxArmaOrder || orders.ma < 0 || orders.ma > kMaxArmaOrder)
        throw std::invalid_argument("the ARMA orders must be 0 .. " + std::to_string(kMaxArmaOrder) + ", got (" +
                                    std::to_string(orders.ar) + ", " + std::to_string(orders.ma) + ")");
    if (y.size() != u.size())
        throw std::invalid_argument("the output has " + std::to_string(y.size()) + " values, the input " +
                                    std::to_string(u.size()));
    if (skip < 0 || y.size() < kMinInputArmaValues + static_cast<std::size_t>(skip))
        throw std::invalid_argument("a fit of a gain with ARMA noise needs " + std::to_string(kMinInputArmaValues) +
                                    " values after the first " + std::to_string(std::max(skip, 0)) + ", got " +
                                    std::to_string(y.size()));
    for (std::size_t i = 0; i < y.size(); ++i)
        if (!std::isfinite(y[i]) || !std::isfinite(u[i]))
            throw std::invalid_argument("value " + std::to_string(i + 1) + " of the series is not a finite number");
    const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
    if (*hi - *lo <= 1e-12 * std::max(1.0, std::abs(*hi)))
        throw std::invalid_argument("the input never changes: its gain cannot be told from the output");
}

}  // namespace

InputArmaFit fitInputArma(const std::vector<double>& y, const std::vector<double>& u, ArmaOrders orders,
                          std::optional<double> priorGain, int skip) {
    checkInput(y, u, orders, skip);
    const Layout l{orders.ar, orders.ma};
    Eigen::VectorXd theta = startFrom(y, u, longArxGain(y, u), l);
    Eigen::VectorXd e;
    Eigen::MatrixXd J;
    int iterations = 0;
    double cost = gaussNewton(y, u, l, theta, e, J, iterations);
    if (priorGain && std::isfinite(*priorGain)) {
        Eigen::VectorXd other = startFrom(y, u, *priorGain, l);
        Eigen::VectorXd eOther;
        Eigen::MatrixXd JOther;
        int itOther = 0;
        const double otherCost = gaussNewton(y, u, l, other, eOther, JOther, itOther);
        if (otherCost < cost) {
            cost = otherCost;
            theta = other;
            e = eOther;
            J = JOther;
            iterations = itOther;
        }
    }
    InputArmaFit fit =
        evaluateInputArma(y, u, theta(l.gain()), theta(l.mean()), std::vector<double>(theta.data(), theta.data() + l.p),
                          std::vector<double>(theta.data() + l.p, theta.data() + l.p + l.q), skip);
    fit.noise.iterations = iterations;
    return fit;
}

InputArmaFit evaluateInputArma(const std::vector<double>& y, const std::vector<double>& u, double gain, double meanMm,
                               const std::vector<double>& ar, const std::vector<double>& ma, int skip,
                               bool noiseFixed) {
    const ArmaOrders orders{static_cast<int>(ar.size()), static_cast<int>(ma.size())};
    checkInput(y, u, orders, skip);
    const Layout l{orders.ar, orders.ma};
    Eigen::VectorXd theta(l.size());
    for (int i = 0; i < l.p; ++i)
        theta(i) = ar[static_cast<std::size_t>(i)];
    for (int j = 0; j < l.q; ++j)
        theta(l.p + j) = ma[static_cast<std::size_t>(j)];
    theta(l.gain()) = gain;
    theta(l.mean()) = meanMm;
    Eigen::VectorXd e;
    Eigen::MatrixXd J;
    const double cost = residuals(y, u, theta, l, e, &J);
    const auto n = static_cast<double>(y.size());
    InputArmaFit fit;
    const int free = noiseFixed ? 2 : l.size();  // the gain and the mean are the last two columns of J
    fit.parameters = free;
    fit.gain = gain;
    fit.meanMm = meanMm;
    ArmaFit& noise = fit.noise;
    noise.values = y.size();
    noise.meanMm = meanMm;
    noise.noiseVarianceMm2 = cost / (n - free);
    const Eigen::MatrixXd Jf = J.rightCols(free);
    const Eigen::MatrixXd cov =
        noise.noiseVarianceMm2 * (Jf.transpose() * Jf).ldlt().solve(Eigen::MatrixXd::Identity(free, free));
    auto stdErr = [&](int i) {
        const double v = cov(i, i);
        return std::isfinite(v) ? std::sqrt(std::max(0.0, v)) : std::numeric_limits<double>::infinity();
    };
    const int offset = l.size() - free;  // where the free parameters start in theta
    for (int i = 0; i < l.p; ++i) {
        noise.ar.push_back(theta(i));
        if (!noiseFixed) noise.arStdErr.push_back(stdErr(i));
    }
    for (int j = 0; j < l.q; ++j) {
        noise.ma.push_back(theta(l.p + j));
        if (!noiseFixed) noise.maStdErr.push_back(stdErr(l.p + j));
    }
    fit.gainStdErr = stdErr(l.gain() - offset);
    fit.meanStdErr = stdErr(l.mean() - offset);
    fit.gainStdErrJoint = fit.gainStdErr;
    if (noiseFixed) {
        const Eigen::MatrixXd joint =
            noise.noiseVarianceMm2 * (J.transpose() * J).ldlt().solve(Eigen::MatrixXd::Identity(l.size(), l.size()));
        const double v = joint(l.gain(), l.gain());
        fit.gainStdErrJoint = std::isfinite(v) ? std::sqrt(std::max(0.0, v)) : std::numeric_limits<double>::infinity();
    }
    fit.residuals.assign(e.data(), e.data() + e.size());
    const std::vector<double> used(fit.residuals.begin() + skip, fit.residuals.end());
    const double sum = std::inner_product(used.begin(), used.end(), used.begin(), 0.0);
    const auto m = static_cast<double>(used.size());
    fit.logLikelihoodTerm = m * std::log(std::max(sum, 1e-300) / m);
    noise.ljungBoxLags = std::min(20, static_cast<int>(used.size() / 5));
    noise.ljungBoxQ = sum > 0.0 ? ljungBoxStatistic(used, noise.ljungBoxLags) : 0.0;
    noise.ljungBoxP =
        chiSquareUpperTail(noise.ljungBoxQ, std::max(1, noise.ljungBoxLags - (noiseFixed ? 0 : l.p + l.q)));
    return fit;
}

}  // namespace tt::core
