#pragma once

#include <functional>

namespace tt::core {

/// The minimum a bracketed 1-D search found.
struct ScalarMinimum {
    double x = 0.0;       ///< where
    double value = 0.0;   ///< f(x)
    int evaluations = 0;  ///< calls of f
};

/// Minimises f on [lo, hi] by Brent's method (golden-section steps safeguarding successive parabolic
/// interpolation; R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 5,
/// procedure localmin) to an abscissa tolerance of about `tolerance` + 1.5e-8 |x|. Finds a local
/// minimum; with a unimodal f on [lo, hi] the minimum. Throws std::invalid_argument unless
/// lo < hi, tolerance > 0 and maxEvaluations ≥ 3.
ScalarMinimum minimiseBrent(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                            int maxEvaluations = 100);

/// Brackets the global minimum on a grid of `gridPoints` ≥ 3 equally spaced points over [lo, hi] (the
/// best grid point and its neighbours), then refines it by minimiseBrent: the bracketed search the
/// corrective pulse's amplitude is chosen by. The result is never worse than the best grid point.
ScalarMinimum minimiseOnGrid(const std::function<double(double)>& f, double lo, double hi, int gridPoints,
                             double tolerance, int maxEvaluations = 100);

}  // namespace tt::core
