#pragma once

#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// The systematic diameter error of a group of parts along the axis (paper 000, eq. (1) and
/// Table 1): d(x) in mm, x in mm from the left end, on a part of length partLengthMm.
class SystematicErrorModel {
public:
    /// Throws std::invalid_argument when partLengthMm is not a finite positive number.
    SystematicErrorModel(ScaledPolynomial diameterErrorMm, double partLengthMm);

    /// d(x), diameter error, mm.
    double diameterErrorMm(double xMm) const { return m_diameterError.value(xMm); }
    /// Feed-forward radial cutter move y_ff(x) = -d(x)/2, mm.
    double feedForwardMm(double xMm) const { return -0.5 * m_diameterError.value(xMm); }
    /// The polynomial d(x).
    const ScaledPolynomial& diameterError() const { return m_diameterError; }
    /// The polynomial y_ff(x) = -d(x)/2.
    ScaledPolynomial feedForward() const { return m_diameterError.scaledBy(-0.5); }
    /// Length of the part the model covers, mm from the left end.
    double partLengthMm() const { return m_partLengthMm; }
    /// Largest |d(x)| on [0, partLengthMm] (paper 000: about 0.156, 0.104, 0.206 mm near x = 140 mm).
    PolynomialPeak peak() const { return m_diameterError.largestMagnitude(0.0, m_partLengthMm); }

private:
    ScaledPolynomial m_diameterError;
    double m_partLengthMm;
};

}  // namespace tt::core
