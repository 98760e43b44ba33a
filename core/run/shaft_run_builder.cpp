#include "core/run/shaft_run_builder.h"

#include <cmath>

#include "core/common/text_format.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

namespace {
/// A G-code output's diameter and the scenario's may differ by rounding only.
constexpr double kDiameterMatchMm = 0.0005;
}  // namespace

OutputDiameterMismatch::OutputDiameterMismatch(double output, double scenario)
    : std::invalid_argument("the CNC output writes programs for a diameter of " + formatFixed(output, 3) +
                            " mm, the scenario turns " + formatFixed(scenario, 3) + " mm"),
      outputMm(output),
      scenarioMm(scenario) {}

ShaftRunPlan planShaftRun(const ShaftScenario& scenario, const ShaftRunChoice& choice) {
    if (choice.ewmaWeight && !(*choice.ewmaWeight > 0.0 && *choice.ewmaWeight <= 1.0))
        throw std::invalid_argument("the EWMA weight must be in (0, 1]");
    if (choice.lastPartNumber && *choice.lastPartNumber < 1)
        throw std::invalid_argument("a run needs at least one part");
    ShaftRunPlan plan;
    // Integral action lives in the LQG's design model only (the EWMA and the open loop have no model).
    // An identified model (control.model) replaces the plant's gains, disturbances and delay in the design.
    const RunToRunPlantSpec spec = designPlantSpec(scenario.control);
    plan.plant = buildRunToRunPlant(
        choice.controller == ControllerKind::Lqg ? withIntegralAction(spec, scenario.control.integral) : spec);
    plan.controller = choice.controller;
    plan.ewmaWeight = choice.controller == ControllerKind::Ewma || choice.controller == ControllerKind::Dewma
                          ? chooseEwmaWeight(scenario.control, plan.plant, choice.ewmaWeight)
                          : scenario.control.ewma.weight;
    plan.loop = scenario.loopConfig(choice.controller != ControllerKind::Open, choice.lastPartNumber);
    return plan;
}

std::unique_ptr<RunToRunController> makeShaftController(const ShaftScenario& scenario, const ShaftRunPlan& plan) {
    return makeRunToRunController(scenario.control, plan.plant, plan.controller, plan.ewmaWeight);
}

std::unique_ptr<LoopEngine> buildShaftRun(const ShaftScenario& scenario, const ShaftRunPlan& plan,
                                          ShaftMachine& machine, HistoryStore* history, DiameterGauge* gauge) {
    if (const std::optional<double> outputMm = machine.outputNominalDiameterMm();
        outputMm && std::fabs(*outputMm - plan.loop.nominalDiameterMm) > kDiameterMatchMm)
        throw OutputDiameterMismatch(*outputMm, plan.loop.nominalDiameterMm);
    auto engine = std::make_unique<LoopEngine>(
        plan.loop,
        LoopPorts{machine.cycle(), machine.output(), gauge ? *gauge : machine.gauge(), machine.clock(), history},
        makeShaftController(scenario, plan));
    // The LQG's model is what the loop adapts when the mismatch monitor fires (the others have no innovations).
    if (plan.controller == ControllerKind::Lqg) engine->setAdaptation(scenario.control);
    return engine;
}

ShaftScenario withControllerTuning(ShaftScenario scenario, const RunToRunSetup& tuning) {
    RunToRunSetup& control = scenario.control;
    const std::size_t points = control.plant.points.size();
    const auto n = static_cast<Eigen::Index>(points);
    if (tuning.plant.points.size() != points || tuning.weights.R1.rows() != n || tuning.weights.R2.rows() != n)
        throw std::invalid_argument("the controller tuning has " + std::to_string(tuning.plant.points.size()) +
                                    " control points, the run " + std::to_string(points));
    const double ewmaWeight = control.ewma.weight;
    control.weights = tuning.weights;
    control.limits = tuning.limits;
    control.lqg = tuning.lqg;
    control.ewma = tuning.ewma;
    control.ewma.weight = ewmaWeight;
    control.integral = tuning.integral;
    for (std::size_t i = 0; i < points; ++i)
        control.plant.points[i].disturbance = tuning.plant.points[i].disturbance;
    control.model = tuning.model;
    if (control.model) control.model->validate(points, control.plant.delay);
    return scenario;
}

std::unique_ptr<RunToRunController> retunedShaftController(const ShaftScenario& scenario, const ShaftRunPlan& plan,
                                                           const RunToRunSetup& tuning) {
    const ShaftScenario tuned = withControllerTuning(scenario, tuning);
    const ShaftRunPlan retuned = planShaftRun(tuned, {plan.controller, plan.ewmaWeight, std::nullopt});
    return makeShaftController(tuned, retuned);
}

void replayStoredParts(ShaftMachine& machine, const LoopConfig& loop, const std::vector<StoredPart>& parts) {
    for (const StoredPart& stored : parts)
        machine.replayPart(partCorrectionFor(loop, stored), stored.finishedS);
}

void resumeShaftRun(LoopEngine& engine, ShaftMachine& machine, const LoopConfig& loop, const ResumePoint& point) {
    for (const StoredPart& pending : point.pendingParts)
        if (!pending.measurement) machine.restorePart(partCorrectionFor(loop, pending));
    engine.resumeFrom(point);
}

}  // namespace tt::core
