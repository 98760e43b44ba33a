#include "core/model/shaping_filter.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/linalg/dare.h"
#include "core/linalg/stein.h"

namespace tt::core {

namespace {

std::vector<double> trimLeadingZeros(const std::vector<double>& coefficients) {
    auto first = std::find_if(coefficients.begin(), coefficients.end(), [](double c) { return c != 0.0; });
    return {first, coefficients.end()};
}

void requireFinite(const std::vector<double>& values, const char* what) {
    for (double v : values)
        if (!std::isfinite(v))
            throw std::invalid_argument(std::string("shaping filter: the ") + what + " has a NaN or Inf");
}

void requireStable(const std::vector<std::complex<double>>& poles) {
    for (const std::complex<double>& p : poles) {
        if (!std::isfinite(p.real()) || !std::isfinite(p.imag()))
            throw std::invalid_argument("shaping filter: a denominator root is not a finite number");
        if (std::abs(p) >= 1.0)
            throw std::invalid_argument("shaping filter is unstable: the denominator has a root at " + formatMode(p) +
                                        " (|z| = " + formatMode(std::abs(p)) +
                                        " >= 1, on or outside the unit circle); rounded coefficients can do this, "
                                        "so give the filter by its roots");
    }
}

/// Coefficients (descending powers, monic) of prod (z - root).
std::vector<double> polynomialFromRoots(const std::vector<std::complex<double>>& roots) {
    std::vector<std::complex<double>> poly{1.0};
    for (const std::complex<double>& r : roots) {
        std::vector<std::complex<double>> next(poly.size() + 1, 0.0);
        for (std::size_t i = 0; i < poly.size(); ++i) {
            next[i] += poly[i];
            next[i + 1] -= r * poly[i];
        }
        poly = std::move(next);
    }
    std::vector<double> real(poly.size());
    for (std::size_t i = 0; i < poly.size(); ++i) {
        if (std::abs(poly[i].imag()) > 1e-9 * std::max(1.0, std::abs(poly[i])))
            throw std::invalid_argument("shaping filter: complex denominator roots must come in conjugate pairs");
        real[i] = poly[i].real();
    }
    return real;
}

}  // namespace

std::vector<std::complex<double>> ShapingFilter::polynomialRoots(const std::vector<double>& coefficients) {
    const std::vector<double> c = trimLeadingZeros(coefficients);
    if (c.size() <= 1) return {};
    const Eigen::Index n = static_cast<Eigen::Index>(c.size()) - 1;
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index j = 0; j < n; ++j)
        companion(0, j) = -c[static_cast<std::size_t>(j) + 1] / c[0];
    for (Eigen::Index i = 1; i < n; ++i)
        companion(i, i - 1) = 1.0;
    Eigen::EigenSolver<Eigen::MatrixXd> eig(companion, false);
    std::vector<std::complex<double>> roots(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
        roots[static_cast<std::size_t>(i)] = eig.eigenvalues()(i);
    std::sort(roots.begin(), roots.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    return roots;
}

ShapingFilter::ShapingFilter(std::vector<double> numerator, std::vector<double> denominator,
                             std::vector<std::complex<double>> poles)
    : m_numerator(std::move(numerator)), m_denominator(std::move(denominator)), m_poles(std::move(poles)) {
    if (m_numerator.empty()) throw std::invalid_argument("shaping filter: the numerator is zero");
    if (m_denominator.size() < 2)
        throw std::invalid_argument("shaping filter: the denominator needs at least one root");
    if (m_numerator.size() > m_denominator.size())
        throw std::invalid_argument("shaping filter: the numerator degree (" + std::to_string(m_numerator.size() - 1) +
                                    ") exceeds the denominator degree (" + std::to_string(m_denominator.size() - 1) +
                                    "); the filter would need future noise");
}

ShapingFilter ShapingFilter::fromRoots(const std::vector<double>& numerator,
                                       const std::vector<std::complex<double>>& roots) {
    requireFinite(numerator, "numerator");
    requireStable(roots);
    std::vector<std::complex<double>> poles = roots;
    std::sort(poles.begin(), poles.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    return ShapingFilter(trimLeadingZeros(numerator), polynomialFromRoots(roots), std::move(poles));
}

ShapingFilter ShapingFilter::fromCoefficients(const std::vector<double>& numerator,
                                              const std::vector<double>& denominator) {
    requireFinite(numerator, "numerator");
    requireFinite(denominator, "denominator");
    std::vector<double> den = trimLeadingZeros(denominator);
    if (den.size() < 2) throw std::invalid_argument("shaping filter: the denominator needs at least one root");
    const double lead = den.front();
    std::vector<double> num = trimLeadingZeros(numerator);
    for (double& c : den)
        c /= lead;
    for (double& c : num)
        c /= lead;
    std::vector<std::complex<double>> poles = polynomialRoots(den);
    requireStable(poles);
    return ShapingFilter(std::move(num), std::move(den), std::move(poles));
}

DisturbanceRealisation ShapingFilter::realise(double inputVariance) const {
    const Eigen::Index n = order();
    DisturbanceRealisation r;
    const bool biproper = m_numerator.size() == m_denominator.size();
    const Eigen::Index states = biproper ? n + 1 : n;
    // Denominator of the realised filter: D(z) or z D(z).
    std::vector<double> den = m_denominator;
    if (biproper) den.push_back(0.0);
    // Numerator padded on the left to `states` coefficients (degree states - 1).
    std::vector<double> padded(static_cast<std::size_t>(states), 0.0);
    std::copy(m_numerator.begin(), m_numerator.end(), padded.end() - static_cast<std::ptrdiff_t>(m_numerator.size()));
    r.A = Eigen::MatrixXd::Zero(states, states);
    for (Eigen::Index j = 0; j < states; ++j)
        r.A(0, j) = -den[static_cast<std::size_t>(j) + 1];
    for (Eigen::Index i = 1; i < states; ++i)
        r.A(i, i - 1) = 1.0;
    r.G = Eigen::MatrixXd::Zero(states, 1);
    r.G(0, 0) = 1.0;
    r.C = Eigen::MatrixXd(1, states);
    for (Eigen::Index j = 0; j < states; ++j)
        r.C(0, j) = padded[static_cast<std::size_t>(j)];
    r.W = Eigen::MatrixXd::Constant(1, 1, inputVariance);
    return r;
}

double ShapingFilter::unitInputVariance() const {
    const DisturbanceRealisation r = realise(1.0);
    const Eigen::MatrixXd sigma = solveDiscreteLyapunov(r.A, r.G * r.G.transpose());
    return (r.C * sigma * r.C.transpose())(0, 0);
}

}  // namespace tt::core
