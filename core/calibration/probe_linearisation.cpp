#include "core/calibration/probe_linearisation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/model/polynomial_regression.h"

namespace tt::core {

namespace {

constexpr int kMinDegree = 2;
constexpr int kMaxDegree = 4;
// A fit of degree d needs d + 1 coefficients plus at least two residual degrees of freedom.
constexpr int kExtraPoints = 2;

std::string fmt(double v, int precision = 1) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(precision);
    s << v;
    return s.str();
}

std::string pointName(const CalibrationPoint& p, std::size_t index) {
    return p.line > 0 ? "line " + std::to_string(p.line) : "point " + std::to_string(index + 1);
}

double maxCode(int adcBits) {
    return std::ldexp(1.0, adcBits) - 1.0;
}

void checkPoints(const std::vector<CalibrationPoint>& points, int adcBits) {
    if (adcBits < kMinAdcBits || adcBits > kMaxAdcBits)
        throw LinearisationRefused(LinearisationProblem::BadInput,
                                   "ADC resolution " + std::to_string(adcBits) + " bits is outside " +
                                       std::to_string(kMinAdcBits) + " .. " + std::to_string(kMaxAdcBits));
    const double top = maxCode(adcBits);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const CalibrationPoint& p = points[i];
        if (!std::isfinite(p.referenceUm) || !std::isfinite(p.adcCode))
            throw LinearisationRefused(LinearisationProblem::BadInput, pointName(p, i) + ": not a number");
        if (p.adcCode < 0.0 || p.adcCode > top)
            throw LinearisationRefused(LinearisationProblem::OutOfRange,
                                       pointName(p, i) + ": ADC code " + fmt(p.adcCode, 0) + " is outside 0 .. " +
                                           fmt(top, 0) + " of a " + std::to_string(adcBits) + "-bit ADC");
    }
}

int distinctReferences(const std::vector<CalibrationPoint>& points) {
    std::vector<double> refs;
    for (const CalibrationPoint& p : points)
        refs.push_back(p.referenceUm);
    std::sort(refs.begin(), refs.end());
    return static_cast<int>(std::unique(refs.begin(), refs.end()) - refs.begin());
}

bool supports(const std::vector<CalibrationPoint>& points, int degree) {
    return static_cast<int>(points.size()) >= pointsNeeded(degree) &&
           distinctReferences(points) >= referencesNeeded(degree);
}

void checkEnough(const std::vector<CalibrationPoint>& points, int degree) {
    const int needed = pointsNeeded(degree);
    if (static_cast<int>(points.size()) < needed)
        throw LinearisationRefused(LinearisationProblem::TooFewPoints,
                                   "a degree-" + std::to_string(degree) + " characteristic needs at least " +
                                       std::to_string(needed) + " calibration points, got " +
                                       std::to_string(points.size()));
    const int distinct = distinctReferences(points);
    if (distinct < referencesNeeded(degree))
        throw LinearisationRefused(LinearisationProblem::TooFewPoints,
                                   "a degree-" + std::to_string(degree) + " characteristic needs at least " +
                                       std::to_string(referencesNeeded(degree)) +
                                       " different reference deflections, got " + std::to_string(distinct));
    const double first = points.front().adcCode;
    if (std::all_of(points.begin(), points.end(), [first](const CalibrationPoint& p) { return p.adcCode == first; }))
        throw LinearisationRefused(LinearisationProblem::BadInput,
                                   "the ADC code is " + fmt(first, 0) +
                                       " at every point: it does not follow the deflection (probe connected?)");
}

struct Data {
    Eigen::VectorXd referenceUm;
    Eigen::VectorXd code;
};

Data columns(const std::vector<CalibrationPoint>& points) {
    Data d;
    d.referenceUm.resize(static_cast<Eigen::Index>(points.size()));
    d.code.resize(d.referenceUm.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        d.referenceUm(static_cast<Eigen::Index>(i)) = points[i].referenceUm;
        d.code(static_cast<Eigen::Index>(i)) = points[i].adcCode;
    }
    return d;
}

// Leave-one-out residuals e_i / (1 − h_ii), with h_ii = t_iᵀ (TᵀT)⁻¹ t_i in the fit's scaled basis.
Eigen::VectorXd looResiduals(const PolynomialRegression& fit, const Data& d) {
    const ScaledPolynomial& p = fit.polynomial;
    Eigen::VectorXd out(d.code.size());
    for (Eigen::Index i = 0; i < d.code.size(); ++i) {
        const double t = (d.referenceUm(i) - p.centre()) / p.scale();
        Eigen::VectorXd row(fit.degree + 1);
        double power = 1.0;
        for (int k = 0; k <= fit.degree; ++k) {
            row(k) = power;
            power *= t;
        }
        const double leverage = row.dot(fit.scaledCovarianceFactor * row);
        out(i) = (d.code(i) - p(d.referenceUm(i))) / std::max(1.0 - leverage, 1e-9);
    }
    return out;
}

// Codes per µm across the calibrated range, to express code errors in µm.
double meanSlope(const PolynomialRegression& fit, const Data& d) {
    const double lo = d.referenceUm.minCoeff();
    const double hi = d.referenceUm.maxCoeff();
    return std::max(std::abs(fit.polynomial(hi) - fit.polynomial(lo)) / std::max(hi - lo, 1e-12), 1e-12);
}

DegreeScore score(const Data& d, int degree) {
    const PolynomialRegression fit = fitPolynomialRegression(d.referenceUm, d.code, degree);
    const double slope = meanSlope(fit, d);
    const Eigen::ArrayXd squared = looResiduals(fit, d).array().square();
    const double count = static_cast<double>(squared.size());
    const double mse = squared.mean();
    const double variance = (squared - mse).square().sum() / std::max(count - 1.0, 1.0);
    DegreeScore s;
    s.degree = degree;
    s.cvRmsUm = std::sqrt(mse) / slope;
    s.cvStandardErrorUm = std::sqrt(std::sqrt(variance / count)) / slope;
    s.rmsResidualUm = std::sqrt(fit.residualSumOfSquares / count) / slope;
    return s;
}

struct Choice {
    int degree = 0;
    DegreeChoice how = DegreeChoice::LowestError;
    int bestDegree = 0;
    std::string reason;
};

// One-standard-error rule on the mean squared LOO error; a difference smaller than the ADC's own
// resolution (half a code, `halfCodeUm` in µm) is no evidence for a higher degree either.
Choice chooseDegree(const std::vector<DegreeScore>& scores, double halfCodeUm) {
    const auto best = std::min_element(
        scores.begin(), scores.end(), [](const DegreeScore& a, const DegreeScore& b) { return a.cvRmsUm < b.cvRmsUm; });
    const double se2 = best->cvStandardErrorUm * best->cvStandardErrorUm;
    const double quantum2 = halfCodeUm * halfCodeUm;
    const double limit = best->cvRmsUm * best->cvRmsUm + std::max(se2, quantum2);
    for (const DegreeScore& s : scores) {
        if (s.cvRmsUm * s.cvRmsUm > limit) continue;
        std::string reason =
            "degree " + std::to_string(s.degree) + ": leave-one-out error " + fmt(s.cvRmsUm, 2) + " µm";
        DegreeChoice how = DegreeChoice::LowestError;
        if (s.degree == best->degree) {
            reason += ", the lowest of the degrees tried";
        } else {
            how = se2 >= quantum2 ? DegreeChoice::WithinStandardError : DegreeChoice::WithinHalfCode;
            reason += std::string(" is within ") + (se2 >= quantum2 ? "one standard error" : "half an ADC code") +
                      " of the lowest (" + fmt(best->cvRmsUm, 2) + " µm at degree " + std::to_string(best->degree) +
                      "), so the simpler curve is kept";
        }
        return {s.degree, how, best->degree, reason};
    }
    return {best->degree, DegreeChoice::LowestError, best->degree,
            "degree " + std::to_string(best->degree) + " has the lowest leave-one-out error"};
}

// The nearest stationary points left of the calibrated range and right of it.
struct Branch {
    std::optional<double> left;
    std::optional<double> right;
};

Branch branchAround(const CharacteristicFit& fit) {
    Branch b;
    for (double x : fit.characteristic.stationaryPoints()) {
        if (x < fit.calibratedMinUm) b.left = x;
        if (x > fit.calibratedMaxUm && !b.right) b.right = x;
    }
    return b;
}

Monotonicity checkMonotonic(const CharacteristicFit& fit) {
    Monotonicity m;
    const ScaledPolynomial& p = fit.characteristic;
    const double top = maxCode(fit.adcBits);
    m.increasing = p(fit.calibratedMaxUm) >= p(fit.calibratedMinUm);
    auto fail = [&](double x, const std::string& where) {
        m.monotonic = false;
        m.insideCalibratedRange = x >= fit.calibratedMinUm && x <= fit.calibratedMaxUm;
        m.turningDeflectionUm = x;
        m.turningCode = p(x);
        m.message = "the fitted characteristic is not monotonic: it turns at " + fmt(x) + " µm (ADC code " +
                    fmt(p(x), 0) + ") " + where +
                    ", so one code would stand for two deflections; check the points near there or choose "
                    "another degree";
    };
    for (double x : p.stationaryPoints()) {
        if (x >= fit.calibratedMinUm && x <= fit.calibratedMaxUm) {
            fail(x,
                 "inside the calibrated range " + fmt(fit.calibratedMinUm) + " .. " + fmt(fit.calibratedMaxUm) + " µm");
            return m;
        }
    }
    // The monotonic branch holding the points must cover every code 0 .. top: the nearest
    // turning point on each side must lie outside the ADC range.
    const Branch branch = branchAround(fit);
    for (const std::optional<double>& x : {branch.left, branch.right}) {
        if (x && p(*x) >= 0.0 && p(*x) <= top) {
            fail(*x, "within the ADC range 0 .. " + fmt(top, 0) + " (beyond the calibrated range)");
            return m;
        }
    }
    return m;
}

}  // namespace

double CharacteristicFit::codeAt(double deflectionUm) const {
    return characteristic(deflectionUm);
}

double CharacteristicFit::slopeAt(double deflectionUm) const {
    return characteristic.derivative(deflectionUm);
}

CharacteristicFit fitCharacteristic(const std::vector<CalibrationPoint>& points, int adcBits, int degree) {
    checkPoints(points, adcBits);
    if (degree != kAutoDegree && (degree < kMinDegree || degree > kMaxDegree))
        throw LinearisationRefused(LinearisationProblem::BadInput,
                                   "degree " + std::to_string(degree) + " must be 2, 3, 4 or auto");
    checkEnough(points, degree == kAutoDegree ? kMinDegree : degree);
    const Data data = columns(points);

    CharacteristicFit fit;
    fit.adcBits = adcBits;
    fit.calibratedMinUm = data.referenceUm.minCoeff();
    fit.calibratedMaxUm = data.referenceUm.maxCoeff();
    if (degree == kAutoDegree) {
        for (int d = kMinDegree; d <= kMaxDegree; ++d)
            if (supports(points, d)) fit.scores.push_back(score(data, d));
        // Codes per µm over the calibrated range, from the points themselves.
        const double slope = std::abs(data.code.maxCoeff() - data.code.minCoeff()) /
                             std::max(fit.calibratedMaxUm - fit.calibratedMinUm, 1e-9);
        const Choice choice = chooseDegree(fit.scores, 0.5 / std::max(slope, 1e-12));
        fit.degree = choice.degree;
        fit.chosenAutomatically = true;
        fit.choice = choice.how;
        fit.bestDegree = choice.bestDegree;
        fit.choiceReason = choice.reason;
        if (fit.scores.back().degree < kMaxDegree)
            fit.choiceReason += " (only degrees up to " + std::to_string(fit.scores.back().degree) +
                                " could be tried with " + std::to_string(points.size()) + " points)";
    } else {
        fit.scores.push_back(score(data, degree));
        fit.degree = degree;
        fit.bestDegree = degree;
        fit.choiceReason = "degree " + std::to_string(degree) + " as asked";
    }

    const PolynomialRegression chosen = fitPolynomialRegression(data.referenceUm, data.code, fit.degree);
    fit.characteristic = chosen.polynomial;
    fit.coefficients = chosen.coefficients;
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        // The reading the fitted curve gives for this code minus the reference, to first order.
        const double slope = fit.slopeAt(points[i].referenceUm);
        const double codeResidual = points[i].adcCode - fit.codeAt(points[i].referenceUm);
        const double r = std::abs(slope) > 1e-12 ? codeResidual / slope : std::numeric_limits<double>::infinity();
        fit.residualsUm.push_back(r);
        sum += r * r;
    }
    fit.rmsResidualUm = std::sqrt(sum / static_cast<double>(points.size()));
    fit.monotonicity = checkMonotonic(fit);
    return fit;
}

LinearisationTable buildTable(const CharacteristicFit& fit) {
    if (!fit.monotonicity.monotonic)
        throw LinearisationRefused(LinearisationProblem::NonMonotonic, fit.monotonicity.message);
    const ScaledPolynomial& p = fit.characteristic;
    const double top = maxCode(fit.adcBits);
    const bool up = fit.monotonicity.increasing;
    const double lowTarget = up ? 0.0 : top;   // code wanted at the left end of the branch
    const double highTarget = up ? top : 0.0;  // and at its right end
    const Branch branch = branchAround(fit);
    // Walk out from the calibrated range until the branch covers the whole ADC range, never past
    // the branch's own turning points (checkMonotonic made sure they lie beyond the ADC range).
    const double span = std::max(fit.calibratedMaxUm - fit.calibratedMinUm, 1e-6);
    auto expand = [&](double start, double direction, double target, const std::optional<double>& limit) {
        double x = start;
        double step = 0.25 * span;
        for (int i = 0; i < 200; ++i) {
            const bool reached = (direction < 0.0) == up ? p(x) <= target : p(x) >= target;
            if (reached) return x;
            x += direction * step;
            if (limit) x = direction < 0.0 ? std::max(x, *limit) : std::min(x, *limit);
            step *= 2.0;
        }
        throw LinearisationRefused(LinearisationProblem::NonMonotonic,
                                   "the fitted characteristic does not reach the end of the ADC range");
    };
    const double a = expand(fit.calibratedMinUm, -1.0, lowTarget, branch.left);
    const double b = expand(fit.calibratedMaxUm, +1.0, highTarget, branch.right);

    const std::size_t count = static_cast<std::size_t>(top) + 1;
    std::vector<double> um(count);
    double largest = 0.0;
    for (std::size_t c = 0; c < count; ++c) {
        const double target = static_cast<double>(c);
        double lo = a;
        double hi = b;
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            const bool before = up ? p(mid) < target : p(mid) > target;
            (before ? lo : hi) = mid;
        }
        um[c] = 0.5 * (lo + hi);
        largest = std::max(largest, std::abs(um[c]));
    }
    static constexpr std::array<std::uint16_t, 9> kScales = {10, 20, 50, 100, 200, 500, 1000, 2000, 5000};
    LinearisationTable table;
    table.adcBits = fit.adcBits;
    for (std::uint16_t s : kScales) {
        if (largest * 1000.0 / s <= 32767.0) {
            table.scaleNm = s;
            break;
        }
    }
    if (table.scaleNm == 0)
        throw LinearisationRefused(LinearisationProblem::OutOfRange,
                                   "the table would reach " + fmt(largest / 1000.0, 1) +
                                       " mm, beyond what a 16-bit table can hold; calibrate over the whole ADC range");
    table.entries.resize(count);
    for (std::size_t c = 0; c < count; ++c)
        table.entries[c] = static_cast<std::int16_t>(std::lround(um[c] * 1000.0 / table.scaleNm));
    return table;
}

int pointsNeeded(int degree) {
    return degree + 1 + kExtraPoints;
}

int referencesNeeded(int degree) {
    return degree + 2;
}

Linearisation linearise(const std::vector<CalibrationPoint>& points, int adcBits, int degree) {
    return lineariseFit(fitCharacteristic(points, adcBits, degree), points);
}

Linearisation lineariseFit(CharacteristicFit fit, const std::vector<CalibrationPoint>& points) {
    Linearisation result;
    result.fit = std::move(fit);
    result.table = buildTable(result.fit);
    const LinearisationTable& t = result.table;
    for (const CalibrationPoint& p : points) {
        const int code = static_cast<int>(std::lround(p.adcCode));
        const double e = t.deflectionUm(code) - p.referenceUm;
        result.tableErrorsUm.push_back(e);
        result.maxTableErrorUm = std::max(result.maxTableErrorUm, std::abs(e));
    }
    double worstStep = 0.0;
    for (std::size_t c = 0; c < t.entries.size(); ++c) {
        const double um = t.deflectionUm(static_cast<int>(c));
        if (c + 1 < t.entries.size())
            worstStep = std::max(worstStep, std::abs(t.deflectionUm(static_cast<int>(c + 1)) - um));
        if (um < result.fit.calibratedMinUm || um > result.fit.calibratedMaxUm) ++result.extrapolatedEntries;
    }
    result.tableResolutionUm = 0.5 * worstStep + 0.5 * t.scaleNm / 1000.0;
    const double share = static_cast<double>(result.extrapolatedEntries) / static_cast<double>(t.entries.size());
    if (share > kExtrapolatedWarningShare)
        result.warnings.push_back(fmt(100.0 * share, 0) +
                                  " % of the table lies outside the calibrated range and is extrapolated; "
                                  "calibrate over more of the probe's travel");
    return result;
}

}  // namespace tt::core
