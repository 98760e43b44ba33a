#pragma once

#include <Eigen/Core>
#include <vector>

namespace tt::core {

/// Where a polynomial reaches its largest magnitude on an interval.
struct PolynomialPeak {
    double x = 0.0;      ///< position of the largest |p(x)| (same unit as x)
    double value = 0.0;  ///< p(x) there, signed
};

/// A real polynomial stored in a centred, scaled variable so that it stays accurate for x in mm up
/// to metres: p(x) = sum_k c_k t^k with t = (x - centre) / scale. With centre 0 and scale 1 it is the
/// ordinary power form b0 + b1 x + ... + bD x^D (paper 000, Table 1: x in mm from the left end,
/// diameter error in mm).
class ScaledPolynomial {
public:
    /// The zero polynomial (degree 0, value 0 everywhere).
    ScaledPolynomial();
    /// From coefficients c0..cD in t = (x - centre) / scale. Throws std::invalid_argument when the
    /// coefficients are empty or not finite, or scale is not a finite positive number.
    ScaledPolynomial(Eigen::VectorXd scaledCoefficients, double centre, double scale);
    /// From ordinary power-form coefficients b0..bD (b0 first), as printed in Table 1 of paper 000.
    static ScaledPolynomial fromPowerCoefficients(const Eigen::VectorXd& powerCoefficients);

    /// Number of the highest stored coefficient (trailing zeros are kept).
    int degree() const { return static_cast<int>(m_coefficients.size()) - 1; }
    /// p(x), Horner's scheme in the scaled variable.
    double value(double x) const;
    /// Same as value(x).
    double operator()(double x) const { return value(x); }
    /// dp/dx at x.
    double derivative(double x) const;
    /// This polynomial multiplied by a constant (for example -1/2 for the feed-forward path).
    ScaledPolynomial scaledBy(double factor) const;

    /// The ordinary power-form coefficients b0..bD in the original variable x.
    Eigen::VectorXd powerCoefficients() const;
    /// The linear map M with b = M c from scaled coefficients c to power coefficients b, used to
    /// carry covariances over: cov(b) = M cov(c) M'. Size (degree+1) x (degree+1).
    static Eigen::MatrixXd scaledToPowerMap(int degree, double centre, double scale);

    /// Coefficients a_0..a_D in the scaled variable t = (x - centre) / scale.
    const Eigen::VectorXd& scaledCoefficients() const { return m_coefficients; }
    /// Centre of the scaling, in x units.
    double centre() const { return m_centre; }
    /// Scale of the scaling (> 0), in x units.
    double scale() const { return m_scale; }

    /// The real x where dp/dx = 0, ascending: the roots of p' as companion-matrix eigenvalues in
    /// the scaled variable, each polished by two Newton steps. Empty for degree 0 or 1.
    std::vector<double> stationaryPoints() const;
    /// The point of [a, b] where |p(x)| is largest (interior stationary points from the roots of p',
    /// found as companion-matrix eigenvalues, plus both ends). Throws std::invalid_argument unless a <= b.
    PolynomialPeak largestMagnitude(double a, double b) const;

private:
    Eigen::VectorXd m_coefficients;
    double m_centre = 0.0;
    double m_scale = 1.0;
};

}  // namespace tt::core
