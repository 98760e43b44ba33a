#include "core/common/brent_minimum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {

constexpr double kGolden = 0.3819660112501051;  // (3 − √5) / 2
constexpr double kSqrtEps = 1.4901161193847656e-08;

}  // namespace

ScalarMinimum minimiseBrent(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                            int maxEvaluations) {
    if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi))
        throw std::invalid_argument("the bracket must have its lower end below its upper end");
    if (!(tolerance > 0.0)) throw std::invalid_argument("the tolerance must be above 0");
    if (maxEvaluations < 3) throw std::invalid_argument("at least 3 evaluations are needed");
    double a = lo;
    double b = hi;
    double x = a + kGolden * (b - a);
    double w = x;
    double v = x;
    double fx = f(x);
    double fw = fx;
    double fv = fx;
    int evaluations = 1;
    double d = 0.0;
    double e = 0.0;
    while (evaluations < maxEvaluations) {
        const double m = 0.5 * (a + b);
        const double tol = kSqrtEps * std::abs(x) + tolerance / 3.0;
        const double t2 = 2.0 * tol;
        if (std::abs(x - m) <= t2 - 0.5 * (b - a)) break;
        bool golden = true;
        if (std::abs(e) > tol) {  // try a parabola through x, w, v
            double r = (x - w) * (fx - fv);
            double q = (x - v) * (fx - fw);
            double p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0) p = -p;
            q = std::abs(q);
            r = e;
            e = d;
            if (std::abs(p) < std::abs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
                d = p / q;
                const double u = x + d;
                if (u - a < t2 || b - u < t2) d = x < m ? tol : -tol;
                golden = false;
            }
        }
        if (golden) {
            e = (x < m ? b : a) - x;
            d = kGolden * e;
        }
        const double u = std::abs(d) >= tol ? x + d : x + (d > 0.0 ? tol : -tol);
        const double fu = f(u);
        ++evaluations;
        if (fu <= fx) {
            (u < x ? b : a) = x;
            v = w;
            fv = fw;
            w = x;
            fw = fx;
            x = u;
            fx = fu;
        } else {
            (u < x ? a : b) = u;
            if (fu <= fw || w == x) {
                v = w;
                fv = fw;
                w = u;
                fw = fu;
            } else if (fu <= fv || v == x || v == w) {
                v = u;
                fv = fu;
            }
        }
    }
    return {x, fx, evaluations};
}

ScalarMinimum minimiseOnGrid(const std::function<double(double)>& f, double lo, double hi, int gridPoints,
                             double tolerance, int maxEvaluations) {
    if (gridPoints < 3) throw std::invalid_argument("the grid needs at least 3 points");
    if (!(lo < hi)) throw std::invalid_argument("the bracket must have its lower end below its upper end");
    const double step = (hi - lo) / (gridPoints - 1);
    int best = 0;
    double bestValue = 0.0;
    for (int i = 0; i < gridPoints; ++i) {
        const double value = f(lo + step * i);
        if (i == 0 || value < bestValue) {
            best = i;
            bestValue = value;
        }
    }
    const double a = lo + step * std::max(0, best - 1);
    const double b = lo + step * std::min(gridPoints - 1, best + 1);
    ScalarMinimum refined = minimiseBrent(f, a, b, tolerance, std::max(3, maxEvaluations - gridPoints));
    refined.evaluations += gridPoints;
    if (bestValue < refined.value) return {lo + step * best, bestValue, refined.evaluations};
    return refined;
}

}  // namespace tt::core
