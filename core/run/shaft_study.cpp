#include "core/run/shaft_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/control/run_to_run_plant.h"
#include "core/run/run_limits.h"
#include "core/run/shaft_run.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Below this variance a part-to-part variation is not there (σ = 1 nm, under any gauge's resolution), mm².
constexpr double kMinVarianceMm2 = 1e-12;

/// k_eff = open / closed variance; NaN (not available) when either is below kMinVarianceMm2: a lathe
/// without variation would give 0 or infinity, neither of which is an effectiveness.
double varianceRatio(double openMm2, double closedMm2) {
    return openMm2 >= kMinVarianceMm2 && closedMm2 >= kMinVarianceMm2 ? openMm2 / closedMm2 : kNaN;
}

/// Passes each finished part on to a progress callback.
class ProgressRelay final : public LoopListener {
public:
    ProgressRelay(const std::function<void(const std::string&, std::int64_t, std::int64_t)>& progress,
                  std::string stage, std::int64_t total)
        : m_progress(progress), m_stage(std::move(stage)), m_total(total) {}
    void onLoopEvent(const LoopEvent& event) override {
        if (event.kind == LoopEvent::Kind::PartFinished && m_progress) m_progress(m_stage, event.partNumber, m_total);
    }

private:
    const std::function<void(const std::string&, std::int64_t, std::int64_t)>& m_progress;
    std::string m_stage;
    std::int64_t m_total;
};

/// The highest part number the record saw finished (0: none).
std::int64_t lastFinishedPart(const LatheRunRecord& record) {
    for (std::size_t i = record.seen.size(); i > 0; --i)
        if (record.seen[i - 1]) return static_cast<std::int64_t>(i);
    return 0;
}

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
        spec.warmupParts = options.warmupParts;
    }
    spec.stop = options.stop;
    if (stored) spec.machine = options.machine;
    ProgressRelay relay(options.progress, stored ? "closed loop" : "open-loop reference",
                        spec.plan.loop.lastPartNumber.value_or(0));
    if (options.progress) spec.listener = &relay;
    LatheRunRecord record = runLatheLoop(std::move(spec));
    if (record.outcome.interrupted) throw StudyInterrupted(stored, record.runId, lastFinishedPart(record));
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

/// What the study takes from the closed run's record as it is.
void takeClosedRun(LatheStudyResult& result, const LatheRunRecord& closed) {
    result.runId = closed.runId;
    result.outcome = closed.outcome;
    result.rejectedValues = closed.rejectedValues;
    result.verdicts = closed.verdicts;
    result.warmupVerdicts = closed.warmupVerdicts;
    result.toleranceAlarms = closed.toleranceAlarms;
    result.modelAlarms = closed.modelAlarms;
    result.adaptations = closed.adaptations;
    result.adaptationNotices = closed.adaptationNotices;
    result.maxCorrectionMm = closed.maxCorrectionMm;
    result.maxCorrectionStepMm = closed.maxCorrectionStepMm;
    result.maxSwitchStepMm = closed.maxSwitchStepMm;
    result.switches = closed.switches;
}

/// The closed run's systematic error per control point after the loop's start-up (the first 2z + 5 parts).
void takeSystematicError(LatheStudyResult& result, const LatheRunRecord& closed, int delay, std::int64_t total) {
    result.systematicFromPart = std::min<std::int64_t>(2 * delay + 6, total - 1);
    const Eigen::VectorXd mean = profileStatistics(closed.pointDeviationMm, result.systematicFromPart, total).meanMm;
    result.systematicMm.assign(mean.data(), mean.data() + mean.size());
}

}  // namespace

double truePlantLqgKEff(const ShaftScenario& scenario) {
    if (scenario.lathe) return kNaN;
    RunToRunPlantSpec spec = scenario.control.plant;
    for (ControlPointSpec& p : spec.points)
        p.gain *= scenario.plantMismatch.gainFactor;
    spec.delay = scenario.plantMismatch.delayParts.value_or(spec.delay);
    const RunToRunPlant plant = buildRunToRunPlant(spec);
    const SteadyStateVariances v =
        analyseSteadyState(plant, lqgControllerModel(plant, designLqg(plant, scenario.control.weights)));
    return v.available ? v.kEffOverall : kNaN;
}

LatheStudyResult runLatheStudy(const ShaftScenario& scenario, std::uint64_t seed, const LatheStudyOptions& options) {
    checkRunParts(options.parts, options.warmupParts);
    const std::int64_t total = options.warmupParts + options.parts;
    const ShaftRunPlan closedPlan = planShaftRun(scenario, {options.controller, options.ewmaWeight, total});
    const LoopConfig& loop = closedPlan.loop;
    LatheStudyResult result;
    result.controller = options.controller;
    result.delay = closedPlan.plant.delay;
    result.parts = options.parts;
    result.warmupParts = options.warmupParts;
    if (options.controller == ControllerKind::Ewma || options.controller == ControllerKind::Dewma)
        result.ewmaWeight = closedPlan.ewmaWeight;
    // The disturbance as modelled (by the identified model when the scenario has one), without the controller's
    // integrating state (integral action).
    // No analytic figure for the double EWMA (no linear model of it here).
    const SteadyStateVariances analytic =
        options.controller == ControllerKind::Dewma
            ? SteadyStateVariances{}
            : analyseSteadyState(
                  buildRunToRunPlant(designPlantSpec(scenario.control)),
                  controllerModel(scenario.control, closedPlan.plant, options.controller, closedPlan.ewmaWeight));

    const LatheRunRecord closed = runOnce(scenario, seed, closedPlan, options, true);
    takeClosedRun(result, closed);
    takeSystematicError(result, closed, closedPlan.plant.delay, total);
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
        result.points.push_back({loop.pointZMm[i], varOpen(k), varClosed(k), varianceRatio(varOpen(k), varClosed(k)),
                                 analytic.available ? analytic.kEff(k) : kNaN});
    }
    result.kEff = varianceRatio(varOpen.sum(), varClosed.sum());
    result.kEffAnalytic = analytic.available ? analytic.kEffOverall : kNaN;
    result.kEffTruePlantLqg = truePlantLqgKEff(scenario);

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
