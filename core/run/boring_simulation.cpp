#include "core/run/boring_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/tool_stiffness.h"
#include "core/run/boring_run.h"
#include "core/run/dither_check.h"

namespace tt::core {

namespace {

/// The machined surface over the gauged length, gathered at every simulation step.
struct SurfaceStats {
    double from = 0.0;
    double to = 0.0;
    double maxGauged = 0.0;
    double maxFull = 0.0;
    double sumSquares = 0.0;
    long count = 0;
    double maxDeflection = 0.0;
    double forceSum = 0.0;
    double forceMax = 0.0;

    void observe(const BoringState& s) {
        const double diameterError = 2.0 * s.radiusErrorMm;
        maxFull = std::max(maxFull, std::abs(diameterError));
        if (s.toolZMm < from || s.toolZMm > to) return;
        maxGauged = std::max(maxGauged, std::abs(diameterError));
        sumSquares += diameterError * diameterError;
        ++count;
        maxDeflection = std::max(maxDeflection, std::abs(s.tipDeflectionXmm));
        forceSum += s.radialForceN;
        forceMax = std::max(forceMax, s.radialForceN);
    }
};

/// The force estimate against the true force over the gauged length.
struct EstimateStats {
    double squares = 0.0;
    double max = 0.0;
    int count = 0;
};

BoringTracePoint tracePoint(const BoringState& s, const std::optional<CompensationCycle>& cycle) {
    BoringTracePoint p;
    p.timeS = s.timeS;
    p.zMm = s.toolZMm;
    p.diameterErrorMm = 2.0 * s.radiusErrorMm;
    p.deflectionMm = s.tipDeflectionXmm;
    p.offsetMm = s.appliedOffsetMm;
    p.forceN = s.radialForceN;
    p.estimatedForceN = std::numeric_limits<double>::quiet_NaN();
    if (cycle && cycle->reading.forceN) p.estimatedForceN = *cycle->reading.forceN;
    return p;
}

}  // namespace

BoringResult runBoring(const BoringScenario& scenario, BoringMethod method) {
    if (method == BoringMethod::Current) requireResolvableDither(scenario);
    SimulatedBoringPass pass(scenario, method, false);
    BoringResult result;
    result.method = method;
    result.stiffnessUsedNPerMm = effectiveStiffnessNPerMm(scenario.tool);
    result.trueStiffnessNPerMm = pass.machine().trueStiffnessNPerMm();
    result.calibration = pass.calibration();

    SurfaceStats stats;
    stats.from = scenario.cut.gaugeMarginMm;
    stats.to = scenario.cut.boreLengthMm - scenario.cut.gaugeMarginMm;
    pass.machine().setSurfaceObserver([&stats](const BoringState& s) { stats.observe(s); });

    const std::unique_ptr<BoringRun> run = buildBoringRun(boringChoices(scenario, method), pass);
    EstimateStats estimate;
    while (!run->finished()) {
        const BoringRunCycle cycle = run->cycle();
        const BoringState& s = pass.machine().state();
        if (!s.cutting) continue;
        const BoringTracePoint p = tracePoint(s, cycle.compensation);
        if (const std::optional<CompensationCycle>& c = cycle.compensation) {
            if (c->reading.fresh) ++result.estimates;
            if (c->step.holding) {
                ++result.holdingCycles;
                result.lastHoldProblem = c->reading.problem;
            }
        }
        result.trace.push_back(p);
        const bool gauged = s.toolZMm >= stats.from && s.toolZMm <= stats.to;
        if (gauged && std::isfinite(p.estimatedForceN) && p.forceN > 0.0) {
            const double e = (p.estimatedForceN - p.forceN) / p.forceN;
            estimate.squares += e * e;
            estimate.max = std::max(estimate.max, std::abs(e));
            ++estimate.count;
        }
    }
    result.gaugedFromMm = stats.from;
    result.gaugedToMm = stats.to;
    result.boreErrorMaxMm = stats.maxGauged;
    result.boreErrorMaxFullLengthMm = stats.maxFull;
    result.boreErrorRmsMm = stats.count > 0 ? std::sqrt(stats.sumSquares / static_cast<double>(stats.count)) : 0.0;
    result.deflectionMaxMm = stats.maxDeflection;
    result.forceMeanN = stats.count > 0 ? stats.forceSum / static_cast<double>(stats.count) : 0.0;
    result.forceMaxN = stats.forceMax;
    if (estimate.count > 0) {
        result.forceEstimateErrorPct = 100.0 * std::sqrt(estimate.squares / estimate.count);
        result.forceEstimateErrorMaxPct = 100.0 * estimate.max;
    }
    return result;
}

}  // namespace tt::core
