#include "core/control/continuous_margins.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

using Complex = std::complex<double>;

constexpr int kGridPerDecade = 400;
constexpr int kBisectionSteps = 60;

Complex evaluate(const std::vector<double>& p, Complex s) {
    Complex v = 0.0;
    for (double c : p)
        v = v * s + c;
    return v;
}

/// Leading zeros removed (a polynomial "0 s^2 + s + 1" is "s + 1").
std::vector<double> trimmed(const std::vector<double>& p) {
    std::size_t first = 0;
    while (first + 1 < p.size() && p[first] == 0.0)
        ++first;
    return {p.begin() + static_cast<std::ptrdiff_t>(first), p.end()};
}

void checkLoop(const RationalTransfer& l, double wMin, double wMax) {
    if (l.numerator.empty() || l.denominator.empty())
        throw std::invalid_argument("margins: the loop's numerator and denominator must not be empty");
    for (const auto* p : {&l.numerator, &l.denominator})
        for (double c : *p)
            if (!std::isfinite(c)) throw std::invalid_argument("margins: the loop's coefficients must be finite");
    const std::vector<double> num = trimmed(l.numerator);
    const std::vector<double> den = trimmed(l.denominator);
    if (den.front() == 0.0) throw std::invalid_argument("margins: the loop's denominator is zero");
    if (num.size() > den.size())
        throw std::invalid_argument("margins: the loop must be proper (numerator degree <= denominator degree)");
    if (!(wMin > 0.0) || !(wMax > wMin) || !std::isfinite(wMax))
        throw std::invalid_argument("margins: the frequency grid must be 0 < w_min < w_max");
}

/// A root of f between a and b, where f(a) and f(b) differ in sign.
template <typename F>
double bisect(F f, double a, double b) {
    const bool negativeAtA = f(a) < 0.0;
    for (int k = 0; k < kBisectionSteps && (b - a) > 1e-12 * b; ++k) {
        const double mid = 0.5 * (a + b);
        ((f(mid) < 0.0) == negativeAtA ? a : b) = mid;
    }
    return 0.5 * (a + b);
}

/// 180 deg + arg L, wrapped to (-180, 180], deg.
double phaseMarginDeg(Complex l) {
    double pm = std::arg(l) * 180.0 / std::numbers::pi + 180.0;
    while (pm > 180.0)
        pm -= 360.0;
    while (pm <= -180.0)
        pm += 360.0;
    return pm;
}

}  // namespace

Complex RationalTransfer::at(double wRadPerS) const {
    const Complex s(0.0, wRadPerS);
    return evaluate(numerator, s) / evaluate(denominator, s);
}

RationalTransfer RationalTransfer::times(const RationalTransfer& other) const {
    return {multiplyPolynomials(numerator, other.numerator), multiplyPolynomials(denominator, other.denominator)};
}

std::vector<double> multiplyPolynomials(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.empty() || b.empty()) return {};
    std::vector<double> out(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            out[i + j] += a[i] * b[j];
    return out;
}

std::vector<Complex> polynomialRoots(const std::vector<double>& coefficients) {
    const std::vector<double> p = trimmed(coefficients);
    if (p.empty() || p.front() == 0.0) throw std::invalid_argument("roots: the polynomial is zero");
    const Eigen::Index n = static_cast<Eigen::Index>(p.size()) - 1;
    if (n == 0) return {};
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index k = 0; k < n; ++k)
        companion(0, k) = -p[static_cast<std::size_t>(k + 1)] / p.front();
    for (Eigen::Index k = 1; k < n; ++k)
        companion(k, k - 1) = 1.0;
    const Eigen::VectorXcd roots = Eigen::EigenSolver<Eigen::MatrixXd>(companion, false).eigenvalues();
    return {roots.data(), roots.data() + roots.size()};
}

std::optional<double> ContinuousMargins::gainMarginDb() const {
    if (!gainMargin) return std::nullopt;
    return 20.0 * std::log10(*gainMargin);
}

ContinuousMargins continuousMargins(const RationalTransfer& loop, double wMinRadPerS, double wMaxRadPerS) {
    checkLoop(loop, wMinRadPerS, wMaxRadPerS);
    ContinuousMargins m;
    const int points = std::max(2, static_cast<int>(kGridPerDecade * std::log10(wMaxRadPerS / wMinRadPerS)) + 1);
    std::vector<double> w(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k)
        w[static_cast<std::size_t>(k)] = wMinRadPerS * std::pow(wMaxRadPerS / wMinRadPerS, double(k) / (points - 1));
    auto magnitudeLessOne = [&](double x) { return std::abs(loop.at(x)) - 1.0; };
    auto imaginary = [&](double x) { return loop.at(x).imag(); };
    for (std::size_t k = 1; k < w.size(); ++k) {
        const Complex a = loop.at(w[k - 1]);
        const Complex b = loop.at(w[k]);
        if ((std::abs(a) < 1.0) != (std::abs(b) < 1.0)) {
            const double wc = bisect(magnitudeLessOne, w[k - 1], w[k]);
            const double pm = phaseMarginDeg(loop.at(wc));
            if (!m.phaseMarginDeg || pm < *m.phaseMarginDeg) {
                m.phaseMarginDeg = pm;
                m.gainCrossoverRadPerS = wc;
            }
            if (pm > 0.0) {
                const double dm = pm * std::numbers::pi / 180.0 / wc;
                if (!m.delayMarginS || dm < *m.delayMarginS) m.delayMarginS = dm;
            }
        }
        if ((a.imag() < 0.0) != (b.imag() < 0.0)) {
            const double wp = bisect(imaginary, w[k - 1], w[k]);
            const Complex at = loop.at(wp);
            if (at.real() < 0.0 && std::abs(at) < 1.0) {
                const double gm = 1.0 / std::abs(at);
                if (!m.gainMargin || gm < *m.gainMargin) {
                    m.gainMargin = gm;
                    m.phaseCrossoverRadPerS = wp;
                }
            }
        }
    }
    std::vector<double> closed = loop.denominator;
    std::vector<double> num = loop.numerator;
    if (num.size() < closed.size()) num.insert(num.begin(), closed.size() - num.size(), 0.0);
    if (closed.size() < num.size()) closed.insert(closed.begin(), num.size() - closed.size(), 0.0);
    for (std::size_t k = 0; k < closed.size(); ++k)
        closed[k] += num[k];
    m.closedLoopPoles = polynomialRoots(closed);
    m.closedLoopStable = !m.closedLoopPoles.empty();
    for (const Complex& p : m.closedLoopPoles)
        if (p.real() >= 0.0) m.closedLoopStable = false;
    return m;
}

}  // namespace tt::core
