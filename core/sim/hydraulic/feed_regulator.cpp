#include "core/sim/hydraulic/feed_regulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tt::core {

namespace {

constexpr double kMinRadPerS = 0.1;
constexpr double kMaxRadPerS = 1.0e6;
constexpr int kGridPerDecade = 400;

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// C(s) = K_p (T_i s + 1)(T_d s + 1) / (T_i s (T_f s + 1)).
RationalTransfer controllerTransfer(double gainS, double ti, double td, double tf) {
    return {multiplyPolynomials({gainS * ti, gainS}, {td, 1.0}), multiplyPolynomials({ti, 0.0}, {tf, 1.0})};
}

/// The frequencies of a log grid over kMinRadPerS .. kMaxRadPerS.
std::vector<double> frequencyGrid() {
    const int points = static_cast<int>(kGridPerDecade * std::log10(kMaxRadPerS / kMinRadPerS)) + 1;
    std::vector<double> w(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k)
        w[static_cast<std::size_t>(k)] = kMinRadPerS * std::pow(kMaxRadPerS / kMinRadPerS, double(k) / (points - 1));
    return w;
}

/// The gain at which the loop's phase (unwrapped from the lowest frequency) first reaches the target margin.
std::optional<double> gainForPhaseMargin(const RationalTransfer& unitLoop, const std::vector<double>& w, double pmDeg) {
    std::complex<double> previous = unitLoop.at(w.front());
    double phaseDeg = std::arg(previous) * 180.0 / std::numbers::pi;
    const double wanted = -180.0 + pmDeg;
    for (std::size_t k = 1; k < w.size(); ++k) {
        const std::complex<double> l = unitLoop.at(w[k]);
        const double step = std::arg(l / previous) * 180.0 / std::numbers::pi;
        if (phaseDeg + step <= wanted) {
            const double f = (phaseDeg - wanted) / (-step);  // the phase interpolated between the grid points
            return 1.0 / std::abs(unitLoop.at(w[k - 1] * std::pow(w[k] / w[k - 1], f)));
        }
        phaseDeg += step;
        previous = l;
    }
    return std::nullopt;
}

/// The smallest gain that puts the loop on -1: 1 / |L| at each crossing of the negative real axis.
std::optional<double> criticalGain(const RationalTransfer& unitLoop, const std::vector<double>& w) {
    std::optional<double> out;
    for (std::size_t k = 1; k < w.size(); ++k) {
        const double a = unitLoop.at(w[k - 1]).imag();
        const double b = unitLoop.at(w[k]).imag();
        if ((a < 0.0) == (b < 0.0)) continue;
        double lo = w[k - 1];
        double hi = w[k];
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            ((unitLoop.at(mid).imag() < 0.0) == (a < 0.0) ? lo : hi) = mid;
        }
        const std::complex<double> l = unitLoop.at(0.5 * (lo + hi));
        if (l.real() < 0.0 && (!out || 1.0 / std::abs(l) < *out)) out = 1.0 / std::abs(l);
    }
    return out;
}

/// The gain K_p for the targets, from the loop with K_p = 1.
double gainForTargets(const RationalTransfer& unitLoop, const FeedFeedbackTargets& t) {
    const std::vector<double> w = frequencyGrid();
    const std::optional<double> forPhase = gainForPhaseMargin(unitLoop, w, t.phaseMarginDeg);
    if (!forPhase) throw std::invalid_argument("feedback design: the loop's phase never reaches the target margin");
    const std::optional<double> critical = criticalGain(unitLoop, w);
    return critical ? std::min(*forPhase, *critical / t.minGainMargin) : *forPhase;
}

}  // namespace

const char* toString(FeedRegulator regulator) {
    switch (regulator) {
        case FeedRegulator::Off:
            return "off";
        case FeedRegulator::FeedForward:
            return "feedforward";
        case FeedRegulator::Feedback:
            return "feedback";
    }
    return "off";
}

FeedRegulator feedRegulatorFromString(const std::string& text) {
    for (FeedRegulator r : {FeedRegulator::Off, FeedRegulator::FeedForward, FeedRegulator::Feedback})
        if (text == toString(r)) return r;
    throw std::invalid_argument("regulator '" + text + "': must be feedforward, feedback or off");
}

RationalTransfer feedPlantTransfer(const HydraulicFeedParams& p) {
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const double tz = p.spoolTimeConstantS;
    const std::vector<double> den = multiplyPolynomials(
        multiplyPolynomials({d.magnetTimeConstantS, 1.0}, {tz * tz, 2.0 * p.spoolDampingRatio * tz, 1.0}),
        {d.cylinderTimeConstantS, 1.0});
    return {{d.slotGainM2PerS * d.cylinderGainPerM2}, den};
}

FeedFeedbackDesign designFeedFeedback(const HydraulicFeedParams& params, const FeedFeedbackTargets& targets) {
    validate(params);
    if (!(targets.phaseMarginDeg > 0.0 && targets.phaseMarginDeg < 90.0) || !(targets.minGainMargin > 1.0) ||
        !(targets.integralRateFactor > 0.0) || !(targets.derivativeFilterRatio > 1.0))
        throw std::invalid_argument("feedback design: phase margin " + number(targets.phaseMarginDeg) +
                                    " deg must be in 0 .. 90, the gain margin > 1, the factors > 0 and > 1");
    const HydraulicFeedDerived d = deriveFeedQuantities(params);
    const double xi = params.spoolDampingRatio;
    const double tz = params.spoolTimeConstantS;
    FeedFeedbackDesign out;
    out.targets = targets;
    out.leadTimeS = xi >= 1.0 ? tz * (xi + std::sqrt(xi * xi - 1.0)) : 2.0 * xi * tz;
    out.integralTimeS = d.cylinderTimeConstantS / targets.integralRateFactor;
    out.filterTimeS = out.leadTimeS / targets.derivativeFilterRatio;
    out.trackingTimeS = std::sqrt(out.integralTimeS * out.leadTimeS);
    out.plant = feedPlantTransfer(params);
    out.gainS = 1.0;
    const RationalTransfer unit =
        controllerTransfer(out.gainS, out.integralTimeS, out.leadTimeS, out.filterTimeS).times(out.plant);
    return scaledFeedback(out, gainForTargets(unit, targets));
}

FeedFeedbackDesign scaledFeedback(const FeedFeedbackDesign& design, double factor) {
    if (!(factor > 0.0) || !std::isfinite(factor))
        throw std::invalid_argument("feedback gain factor " + number(factor) + ": must be > 0");
    FeedFeedbackDesign out = design;
    out.gainS = design.gainS * factor;
    out.controller = controllerTransfer(out.gainS, out.integralTimeS, out.leadTimeS, out.filterTimeS);
    out.loop = out.controller.times(out.plant);
    out.margins = continuousMargins(out.loop, kMinRadPerS, kMaxRadPerS);
    return out;
}

}  // namespace tt::core
