#pragma once

#include <optional>
#include <vector>

#include "core/control/profile_interpolation.h"
#include "core/model/scaled_polynomial.h"
#include "core/ports/correction_output.h"

namespace tt::core {

/// What the approximation unit needs to turn per-point corrections into the cutter path for one
/// part (paper 000: y_set(x) = y_ff(x) + y(x)).
struct CorrectionPathRequest {
    /// Control point positions along the part, mm from the left end, strictly increasing, inside
    /// [0, partLengthMm]. May be empty: then only the feed-forward is applied.
    std::vector<double> pointZMm;
    /// Radial cutter corrections u_1..u_N at those points, mm (same length as pointZMm).
    std::vector<double> pointCorrectionMm;
    /// How y(x) is drawn through the points; outside [z_1, z_N] the end corrections are held.
    InterpolationMethod method = InterpolationMethod::Pchip;
    /// Systematic DIAMETER error model d(z), mm, z in mm (Table 1 of paper 000). When given, the
    /// feed-forward y_ff(z) = -d(z)/2 is added (a diameter error d needs a radial move of -d/2).
    std::optional<ScaledPolynomial> diameterErrorModel;
    /// Part length, mm (> 0): the path is sampled on [0, partLengthMm].
    double partLengthMm = 0.0;
    /// Sampling step along z, mm (> 0); the last sample is always exactly partLengthMm.
    double stepMm = 0.5;
};

/// The correction as a function of z: y_set(z) = y_ff(z) + y(z), for evaluation at any position
/// (the simulator, plots). Built and checked once; throws std::invalid_argument on bad input
/// (NaN, unsorted or duplicate points, points outside the part, size mismatch, bad length/step).
class CorrectionProfile {
public:
    /// Checks the request (throws std::invalid_argument naming the problem) and prepares the interpolant.
    explicit CorrectionProfile(const CorrectionPathRequest& request);

    /// Total radial correction y_set(z), mm.
    double correctionMm(double zMm) const { return feedForwardMm(zMm) + pointCorrectionPartMm(zMm); }
    /// Feed-forward part y_ff(z) = -d(z)/2, mm (0 without a model).
    double feedForwardMm(double zMm) const;
    /// Interpolated per-point correction y(z), mm (0 without points).
    double pointCorrectionPartMm(double zMm) const;

private:
    std::optional<PiecewiseCubic> m_interpolant;
    std::optional<ScaledPolynomial> m_feedForward;
};

/// Samples y_set(z) on 0, step, 2 step, ..., partLengthMm into the X(z) path for the CNC.
/// At most 1 000 000 samples. Throws std::invalid_argument on bad input (see CorrectionProfile).
CorrectionPath buildCorrectionPath(const CorrectionPathRequest& request);

}  // namespace tt::core
