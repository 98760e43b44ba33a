#pragma once

#include <complex>
#include <vector>

#include <Eigen/Core>

namespace tt::core {

/// A state-space realisation of a disturbance source driven by scalar or vector white noise:
/// `s(k+1) = A s(k) + G w(k)`, `d(k) = C s(k)`, cov(w) = W.
struct DisturbanceRealisation {
    Eigen::MatrixXd A;
    Eigen::MatrixXd G;
    Eigen::MatrixXd C;  ///< one row: the disturbance of one control point
    Eigen::MatrixXd W;  ///< covariance of w (diagonal)
};

/// A rational shaping filter `W(z) = N(z) / D(z)` that turns white noise into a coloured disturbance
/// (paper 000: "формирующий фильтр", obtained by spectral factorisation). N and D are polynomials in
/// z with coefficients in descending powers; D is monic after normalisation. Construction refuses a
/// denominator root on or outside the unit circle, naming the root: the paper's printed, rounded
/// coefficients z^3 - 2.024 z^2 + 1.08 z - 0.0561 have a root at 1.0029, while its printed roots
/// 0.9969, 0.9692, 0.0580 are stable.
class ShapingFilter {
public:
    /// From numerator coefficients and denominator roots (complex roots must come in conjugate pairs).
    static ShapingFilter fromRoots(const std::vector<double>& numerator,
                                   const std::vector<std::complex<double>>& roots);
    /// From numerator and denominator coefficients (descending powers of z).
    static ShapingFilter fromCoefficients(const std::vector<double>& numerator, const std::vector<double>& denominator);

    /// Numerator coefficients, descending powers, leading zeros removed.
    const std::vector<double>& numerator() const { return m_numerator; }
    /// Monic denominator coefficients, descending powers (first = 1).
    const std::vector<double>& denominator() const { return m_denominator; }
    /// The denominator roots (poles), all strictly inside the unit circle.
    const std::vector<std::complex<double>>& poles() const { return m_poles; }
    /// Order of the denominator (number of poles).
    int order() const { return static_cast<int>(m_denominator.size()) - 1; }

    /// Controllable canonical realisation driven by one white input of variance `inputVariance`.
    /// A biproper filter (deg N = deg D) is realised as z^-1 W(z): the same stationary output
    /// process (the white input is just renumbered), so variances and control performance agree.
    DisturbanceRealisation realise(double inputVariance) const;

    /// Stationary output variance for a unit-variance white input: sum of the squared impulse response.
    double unitInputVariance() const;

    /// Roots of a polynomial given in descending powers (companion-matrix eigenvalues), largest first.
    static std::vector<std::complex<double>> polynomialRoots(const std::vector<double>& coefficients);

private:
    ShapingFilter(std::vector<double> numerator, std::vector<double> denominator,
                  std::vector<std::complex<double>> poles);

    std::vector<double> m_numerator;
    std::vector<double> m_denominator;
    std::vector<std::complex<double>> m_poles;
};

}  // namespace tt::core
