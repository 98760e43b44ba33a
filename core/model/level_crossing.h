#pragma once

#include <optional>

#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// Which side of the level a crossing reaches.
enum class CrossingSide {
    AtOrBelow,  ///< the first x where p(x) <= level
    AtOrAbove,  ///< the first x where p(x) >= level
};

/// The first x on the way from `from` to `to` (either order) where the polynomial reaches `level` from
/// the given side: `from` itself when p(from) is already there, otherwise the root of p(x) - level in
/// the first monotone piece (between the real stationary points of p) whose far end is on that side.
/// The root is bracketed by a sign change and found by TOMS 748 (Alefeld, Potra & Shi 1995, a
/// bracketing method of the Brent family, Boost.Math) to a few ulps, so it is never missed between the
/// points of a scan and never leaves the bracket. Empty when p stays on the other side all the way.
/// Throws std::invalid_argument for non-finite ends or level.
std::optional<double> firstCrossing(const ScaledPolynomial& p, double level, double from, double to, CrossingSide side);

}  // namespace tt::core
