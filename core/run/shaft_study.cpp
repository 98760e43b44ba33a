#include "core/run/shaft_study.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/control/run_to_run_plant.h"
#include "core/run/shaft_run.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

LatheRunRecord runOnce(const ShaftScenario& scenario, std::uint64_t seed, ShaftRunPlan plan,
                       const LatheStudyOptions& options, bool stored) {
    LatheRunSpec spec;
    spec.scenario = scenario;
    spec.seed = seed;
    spec.plan = std::move(plan);
    spec.profileZMm = options.profileZMm;
    if (stored) {
        spec.history = options.history;
        spec.description = options.description;
        spec.resume = options.resume;
        spec.speed = options.speed;
    }
    LatheRunRecord record = runLatheLoop(std::move(spec));
    if (!record.outcome.complete)
        throw std::runtime_error("the simulated run stopped before its last part: " + record.outcome.stopReason);
    return record;
}

/// The step's residual: the closed run with the step against the same closed run without it.
StepResidual stepResidual(const ShaftScenario& scenario, std::uint64_t seed, const ShaftRunPlan& plan,
                          const LatheStudyOptions& options, const LatheRunRecord& withStep) {
    const PlantStep& step = *scenario.plantMismatch.step;
    StepResidual r{step.atPart, step.sizeMm, step.point, 0, 0, 0.0};
    r.fromPart = step.atPart + kStepSettleFactor * scenario.delay() + kStepSettleParts;
    r.toPart = r.fromPart + kStepAveragedParts - 1;
    const auto total = static_cast<std::int64_t>(withStep.pointDeviationMm.size());
    if (r.toPart > total)
        throw std::invalid_argument("the step at part " + std::to_string(step.atPart) +
                                    " needs the run to last until part " + std::to_string(r.toPart) +
                                    " (3z + 5 parts to settle, 20 averaged), it has " + std::to_string(total));
    ShaftScenario plain = scenario;
    plain.plantMismatch.step.reset();
    LatheStudyOptions quiet = options;
    quiet.profileZMm.clear();
    const LatheRunRecord without = runOnce(plain, seed, plan, quiet, false);
    double sum = 0.0;
    for (std::int64_t k = r.fromPart; k <= r.toPart; ++k) {
        const auto i = static_cast<std::size_t>(k - 1);
        const Eigen::VectorXd effect = withStep.pointDeviationMm[i] - without.pointDeviationMm[i];
        sum += step.point ? effect(*step.point) : effect.mean();
    }
    r.residualPct = 100.0 * sum / kStepAveragedParts / step.sizeMm;
    return r;
}

}  // namespace

LatheStudyResult runLatheStudy(const ShaftScenario& scenario, std::uint64_t seed, const LatheStudyOptions& options) {
    if (options.parts < 2) throw std::invalid_argument("a study needs at least 2 counted parts");
    if (options.warmupParts < 0) throw std::invalid_argument("the warm-up cannot be negative");
    const std::int64_t total = options.warmupParts + options.parts;
    const ShaftRunPlan closedPlan = planShaftRun(scenario, {options.controller, options.ewmaWeight, total});
    const LoopConfig& loop = closedPlan.loop;
    LatheStudyResult result;
    result.controller = options.controller;
    result.delay = closedPlan.plant.delay;
    result.parts = options.parts;
    if (options.controller == ControllerKind::Ewma || options.controller == ControllerKind::Dewma)
        result.ewmaWeight = closedPlan.ewmaWeight;
    // The disturbance as modelled, without the controller's integrating state (integral action).
    // No analytic figure for the double EWMA (no linear model of it here).
    const SteadyStateVariances analytic =
        options.controller == ControllerKind::Dewma
            ? SteadyStateVariances{}
            : analyseSteadyState(
                  buildRunToRunPlant(scenario.control.plant),
                  controllerModel(scenario.control, closedPlan.plant, options.controller, closedPlan.ewmaWeight));

    const LatheRunRecord closed = runOnce(scenario, seed, closedPlan, options, true);
    result.runId = closed.runId;
    result.outcome = closed.outcome;
    result.rejectedValues = closed.rejectedValues;
    result.verdicts = closed.verdicts;
    result.toleranceAlarms = closed.toleranceAlarms;
    result.modelAlarms = closed.modelAlarms;
    result.maxCorrectionMm = closed.maxCorrectionMm;
    result.maxCorrectionStepMm = closed.maxCorrectionStepMm;
    if (scenario.plantMismatch.step) result.step = stepResidual(scenario, seed, closedPlan, options, closed);

    const std::int64_t from = options.warmupParts + 1;
    const Eigen::VectorXd varClosed = deviationVariance(closed.pointDeviationMm, from, total);
    Eigen::VectorXd varOpen = varClosed;
    if (options.controller != ControllerKind::Open) {
        LatheStudyOptions plain = options;
        plain.profileZMm.clear();
        const LatheRunRecord open =
            runOnce(scenario, seed, planShaftRun(scenario, {ControllerKind::Open, std::nullopt, total}), plain, false);
        varOpen = deviationVariance(open.pointDeviationMm, from, total);
    }
    for (std::size_t i = 0; i < loop.pointZMm.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        result.points.push_back({loop.pointZMm[i], varOpen(k), varClosed(k), varOpen(k) / varClosed(k),
                                 analytic.available ? analytic.kEff(k) : kNaN});
    }
    result.kEff = varOpen.sum() / varClosed.sum();
    result.kEffAnalytic = analytic.available ? analytic.kEffOverall : kNaN;

    if (!options.profileZMm.empty()) {
        // After the loop's start-up: the first 2z + 5 parts (z parts before the first measurement
        // arrives, then the controller settles).
        result.profileFromPart = std::min<std::int64_t>(2 * closedPlan.plant.delay + 6, total - 1);
        result.profileToPart = total;
        const ProfileStatistics s = profileStatistics(closed.profileDeviationMm, result.profileFromPart, total);
        result.profileZMm = options.profileZMm;
        result.profileMeanMm.assign(s.meanMm.data(), s.meanMm.data() + s.meanMm.size());
        result.profileStdMm.assign(s.stdMm.data(), s.stdMm.data() + s.stdMm.size());
    }
    return result;
}

}  // namespace tt::core
