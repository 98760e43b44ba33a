#pragma once

#include <complex>
#include <optional>
#include <vector>

namespace tt::core {

/// A rational transfer function of the Laplace variable s, num(s) / den(s), coefficients highest power
/// first (the convention of scipy.signal and MATLAB `tf`), in the units of its output per unit of input.
struct RationalTransfer {
    std::vector<double> numerator;
    std::vector<double> denominator;

    /// The value at s = j w, w in rad/s.
    std::complex<double> at(double wRadPerS) const;
    /// The product of two transfer functions (series connection).
    RationalTransfer times(const RationalTransfer& other) const;
};

/// The product of two polynomials, coefficients highest power first.
std::vector<double> multiplyPolynomials(const std::vector<double>& a, const std::vector<double>& b);
/// The roots of a polynomial (coefficients highest power first, leading one non-zero), from the eigenvalues
/// of its companion matrix.
std::vector<std::complex<double>> polynomialRoots(const std::vector<double>& coefficients);

/// Stability margins of a continuous SISO loop L(s) closed with negative feedback (MATLAB `margin`/
/// `allmargin`, the textbook definitions): the gain margin is 1 / |L| where the phase crosses -180 deg,
/// the phase margin is 180 deg + arg L where |L| crosses 1, the delay margin is the phase margin over
/// its crossover frequency. A margin without a crossing is empty (the loop tolerates any such change).
struct ContinuousMargins {
    std::optional<double> gainMargin;                   ///< the loop gain may grow this many times (smallest > 1)
    std::optional<double> phaseCrossoverRadPerS;        ///< where the phase is -180 deg (of that gain margin), rad/s
    std::optional<double> phaseMarginDeg;               ///< smallest over the gain crossovers, deg
    std::optional<double> gainCrossoverRadPerS;         ///< where |L| = 1 (of that phase margin), rad/s
    std::optional<double> delayMarginS;                 ///< extra pure delay the loop tolerates, s
    std::vector<std::complex<double>> closedLoopPoles;  ///< roots of den + num, 1/s
    bool closedLoopStable = false;                      ///< every closed-loop pole in the left half-plane

    /// The gain margin in decibels (20 log10), when there is one.
    std::optional<double> gainMarginDb() const;
};

/// Margins of `loop` from its frequency response on a logarithmic grid from `wMinRadPerS` to
/// `wMaxRadPerS` (crossings refined by bisection to 1e-12 relative), and its closed-loop poles.
/// The loop must be proper (numerator degree <= denominator degree). Throws std::invalid_argument for an
/// empty or non-finite loop or a grid that is not 0 < wMin < wMax.
ContinuousMargins continuousMargins(const RationalTransfer& loop, double wMinRadPerS, double wMaxRadPerS);

}  // namespace tt::core
