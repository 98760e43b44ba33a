#include "core/run/boring_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/calibration/linearisation_image.h"
#include "core/control/in_process_compensation.h"
#include "core/sim/rigs/probe_calibration_rig.h"

namespace tt::core {

const char* toString(BoringMethod method) {
    switch (method) {
        case BoringMethod::None:
            return "none";
        case BoringMethod::Current:
            return "current";
        case BoringMethod::Probe:
            return "probe";
    }
    return "none";
}

BoringMethod boringMethodFromString(const std::string& text) {
    if (text == "none") return BoringMethod::None;
    if (text == "current") return BoringMethod::Current;
    if (text == "probe") return BoringMethod::Probe;
    throw std::invalid_argument("method '" + text + "' must be current, probe or none");
}

ProbeCalibrationSummary calibrateMandrel(BoringMachine& machine, const BoringScenario& scenario) {
    ProbeCalibrationRig rig(machine.probeSensor(), 0, scenario.calibration.referenceResolutionUm,
                            scenario.calibration.referenceNoiseUm, scenario.seed * 7919ULL + 3);
    const std::vector<CalibrationPoint> points = rig.sweep(scenario.calibration);
    const Linearisation lin = linearise(points, scenario.probe.adcBits, scenario.calibration.degree);
    TableImageInfo info;
    info.degree = static_cast<std::uint8_t>(lin.fit.degree);
    const std::vector<std::uint8_t> image = encodeTableImage(lin.table, info);
    const TableImage loaded = decodeTableImage(image);
    machine.probeSensor().setTable(0, loaded.table);
    machine.probeSensor().settle(0.0, 0.0);
    ProbeCalibrationSummary summary;
    summary.points = static_cast<int>(points.size());
    summary.degree = lin.fit.degree;
    summary.rmsResidualUm = lin.fit.rmsResidualUm;
    summary.maxTableErrorUm = lin.maxTableErrorUm;
    summary.imageCrc = loaded.crc;
    return summary;
}

namespace {

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
};

}  // namespace

BoringResult runBoring(const BoringScenario& scenario, BoringMethod method) {
    BoringMachine machine(scenario, method == BoringMethod::Current);
    BoringResult result;
    result.method = method;
    result.stiffnessUsedNPerMm = effectiveStiffnessNPerMm(scenario.tool);
    result.trueStiffnessNPerMm = machine.trueStiffnessNPerMm();

    SurfaceStats stats;
    stats.from = scenario.cut.gaugeMarginMm;
    stats.to = scenario.cut.boreLengthMm - scenario.cut.gaugeMarginMm;
    machine.setSurfaceObserver([&stats](const BoringState& s) {
        const double diameterError = 2.0 * s.radiusErrorMm;
        stats.maxFull = std::max(stats.maxFull, std::abs(diameterError));
        if (s.toolZMm < stats.from || s.toolZMm > stats.to) return;
        stats.maxGauged = std::max(stats.maxGauged, std::abs(diameterError));
        stats.sumSquares += diameterError * diameterError;
        ++stats.count;
        stats.maxDeflection = std::max(stats.maxDeflection, std::abs(s.tipDeflectionXmm));
        stats.forceSum += s.radialForceN;
        stats.forceMax = std::max(stats.forceMax, s.radialForceN);
    });

    std::unique_ptr<DeflectionSource> source;
    if (method == BoringMethod::Current) {
        DitherEstimatorConfig config = scenario.estimator;
        config.currentToForceNPerA = scenario.tool.currentToForceGainNPerA;
        config.stiffnessNPerMm = result.stiffnessUsedNPerMm;
        source = std::make_unique<CurrentDeflectionSource>(machine.driveReadout(), config);
    } else if (method == BoringMethod::Probe) {
        result.calibration = calibrateMandrel(machine, scenario);
        source = std::make_unique<ProbeDeflectionSource>(machine.probe(), 0, std::nullopt, result.stiffnessUsedNPerMm);
    }
    std::unique_ptr<InProcessCompensator> compensator;
    if (source)
        compensator =
            std::make_unique<InProcessCompensator>(*source, machine.output(), scenario.limits, scenario.plcCycleS);

    double errorSquares = 0.0;
    double errorMax = 0.0;
    int errorCount = 0;
    while (!machine.finished()) {
        machine.advanceCycle();
        const BoringState& s = machine.state();
        std::optional<CompensationCycle> cycle;
        if (compensator) cycle = compensator->cycle(s.timeS);
        if (!s.cutting) continue;
        BoringTracePoint p;
        p.timeS = s.timeS;
        p.zMm = s.toolZMm;
        p.diameterErrorMm = 2.0 * s.radiusErrorMm;
        p.deflectionMm = s.tipDeflectionXmm;
        p.offsetMm = s.appliedOffsetMm;
        p.forceN = s.radialForceN;
        p.estimatedForceN = std::numeric_limits<double>::quiet_NaN();
        if (cycle) {
            if (cycle->reading.forceN) p.estimatedForceN = *cycle->reading.forceN;
            if (cycle->reading.fresh) ++result.estimates;
            if (cycle->step.holding) {
                ++result.holdingCycles;
                result.lastHoldReason = cycle->step.reason;
            }
        }
        result.trace.push_back(p);
        const bool gauged = s.toolZMm >= stats.from && s.toolZMm <= stats.to;
        if (gauged && std::isfinite(p.estimatedForceN) && p.forceN > 0.0) {
            const double e = (p.estimatedForceN - p.forceN) / p.forceN;
            errorSquares += e * e;
            errorMax = std::max(errorMax, std::abs(e));
            ++errorCount;
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
    if (errorCount > 0) {
        result.forceEstimateErrorPct = 100.0 * std::sqrt(errorSquares / errorCount);
        result.forceEstimateErrorMaxPct = 100.0 * errorMax;
    }
    return result;
}

}  // namespace tt::core
