#include "core/model/level_crossing.h"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tt::core {

namespace {

/// The ends and the stationary points strictly between them, in the order of travel.
std::vector<double> monotonePieces(const ScaledPolynomial& p, double from, double to) {
    std::vector<double> points = {from};
    const double lo = std::min(from, to);
    const double hi = std::max(from, to);
    std::vector<double> inside;
    for (double x : p.stationaryPoints())
        if (x > lo && x < hi) inside.push_back(x);
    if (to < from) std::reverse(inside.begin(), inside.end());
    points.insert(points.end(), inside.begin(), inside.end());
    points.push_back(to);
    return points;
}

}  // namespace

std::optional<double> firstCrossing(const ScaledPolynomial& p, double level, double from, double to,
                                    CrossingSide side) {
    if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(level))
        throw std::invalid_argument("a crossing needs a finite interval and level");
    const double sign = side == CrossingSide::AtOrBelow ? 1.0 : -1.0;
    // g <= 0 exactly where the polynomial is on the wanted side of the level.
    auto g = [&](double x) { return sign * (p.value(x) - level); };
    const std::vector<double> points = monotonePieces(p, from, to);
    double gStart = g(points.front());
    if (gStart <= 0.0) return points.front();
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double gEnd = g(points[i]);
        if (gEnd <= 0.0) {
            if (gEnd == 0.0) return points[i];
            // g > 0 at the start of this piece, < 0 at its end: a bracketed root.
            const double a = std::min(points[i - 1], points[i]);
            const double b = std::max(points[i - 1], points[i]);
            const double ga = a == points[i - 1] ? gStart : gEnd;
            const double gb = a == points[i - 1] ? gEnd : gStart;
            std::uintmax_t iterations = 200;
            const auto [lo, hi] = boost::math::tools::toms748_solve(
                g, a, b, ga, gb, boost::math::tools::eps_tolerance<double>(52), iterations);
            // The bracket holds the sign change; the earlier of its ends on the way, if it is already on
            // the wanted side, else the later one (which is, by the bracket).
            const double earlier = to > from ? lo : hi;
            const double later = to > from ? hi : lo;
            return g(earlier) <= 0.0 ? earlier : later;
        }
        gStart = gEnd;
    }
    return std::nullopt;
}

}  // namespace tt::core
