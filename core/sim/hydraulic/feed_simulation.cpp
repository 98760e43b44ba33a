#include "core/sim/hydraulic/feed_simulation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/sim/hydraulic/ode_integrator.h"

namespace tt::core {

namespace {

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void checkOptions(const FeedRunOptions& o) {
    if (!std::isfinite(o.durationS) || o.durationS <= 0.0 || o.durationS > FeedLoadProfile::kMaxTimeS)
        throw std::invalid_argument("simulated time " + number(o.durationS) + " s is outside 0 .. 60 s");
    if (!std::isfinite(o.sampleS) || o.sampleS < 1e-6 || o.sampleS > o.durationS)
        throw std::invalid_argument("sample interval " + number(o.sampleS) + " s is outside 1e-06 .. " +
                                    number(o.durationS) + " s");
    if (!std::isfinite(o.bandPct) || o.bandPct <= 0.0 || o.bandPct > 100.0)
        throw std::invalid_argument("feed band " + number(o.bandPct) + " % is outside 0 .. 100 %");
    if (o.durationS / o.sampleS > FeedRunOptions::kMaxSamples)
        throw std::invalid_argument("simulated time " + number(o.durationS) + " s at " + number(o.sampleS) +
                                    " s gives more than 200000 samples; sample less often");
}

std::vector<double> toVector(const FeedState& s) {
    return {s.currentA, s.spoolM, s.spoolVelocityMPerS, s.feedMPerS, s.integralM, s.leadM};
}

FeedState toState(const std::vector<double>& x) {
    return {x[0], x[1], x[2], x[3], x[4], x[5]};
}

/// Typical sizes of the states, for the stepper's error control.
std::vector<double> stateScales(const HydraulicFeedModel& model, const FeedLoadProfile& load) {
    const HydraulicFeedParams& p = model.params();
    const FeedEquilibrium loaded = model.equilibrium(load.maxForceN());
    const double current = std::max({1e-4, model.derived().biasCurrentA, std::abs(loaded.state.currentA)});
    const double spool = std::max(1e-7, model.params().spoolLapM + p.maxOpeningM);
    // The integral of the feed error: the size that makes the PI's part of the demand a full opening.
    const double integral = model.feedback() ? p.maxOpeningM * model.feedback()->integralTimeS / model.feedback()->gainS
                                             : p.setFeedMPerS * 1e-3;
    return {current, spool, spool / p.spoolTimeConstantS, p.setFeedMPerS, integral, p.maxOpeningM};
}

FeedSample sampleOf(const HydraulicFeedModel& model, double t, double loadN, const FeedState& s) {
    return {t,
            loadN,
            s.feedMPerS,
            s.currentA,
            s.spoolM,
            model.opening(s.spoolM),
            model.regulatorFlow(s.spoolM),
            model.feedbackSignals(s).demandM,
            model.stalled(s, loadN)};
}

/// The largest deviation from the set feed outside the transients after each load change.
FeedHold holdOf(const std::vector<FeedSample>& samples, const FeedLoadProfile& load, const FeedRunOptions& o,
                double setFeed, double excludedS) {
    FeedHold h;
    h.bandPct = o.bandPct;
    h.excludedS = excludedS;
    std::vector<double> starts;
    for (const FeedLoadEvent& e : load.events())
        starts.push_back(e.timeS);
    if (o.fromRest) starts.push_back(0.0);
    for (const FeedSample& s : samples) {
        const bool transient = std::any_of(starts.begin(), starts.end(),
                                           [&](double t0) { return s.timeS >= t0 && s.timeS < t0 + excludedS; });
        if (transient) continue;
        const double deviation = 100.0 * (s.feedMPerS - setFeed) / setFeed;
        if (std::abs(deviation) > std::abs(h.largestDeviationPct)) {
            h.largestDeviationPct = deviation;
            h.atS = s.timeS;
        }
    }
    h.withinBand = std::abs(h.largestDeviationPct) <= h.bandPct;
    return h;
}

/// Each kind of warning at most once: the first and last sample in that state and the time in it.
std::vector<FeedWarning> warningsOf(const FeedRun& run, const HydraulicFeedModel& model, double bandPct) {
    const double full = model.params().maxOpeningM * (1.0 - 1e-9);
    const double shutBelow = -0.01 * model.params().maxOpeningM;  // 1 % of the opening: not a rounding
    auto holds = [&](FeedWarningKind kind, const FeedSample& s) {
        switch (kind) {
            case FeedWarningKind::CarriageStalled:
                return s.stalled;
            case FeedWarningKind::SlotFullyOpen:
                return s.openingM >= full;
            case FeedWarningKind::SlotShut:
                return s.demandM < shutBelow;
            case FeedWarningKind::FeedOffSet:
                return false;
        }
        return false;
    };
    std::vector<FeedWarning> out;
    for (FeedWarningKind kind :
         {FeedWarningKind::CarriageStalled, FeedWarningKind::SlotFullyOpen, FeedWarningKind::SlotShut}) {
        FeedWarning w{kind};
        bool any = false;
        for (std::size_t k = 0; k < run.samples.size(); ++k) {
            if (!holds(kind, run.samples[k])) continue;
            if (!any) w.fromS = run.samples[k].timeS;
            any = true;
            w.toS = run.samples[k].timeS;
            if (k + 1 < run.samples.size()) w.durationS += run.samples[k + 1].timeS - run.samples[k].timeS;
        }
        if (any) out.push_back(w);
    }
    if (std::abs(run.deviationPct) > bandPct) {
        const double end = run.samples.back().timeS;
        out.push_back({FeedWarningKind::FeedOffSet, end, end, 0.0, run.deviationPct});
    }
    return out;
}

/// The metrics, the hold and the warnings of a simulated run.
void finishRun(FeedRun& run, const HydraulicFeedModel& model, const FeedLoadProfile& load,
               const FeedRunOptions& options) {
    std::vector<double> t;
    std::vector<double> feed;
    std::vector<double> opening;
    for (const FeedSample& s : run.samples) {
        t.push_back(s.timeS);
        feed.push_back(s.feedMPerS);
        opening.push_back(s.openingM);
    }
    const double event = std::min(load.lastEventS(), t.size() >= 2 ? t[t.size() - 2] : 0.0);
    run.feed = stepMetrics(t, feed, event);
    run.opening = stepMetrics(t, opening, event);
    run.slotFullyOpen = run.samples.back().openingM >= model.params().maxOpeningM * (1.0 - 1e-9);
    run.setFeedMPerS = model.params().setFeedMPerS;
    run.deviationPct = 100.0 * (run.feed.finalValue - run.setFeedMPerS) / run.setFeedMPerS;
    run.hold = holdOf(run.samples, load, options, run.setFeedMPerS, 3.0 * model.derived().cylinderTimeConstantS);
    run.warnings = warningsOf(run, model, options.bandPct);
}

}  // namespace

const char* toString(FeedWarningKind kind) {
    switch (kind) {
        case FeedWarningKind::CarriageStalled:
            return "carriage_stalled";
        case FeedWarningKind::SlotFullyOpen:
            return "slot_fully_open";
        case FeedWarningKind::SlotShut:
            return "slot_shut";
        case FeedWarningKind::FeedOffSet:
            return "feed_off_set";
    }
    return "feed_off_set";
}

FeedRun simulateFeed(const HydraulicFeedModel& model, const FeedLoadProfile& load, const FeedRunOptions& options,
                     const std::function<bool()>& cancelled) {
    checkOptions(options);
    const int count = static_cast<int>(std::floor(options.durationS / options.sampleS + 1e-9));
    std::vector<double> grid;
    for (int k = 0; k <= count; ++k)
        grid.push_back(k * options.sampleS);
    std::vector<double> edges{0.0};
    for (double b : load.breakpoints())
        if (b > 0.0 && b < grid.back()) edges.push_back(b);
    edges.push_back(grid.back());

    FeedRun run;
    run.regulator = model.regulator();
    run.regulatorOn = model.regulatorOn();
    run.samples.reserve(grid.size());
    const std::vector<double> scale = stateScales(model, load);
    std::vector<double> x = toVector(options.fromRest ? model.restState() : model.unloadedState());
    run.samples.push_back(sampleOf(model, 0.0, load.forceAt(0.0), toState(x)));
    std::size_t next = 1;  // the next grid time to record
    for (std::size_t seg = 0; seg + 1 < edges.size(); ++seg) {
        const double a = edges[seg];
        const double b = edges[seg + 1];
        if (b <= a) continue;
        // The load is linear inside a segment: evaluate it as that line, also at b, so the stepper's
        // last stage never sees the next segment's jump.
        const double loadA = load.forceAt(a);
        const double slope = (load.forceAt(0.5 * (a + b)) - loadA) / (0.5 * (b - a));
        auto loadAt = [&](double t) { return std::max(0.0, loadA + slope * (t - a)); };
        std::vector<double> times{a};
        for (std::size_t k = next; k < grid.size() && grid[k] < b - 1e-12; ++k)
            if (grid[k] > a + 1e-12) times.push_back(grid[k]);
        times.push_back(b);
        const OdeRightHandSide rhs = [&](double t, const std::vector<double>& xs, std::vector<double>& dxdt) {
            dxdt = toVector(model.derivative(toState(xs), loadAt(t)));
        };
        const OdeObserver observe = [&](double t, const std::vector<double>& xs) {
            if (t <= a) return;
            if (cancelled && cancelled()) throw FeedSimulationCancelled();
            if (next < grid.size() && std::abs(grid[next] - t) <= 1e-12) {
                run.samples.push_back(sampleOf(model, grid[next], loadAt(t), toState(xs)));
                ++next;
            }
        };
        x = integrateDormandPrince(rhs, x, times, observe, scale);
    }

    finishRun(run, model, load, options);
    return run;
}

}  // namespace tt::core
