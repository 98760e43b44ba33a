#include "core/control/profile_interpolation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace tt::core {

namespace {

void checkKnots(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.empty()) throw std::invalid_argument("interpolation needs at least one point");
    if (x.size() != y.size())
        throw std::invalid_argument("interpolation needs as many values as positions (" + std::to_string(x.size()) +
                                    " positions, " + std::to_string(y.size()) + " values)");
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
            throw std::invalid_argument("interpolation point " + std::to_string(i + 1) + " is not a finite number");
        if (i > 0 && !(x[i] > x[i - 1]))
            throw std::invalid_argument("interpolation positions must be strictly increasing (point " +
                                        std::to_string(i + 1) + " is not after point " + std::to_string(i) + ")");
    }
}

double sign(double v) {
    return static_cast<double>((v > 0.0) - (v < 0.0));
}

/// One-sided three-point end slope of MATLAB pchip ("pchipend"), kept shape-preserving.
double pchipEndSlope(double h1, double h2, double del1, double del2) {
    double d = ((2.0 * h1 + h2) * del1 - h1 * del2) / (h1 + h2);
    if (sign(d) != sign(del1))
        d = 0.0;
    else if (sign(del1) != sign(del2) && std::abs(d) > std::abs(3.0 * del1))
        d = 3.0 * del1;
    return d;
}

}  // namespace

std::string interpolationMethodName(InterpolationMethod method) {
    return method == InterpolationMethod::Pchip ? "pchip" : "spline";
}

InterpolationMethod interpolationMethodFromName(const std::string& name) {
    if (name == "pchip") return InterpolationMethod::Pchip;
    if (name == "spline" || name == "natural-spline") return InterpolationMethod::NaturalSpline;
    throw std::invalid_argument("interpolation method '" + name + "' is not one of pchip, spline");
}

PiecewiseCubic::PiecewiseCubic(std::vector<double> x, std::vector<double> y, std::vector<double> d)
    : m_x(std::move(x)), m_y(std::move(y)), m_d(std::move(d)) {}

PiecewiseCubic PiecewiseCubic::pchip(const std::vector<double>& x, const std::vector<double>& y) {
    checkKnots(x, y);
    const std::size_t n = x.size();
    std::vector<double> d(n, 0.0);
    if (n == 1) return PiecewiseCubic(x, y, d);
    std::vector<double> h(n - 1), del(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        h[k] = x[k + 1] - x[k];
        del[k] = (y[k + 1] - y[k]) / h[k];
    }
    if (n == 2) {  // MATLAB pchip: linear interpolation between two points
        d[0] = d[1] = del[0];
        return PiecewiseCubic(x, y, d);
    }
    // Interior: weighted harmonic mean of the neighbouring secants where they have the same sign,
    // 0 at a local extremum or flat piece (Fritsch-Carlson, Brodlie's weights).
    for (std::size_t k = 1; k + 1 < n; ++k) {
        if (sign(del[k - 1]) * sign(del[k]) > 0.0) {
            const double w1 = 2.0 * h[k] + h[k - 1];
            const double w2 = h[k] + 2.0 * h[k - 1];
            d[k] = (w1 + w2) / (w1 / del[k - 1] + w2 / del[k]);
        }
    }
    d[0] = pchipEndSlope(h[0], h[1], del[0], del[1]);
    d[n - 1] = pchipEndSlope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
    return PiecewiseCubic(x, y, d);
}

PiecewiseCubic PiecewiseCubic::naturalSpline(const std::vector<double>& x, const std::vector<double>& y) {
    checkKnots(x, y);
    const std::size_t n = x.size();
    if (n == 1) return PiecewiseCubic(x, y, {0.0});
    std::vector<double> h(n - 1), del(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        h[k] = x[k + 1] - x[k];
        del[k] = (y[k + 1] - y[k]) / h[k];
    }
    // Slopes from second-derivative continuity, y'' = 0 at both ends: a tridiagonal, strictly
    // diagonally dominant system solved by the Thomas algorithm (no pivoting needed).
    std::vector<double> lower(n, 0.0), diag(n), upper(n, 0.0), rhs(n);
    diag[0] = 2.0;
    upper[0] = 1.0;
    rhs[0] = 3.0 * del[0];
    for (std::size_t i = 1; i + 1 < n; ++i) {
        lower[i] = h[i];
        diag[i] = 2.0 * (h[i - 1] + h[i]);
        upper[i] = h[i - 1];
        rhs[i] = 3.0 * (h[i] * del[i - 1] + h[i - 1] * del[i]);
    }
    lower[n - 1] = 1.0;
    diag[n - 1] = 2.0;
    rhs[n - 1] = 3.0 * del[n - 2];
    for (std::size_t i = 1; i < n; ++i) {
        const double m = lower[i] / diag[i - 1];
        diag[i] -= m * upper[i - 1];
        rhs[i] -= m * rhs[i - 1];
    }
    std::vector<double> d(n);
    d[n - 1] = rhs[n - 1] / diag[n - 1];
    for (std::size_t i = n - 1; i-- > 0;)
        d[i] = (rhs[i] - upper[i] * d[i + 1]) / diag[i];
    return PiecewiseCubic(x, y, d);
}

PiecewiseCubic PiecewiseCubic::make(InterpolationMethod method, const std::vector<double>& x,
                                    const std::vector<double>& y) {
    return method == InterpolationMethod::Pchip ? pchip(x, y) : naturalSpline(x, y);
}

PiecewiseCubic::Segment PiecewiseCubic::segment(std::size_t k, double x) const {
    const double h = m_x[k + 1] - m_x[k];
    const double del = (m_y[k + 1] - m_y[k]) / h;
    return {x - m_x[k], (3.0 * del - 2.0 * m_d[k] - m_d[k + 1]) / h, (m_d[k] - 2.0 * del + m_d[k + 1]) / (h * h)};
}

double PiecewiseCubic::value(double x) const {
    if (m_x.size() == 1 || x <= m_x.front()) return m_y.front();
    if (x >= m_x.back()) return m_y.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(m_x.begin(), m_x.end(), x) - m_x.begin()) - 1;
    const Segment g = segment(k, x);
    return m_y[k] + g.s * (m_d[k] + g.s * (g.c2 + g.s * g.c3));
}

double PiecewiseCubic::derivative(double x) const {
    if (m_x.size() == 1 || x < m_x.front() || x > m_x.back()) return 0.0;
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(m_x.begin(), m_x.end(), x) - m_x.begin()) - 1, m_x.size() - 2);
    const Segment g = segment(k, x);
    return m_d[k] + g.s * (2.0 * g.c2 + 3.0 * g.s * g.c3);
}

}  // namespace tt::core
