#include "core/quality/run_rules.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/quality/series.h"

namespace tt::core {

namespace {

using Violations = std::vector<RuleViolation>;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

struct Rule {
    RuleSet set;
    int number;
};

int sign(double v) {
    return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

/// Rules "m of w consecutive points beyond k sigma on one side" (w = 1: one point beyond).
void scanWindow(std::span<const double> z, Rule rule, double k, std::size_t m, std::size_t w, Violations& out) {
    for (const int side : {1, -1}) {
        std::vector<std::size_t> flagged;  // qualifying points within the current window, ascending
        std::size_t open = kNone;          // index in `out` of the violation the next firing may extend
        for (std::size_t i = 0; i < z.size(); ++i) {
            const std::size_t windowStart = i + 1 >= w ? i + 1 - w : 0;
            std::erase_if(flagged, [windowStart](std::size_t p) { return p < windowStart; });
            if (static_cast<double>(side) * z[i] > k) flagged.push_back(i);
            if (flagged.size() < m) continue;
            // Merge with the open violation when they share a point (its last point is still in the window).
            if (open != kNone && out[open].points.back() >= windowStart) {
                std::vector<std::size_t>& points = out[open].points;
                for (const std::size_t p : flagged)
                    if (p > points.back()) points.push_back(p);
                continue;
            }
            open = out.size();
            out.push_back({rule.set, rule.number, side, i, flagged});
        }
    }
}

/// Rules "r points in a row with the same non-zero key" (key: side of the centre, or 1 for a point in the
/// zone the rule looks at); side reported when `reportSide`.
void scanPointRun(const std::vector<int>& key, Rule rule, std::size_t r, bool reportSide, Violations& out) {
    std::size_t start = 0;
    bool open = false;
    for (std::size_t i = 0; i < key.size(); ++i) {
        if (key[i] == 0) {
            open = false;
            continue;
        }
        if (i == 0 || key[i] != key[i - 1]) {
            start = i;
            open = false;
        }
        if (i + 1 - start < r) continue;
        if (open) {
            out.back().points.push_back(i);
            continue;
        }
        RuleViolation v{rule.set, rule.number, reportSide ? key[i] : 0, i, {}};
        for (std::size_t p = start; p <= i; ++p)
            v.points.push_back(p);
        out.push_back(std::move(v));
        open = true;
    }
}

/// Nelson 3 (trend: every step the same direction) and 4 (alternating: every step reverses): r points in a
/// row, i.e. r - 1 consecutive non-zero steps linked by `linked(step, previousStep)`.
template <typename Linked>
void scanStepRun(std::span<const double> x, Rule rule, std::size_t r, bool reportSide, Linked linked, Violations& out) {
    std::size_t start = 0;  // first point of the current run
    bool open = false;
    for (std::size_t i = 1; i < x.size(); ++i) {
        const int step = sign(x[i] - x[i - 1]);
        if (step == 0) {
            start = i;
            open = false;
            continue;
        }
        const int previous = i >= 2 ? sign(x[i - 1] - x[i - 2]) : 0;
        if (!(i - 1 > start && linked(step, previous))) {
            start = i - 1;
            open = false;
        }
        if (i + 1 - start < r) continue;
        if (open) {
            out.back().points.push_back(i);
            continue;
        }
        RuleViolation v{rule.set, rule.number, reportSide ? step : 0, i, {}};
        for (std::size_t p = start; p <= i; ++p)
            v.points.push_back(p);
        out.push_back(std::move(v));
        open = true;
    }
}

std::vector<int> keys(std::span<const double> z, int (*key)(double)) {
    std::vector<int> k(z.size());
    std::transform(z.begin(), z.end(), k.begin(), key);
    return k;
}

int sideOfCentre(double z) {
    return sign(z);
}
int withinOneSigma(double z) {
    return std::abs(z) < 1.0 ? 1 : 0;
}
int beyondOneSigma(double z) {
    return std::abs(z) > 1.0 ? 1 : 0;
}
bool sameDirection(int step, int previous) {
    return step == previous;
}
bool reversed(int step, int previous) {
    return step == -previous;
}

void westernElectric(std::span<const double> z, Violations& out) {
    constexpr RuleSet we = RuleSet::WesternElectric;
    scanWindow(z, {we, 1}, 3.0, 1, 1, out);
    scanWindow(z, {we, 2}, 2.0, 2, 3, out);
    scanWindow(z, {we, 3}, 1.0, 4, 5, out);
    scanPointRun(keys(z, sideOfCentre), {we, 4}, 8, true, out);
}

void nelson(std::span<const double> z, Violations& out) {
    constexpr RuleSet ne = RuleSet::Nelson;
    scanWindow(z, {ne, 1}, 3.0, 1, 1, out);
    scanPointRun(keys(z, sideOfCentre), {ne, 2}, 9, true, out);
    scanStepRun(z, {ne, 3}, 6, true, sameDirection, out);
    scanStepRun(z, {ne, 4}, 14, false, reversed, out);
    scanWindow(z, {ne, 5}, 2.0, 2, 3, out);
    scanWindow(z, {ne, 6}, 1.0, 4, 5, out);
    scanPointRun(keys(z, withinOneSigma), {ne, 7}, 15, false, out);
    scanPointRun(keys(z, beyondOneSigma), {ne, 8}, 8, false, out);
}

}  // namespace

std::string ruleCode(RuleSet set, int rule) {
    const int last = set == RuleSet::WesternElectric ? 4 : 8;
    if (rule < 1 || rule > last)
        throw std::invalid_argument("there is no rule " + std::to_string(rule) + " in the " +
                                    (set == RuleSet::WesternElectric ? "Western Electric" : "Nelson") + " rules");
    return (set == RuleSet::WesternElectric ? "WE" : "N") + std::to_string(rule);
}

std::vector<RuleViolation> findRuleViolations(std::span<const double> pointsMm, double centreMm, double sigmaMm,
                                              RuleSet set) {
    checkValues(pointsMm, 0, "the run rules");
    if (!std::isfinite(centreMm)) throw std::invalid_argument("the run rules need a finite centre line");
    if (!(sigmaMm > 0.0 && std::isfinite(sigmaMm)))
        throw std::invalid_argument("the run rules need a sigma above 0 mm (got " + std::to_string(sigmaMm) + " mm)");
    // Points in units of sigma from the centre line: the zones are at 1, 2 and 3.
    std::vector<double> z(pointsMm.size());
    std::transform(pointsMm.begin(), pointsMm.end(), z.begin(),
                   [centreMm, sigmaMm](double x) { return (x - centreMm) / sigmaMm; });
    Violations violations;
    if (set == RuleSet::WesternElectric)
        westernElectric(z, violations);
    else
        nelson(z, violations);
    std::stable_sort(violations.begin(), violations.end(), [](const RuleViolation& a, const RuleViolation& b) {
        return a.signalPoint != b.signalPoint ? a.signalPoint < b.signalPoint : a.rule < b.rule;
    });
    return violations;
}

}  // namespace tt::core
