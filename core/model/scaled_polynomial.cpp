#include "core/model/scaled_polynomial.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace tt::core {

namespace {

bool allFinite(const Eigen::VectorXd& v) {
    return v.allFinite();
}

/// Binomial coefficient C(n, k) as a double (n <= 64 in practice: degree <= 6 here).
double binomial(int n, int k) {
    double result = 1.0;
    for (int i = 1; i <= k; ++i)
        result = result * (n - k + i) / i;
    return result;
}

/// Horner in the scaled variable.
double horner(const Eigen::VectorXd& c, double t) {
    double sum = 0.0;
    for (Eigen::Index k = c.size() - 1; k >= 0; --k)
        sum = sum * t + c(k);
    return sum;
}

/// Derivative coefficients in t: d/dt sum c_k t^k = sum k c_k t^(k-1).
Eigen::VectorXd derivativeCoefficients(const Eigen::VectorXd& c) {
    if (c.size() <= 1) return Eigen::VectorXd::Zero(1);
    Eigen::VectorXd d(c.size() - 1);
    for (Eigen::Index k = 1; k < c.size(); ++k)
        d(k - 1) = static_cast<double>(k) * c(k);
    return d;
}

/// Real roots of sum c_k t^k (eigenvalues of the companion matrix; leading zeros dropped).
std::vector<double> realRoots(const Eigen::VectorXd& c) {
    Eigen::Index n = c.size() - 1;
    const double size = c.cwiseAbs().maxCoeff();
    while (n > 0 && std::abs(c(n)) <= 1e-14 * size)
        --n;
    std::vector<double> roots;
    if (n <= 0) return roots;
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 1; i < n; ++i)
        companion(i, i - 1) = 1.0;
    for (Eigen::Index i = 0; i < n; ++i)
        companion(i, n - 1) = -c(i) / c(n);
    const Eigen::VectorXcd eig = Eigen::EigenSolver<Eigen::MatrixXd>(companion, false).eigenvalues();
    for (Eigen::Index i = 0; i < eig.size(); ++i)
        if (std::abs(eig(i).imag()) <= 1e-7 * (1.0 + std::abs(eig(i).real()))) roots.push_back(eig(i).real());
    return roots;
}

}  // namespace

ScaledPolynomial::ScaledPolynomial() : m_coefficients(Eigen::VectorXd::Zero(1)) {}

ScaledPolynomial::ScaledPolynomial(Eigen::VectorXd scaledCoefficients, double centre, double scale)
    : m_coefficients(std::move(scaledCoefficients)), m_centre(centre), m_scale(scale) {
    if (m_coefficients.size() == 0) throw std::invalid_argument("a polynomial needs at least one coefficient");
    if (!allFinite(m_coefficients)) throw std::invalid_argument("polynomial coefficients must be finite numbers");
    if (!std::isfinite(centre) || !std::isfinite(scale) || scale <= 0.0)
        throw std::invalid_argument("polynomial scale must be a finite positive number and the centre finite");
}

ScaledPolynomial ScaledPolynomial::fromPowerCoefficients(const Eigen::VectorXd& powerCoefficients) {
    return ScaledPolynomial(powerCoefficients, 0.0, 1.0);
}

double ScaledPolynomial::value(double x) const {
    return horner(m_coefficients, (x - m_centre) / m_scale);
}

double ScaledPolynomial::derivative(double x) const {
    return horner(derivativeCoefficients(m_coefficients), (x - m_centre) / m_scale) / m_scale;
}

ScaledPolynomial ScaledPolynomial::scaledBy(double factor) const {
    return ScaledPolynomial(m_coefficients * factor, m_centre, m_scale);
}

Eigen::MatrixXd ScaledPolynomial::scaledToPowerMap(int degree, double centre, double scale) {
    // c_k ((x - m)/s)^k = c_k s^-k sum_j C(k, j) x^j (-m)^(k-j)  =>  M(j, k) = C(k, j) (-m)^(k-j) / s^k.
    const int p = degree + 1;
    Eigen::MatrixXd map = Eigen::MatrixXd::Zero(p, p);
    for (int k = 0; k < p; ++k)
        for (int j = 0; j <= k; ++j)
            map(j, k) = binomial(k, j) * std::pow(-centre, k - j) / std::pow(scale, k);
    return map;
}

Eigen::VectorXd ScaledPolynomial::powerCoefficients() const {
    return scaledToPowerMap(degree(), m_centre, m_scale) * m_coefficients;
}

std::vector<double> ScaledPolynomial::stationaryPoints() const {
    std::vector<double> points;
    const Eigen::VectorXd dc = derivativeCoefficients(m_coefficients);
    if (dc.cwiseAbs().maxCoeff() == 0.0) return points;
    const Eigen::VectorXd ddc = derivativeCoefficients(dc);
    for (double t : realRoots(dc)) {
        // Two Newton steps polish the eigenvalue to full precision.
        for (int i = 0; i < 2; ++i) {
            const double slope = horner(ddc, t);
            if (slope == 0.0) break;
            t -= horner(dc, t) / slope;
        }
        points.push_back(m_centre + m_scale * t);
    }
    std::sort(points.begin(), points.end());
    return points;
}

PolynomialPeak ScaledPolynomial::largestMagnitude(double a, double b) const {
    if (!std::isfinite(a) || !std::isfinite(b) || a > b)
        throw std::invalid_argument("the interval for the peak must be finite with its start <= its end");
    std::vector<double> candidates = {a, b};
    for (double x : stationaryPoints())
        if (x > a && x < b) candidates.push_back(x);
    PolynomialPeak best{a, value(a)};
    for (double x : candidates) {
        const double v = value(x);
        if (std::abs(v) > std::abs(best.value)) best = {x, v};
    }
    return best;
}

}  // namespace tt::core
