#pragma once

#include <string>
#include <vector>

namespace tt::core {

/// How the per-point corrections become a smooth correction along the part (paper 000,
/// "approximation unit").
enum class InterpolationMethod {
    Pchip,          ///< shape-preserving piecewise cubic Hermite (Fritsch-Carlson, as MATLAB pchip); default
    NaturalSpline,  ///< C2 cubic spline with zero second derivative at the first and last point
};

/// "pchip" / "spline".
std::string interpolationMethodName(InterpolationMethod method);
/// Parses "pchip" or "spline" ("natural-spline" also accepted); throws std::invalid_argument otherwise.
InterpolationMethod interpolationMethodFromName(const std::string& name);

/// A piecewise cubic in Hermite form through the knots (x_i, y_i) with slopes d_i.
/// Outside [x_1, x_N] it HOLDS the end values (constant extension; see docs/DECISIONS.md,
/// "Correction path end behaviour"): the cutter never receives an extrapolated correction.
/// One knot gives a constant; two knots give the straight line between them.
class PiecewiseCubic {
public:
    /// y(x); the end value outside [x_1, x_N].
    double value(double x) const;
    /// Same as value(x).
    double operator()(double x) const { return value(x); }
    /// dy/dx (0 outside [x_1, x_N]).
    double derivative(double x) const;

    /// The knot positions x_i, increasing, mm.
    const std::vector<double>& knots() const { return m_x; }
    /// The values y_i at the knots.
    const std::vector<double>& knotValues() const { return m_y; }
    /// The slopes dy/dx at the knots.
    const std::vector<double>& knotSlopes() const { return m_d; }

    /// Shape-preserving PCHIP (Fritsch & Carlson 1980; slopes and end conditions as MATLAB pchip,
    /// Moler, "Numerical Computing with MATLAB", ch. 3.6): monotone data give a monotone curve and
    /// the curve never leaves the range of the data. x strictly increasing, all values finite,
    /// at least one knot; throws std::invalid_argument otherwise.
    static PiecewiseCubic pchip(const std::vector<double>& x, const std::vector<double>& y);
    /// Natural cubic spline (second derivative 0 at both ends). May overshoot between knots.
    /// Same input rules as pchip.
    static PiecewiseCubic naturalSpline(const std::vector<double>& x, const std::vector<double>& y);
    /// pchip or naturalSpline by method.
    static PiecewiseCubic make(InterpolationMethod method, const std::vector<double>& x, const std::vector<double>& y);

private:
    PiecewiseCubic(std::vector<double> x, std::vector<double> y, std::vector<double> d);

    // Interval k as y_k + s (d_k + s (c2 + s c3)), s = x - x_k (cubic Hermite form).
    struct Segment {
        double s = 0.0;
        double c2 = 0.0;
        double c3 = 0.0;
    };
    Segment segment(std::size_t k, double x) const;

    std::vector<double> m_x;
    std::vector<double> m_y;
    std::vector<double> m_d;
};

}  // namespace tt::core
