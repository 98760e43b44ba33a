#include "core/sim/hydraulic/feed_study.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

constexpr double kOscillationPct = 0.05;  ///< an opening overshoot below this is numerical, not a swing
constexpr int kMaxSweepValues = 50;

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

double& sweptParameter(HydraulicFeedParams& p, FeedSweepKind kind) {
    return kind == FeedSweepKind::DampingRatio ? p.spoolDampingRatio : p.amplifierGain;
}

const FeedParameterInfo& sweptInfo(FeedSweepKind kind) {
    return feedParameter(kind == FeedSweepKind::DampingRatio ? "spool.damping_ratio" : "amplifier.gain");
}

/// The load a design gain is computed for: the final load, else the largest.
double designLoad(const FeedScenario& s) {
    const double final = s.finalLoadN();
    return final > 0.0 ? final : s.load.maxForceN();
}

/// Whether the chain regulates at these parameters: its steady state under the load is stable, and the
/// gain is below the stability boundary (beyond it the only steady state left is the fully open slot,
/// which the linearisation alone would call stable).
bool stableAt(const HydraulicFeedParams& p, double loadN, const FeedLinearisation& lin) {
    if (!lin.stable()) return false;
    if (!(loadN > 0.0)) return true;
    try {
        const FeedStability st = analyseStability(p, loadN);
        return !st.gainLimit || p.amplifierGain < *st.gainLimit;
    } catch (const std::invalid_argument&) {
        return true;  // the slot cannot make up this load at any gain: no design point, the eigenvalues decide
    }
}

}  // namespace

FeedRun runFeedScenario(const FeedScenario& scenario, bool regulatorOn, const FeedCancelled& cancelled) {
    return simulateFeed(HydraulicFeedModel(scenario.params, regulatorOn), scenario.load, scenario.run, cancelled);
}

FeedRun runFeedScenario(const FeedScenario& scenario, FeedRegulator regulator, const FeedCancelled& cancelled) {
    return simulateFeed(HydraulicFeedModel(scenario.params, regulator), scenario.load, scenario.run, cancelled);
}

const char* toString(FeedSweepKind kind) {
    return kind == FeedSweepKind::DampingRatio ? "xi" : "gain";
}

FeedSweepKind feedSweepKindFromString(const std::string& text) {
    if (text == "xi") return FeedSweepKind::DampingRatio;
    if (text == "gain") return FeedSweepKind::AmplifierGain;
    throw std::invalid_argument("sweep '" + text + "': must be xi or gain");
}

std::vector<double> defaultSweepValues(FeedSweepKind kind, const FeedScenario& scenario, FeedRegulator regulator) {
    if (kind == FeedSweepKind::DampingRatio) return {0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.5, 2.0};
    if (regulator == FeedRegulator::Feedback) return {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0};
    const double load = designLoad(scenario);
    const double design = load > 0.0 ? designAmplifierGain(scenario.params, load) : scenario.params.amplifierGain;
    std::vector<double> out;
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0})
        out.push_back(f * design);
    return out;
}

std::vector<FeedSweepPoint> sweepFeed(const FeedScenario& scenario, FeedSweepKind kind,
                                      const std::vector<double>& values, FeedRegulator regulator,
                                      const FeedProgress& progress, const FeedCancelled& cancelled) {
    if (regulator == FeedRegulator::Off)
        throw std::invalid_argument(
            "a sweep of xi or of the gain needs a regulator (feedforward or feedback), not off");
    if (values.empty() || values.size() > kMaxSweepValues)
        throw std::invalid_argument("a sweep takes 1 .. 50 values, not " + number(static_cast<double>(values.size())));
    const bool gainFactor = regulator == FeedRegulator::Feedback && kind == FeedSweepKind::AmplifierGain;
    const FeedParameterInfo& info = sweptInfo(kind);
    for (double v : values) {
        const double lo = gainFactor ? 0.01 : info.minValue;
        const double hi = gainFactor ? 100.0 : info.maxValue;
        if (!std::isfinite(v) || v < lo || v > hi)
            throw std::invalid_argument(std::string(gainFactor ? "feedback gain factor" : info.name) + " = " +
                                        number(v) + " in the sweep is outside " + number(lo) + " .. " + number(hi));
    }
    const double load = scenario.finalLoadN();
    std::vector<FeedSweepPoint> out;
    for (double v : values) {
        FeedScenario s = scenario;
        if (!gainFactor) sweptParameter(s.params, kind) = v;
        FeedSweepPoint point;
        point.value = v;
        if (regulator == FeedRegulator::Feedback) {
            point.feedback = designFeedFeedback(s.params);
            if (gainFactor) point.feedback = scaledFeedback(*point.feedback, v);
            point.run = simulateFeed(HydraulicFeedModel(s.params, regulator, point.feedback), s.load, s.run, cancelled);
            point.stable = point.feedback->margins.closedLoopStable;
        } else {
            point.run = runFeedScenario(s, true, cancelled);
            point.stable = stableAt(s.params, load, linearise(HydraulicFeedModel(s.params, true), load));
        }
        point.oscillates = point.run.opening.overshootPct > kOscillationPct;
        out.push_back(std::move(point));
        if (progress) progress(static_cast<int>(out.size()), static_cast<int>(values.size()));
    }
    return out;
}

const FeedRun& FeedLoadPoint::of(FeedRegulator regulator) const {
    return regulator == FeedRegulator::Off ? off : regulator == FeedRegulator::FeedForward ? feedForward : feedback;
}

std::vector<double> defaultLoadSweepValues() {
    return {0.5, 1.0, 2.0, 3.0, 3.23, 4.0, 5.0, 6.0};
}

std::vector<FeedLoadPoint> sweepLoad(const FeedScenario& scenario, const std::vector<double>& loadsN,
                                     const FeedProgress& progress, const FeedCancelled& cancelled) {
    if (loadsN.empty() || loadsN.size() > kMaxSweepValues)
        throw std::invalid_argument("a load sweep takes 1 .. 50 loads, not " +
                                    number(static_cast<double>(loadsN.size())));
    const double stepS = scenario.load.empty() ? 0.02 : scenario.load.lastEventS();
    std::vector<FeedLoadPoint> out;
    for (double loadN : loadsN) {
        FeedScenario s = scenario;
        s.load = FeedLoadProfile::step(stepS, loadN);  // checks the load's limits
        FeedLoadPoint point;
        point.loadN = loadN;
        point.off = runFeedScenario(s, FeedRegulator::Off, cancelled);
        point.feedForward = runFeedScenario(s, FeedRegulator::FeedForward, cancelled);
        point.feedback = runFeedScenario(s, FeedRegulator::Feedback, cancelled);
        out.push_back(std::move(point));
        if (progress) progress(static_cast<int>(out.size()), static_cast<int>(loadsN.size()));
    }
    return out;
}

FeedBoundaryCheck crossCheckGainLimit(const FeedScenario& scenario, double gainLimit, const FeedCancelled& cancelled) {
    FeedBoundaryCheck c;
    c.gainLimit = gainLimit;
    c.belowGain = 0.95 * gainLimit;
    c.aboveGain = 1.05 * gainLimit;
    FeedScenario below = scenario;
    below.params.amplifierGain = c.belowGain;
    const FeedLinearisation lin = linearise(HydraulicFeedModel(below.params, true), scenario.finalLoadN());
    c.predictedFeedMPerS = lin.equilibrium.state.feedMPerS;
    double slowest = 0.0;  // the slowest decay rate below the limit, 1/s
    for (Eigen::Index k = 0; k < lin.eigenvalues.size(); ++k)
        slowest = k == 0 ? -lin.eigenvalues(k).real() : std::min(slowest, -lin.eigenvalues(k).real());
    // Ten time constants of the slowest mode after the last load change, within 60 s.
    const double needed = scenario.load.lastEventS() + 10.0 / std::max(slowest, 1e-3);
    FeedRunOptions options = scenario.run;
    options.durationS = std::clamp(needed, scenario.run.durationS, FeedLoadProfile::kMaxTimeS);
    options.sampleS = std::max(scenario.run.sampleS, options.durationS / 20000.0);
    below.run = options;
    FeedScenario above = below;
    above.params.amplifierGain = c.aboveGain;
    c.below = runFeedScenario(below, true, cancelled);
    c.above = runFeedScenario(above, true, cancelled);
    c.belowSettles = !c.below.slotFullyOpen &&
                     std::abs(c.below.feed.finalValue - c.predictedFeedMPerS) <= 0.01 * std::abs(c.predictedFeedMPerS);
    c.aboveRunsAway = c.above.slotFullyOpen;
    return c;
}

std::vector<FeedSensitivity> feedSensitivity(const HydraulicFeedParams& params, double loadN, double change,
                                             FeedRegulator regulator) {
    if (!(change > 0.0 && change <= 0.5))
        throw std::invalid_argument("sensitivity step " + number(change) + " is outside 0 .. 0.5");
    validate(params);
    const FeedRegulator regulated = regulator == FeedRegulator::Off ? FeedRegulator::FeedForward : regulator;
    auto steadyFeed = [&](const HydraulicFeedParams& p, bool on, bool& fullyOpen) {
        const FeedEquilibrium e = HydraulicFeedModel(p, on ? regulated : FeedRegulator::Off).equilibrium(loadN);
        fullyOpen = fullyOpen || e.slotFullyOpen;
        return e.state.feedMPerS;
    };
    bool ignored = false;
    const double nominalOn = steadyFeed(params, true, ignored);
    const double nominalOff = steadyFeed(params, false, ignored);
    // Of the nominal feed; of the set feed when the nominal carriage stands (stalled on its stop).
    auto percent = [&](double value, double nominal) {
        return 100.0 * (value - nominal) / (nominal != 0.0 ? std::abs(nominal) : params.setFeedMPerS);
    };
    std::vector<FeedSensitivity> out;
    for (const FeedParameterInfo& info : feedParameters()) {
        const double nominal = params.*(info.member);
        if (nominal == 0.0 || info.member == &HydraulicFeedParams::setFeedMPerS) continue;
        FeedSensitivity s{info.key, info.name, nominal};
        for (const double sign : {-1.0, 1.0}) {
            HydraulicFeedParams p = params;
            p.*(info.member) = std::clamp(nominal * (1.0 + sign * change), info.minValue, info.maxValue);
            const double on = percent(steadyFeed(p, true, s.fullyOpen), nominalOn);
            const double off = percent(steadyFeed(p, false, ignored), nominalOff);
            (sign < 0.0 ? s.onMinusPct : s.onPlusPct) = on;
            (sign < 0.0 ? s.offMinusPct : s.offPlusPct) = off;
        }
        out.push_back(s);
    }
    std::stable_sort(out.begin(), out.end(), [](const FeedSensitivity& a, const FeedSensitivity& b) {
        return std::max(std::abs(a.onMinusPct), std::abs(a.onPlusPct)) >
               std::max(std::abs(b.onMinusPct), std::abs(b.onPlusPct));
    });
    return out;
}

}  // namespace tt::core
