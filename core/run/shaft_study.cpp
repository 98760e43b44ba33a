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

LinearControllerModel designModel(const RunToRunSetup& control, const RunToRunPlant& plant, ControllerKind kind,
                                  double ewmaWeight) {
    switch (kind) {
        case ControllerKind::Lqg:
            return lqgControllerModel(plant, designLqg(plant, control.weights));
        case ControllerKind::Ewma:
            return ewmaControllerModel(plant, ewmaWeight);
        case ControllerKind::Open:
            break;
    }
    return openLoopControllerModel(plant);
}

LatheRunRecord runOnce(const LatheShopSpec& shop, LoopConfig loop, std::unique_ptr<RunToRunController> controller,
                       const LatheStudyOptions& options, bool stored) {
    LatheRunSpec spec;
    spec.shop = shop;
    spec.loop = std::move(loop);
    spec.controller = std::move(controller);
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

}  // namespace

LatheStudyResult runLatheStudy(const RunToRunSetup& control, const LatheShopSpec& shop, const LoopConfig& loop,
                               const LatheStudyOptions& options) {
    if (options.parts < 2) throw std::invalid_argument("a study needs at least 2 counted parts");
    if (options.warmupParts < 0) throw std::invalid_argument("the warm-up cannot be negative");
    const RunToRunPlant plant = buildRunToRunPlant(control.plant);
    LatheStudyResult result;
    result.controller = options.controller;
    result.delay = plant.delay;
    result.parts = options.parts;

    double ewmaWeight = control.ewma.weight;
    if (options.controller == ControllerKind::Ewma) {
        ewmaWeight = options.ewmaWeight       ? *options.ewmaWeight
                     : control.ewmaWeightAuto ? bestEwmaWeight(plant, defaultEwmaWeightGrid()).weight
                                              : control.ewma.weight;
        result.ewmaWeight = ewmaWeight;
    }
    const SteadyStateVariances analytic =
        analyseSteadyState(plant, designModel(control, plant, options.controller, ewmaWeight));

    const std::int64_t total = options.warmupParts + options.parts;
    LoopConfig closedLoop = loop;
    closedLoop.lastPartNumber = total;
    const LatheRunRecord closed = runOnce(
        shop, closedLoop, makeRunToRunController(control, plant, options.controller, ewmaWeight), options, true);
    result.runId = closed.runId;
    result.outcome = closed.outcome;
    result.rejectedValues = closed.rejectedValues;

    const std::int64_t from = options.warmupParts + 1;
    const Eigen::VectorXd varClosed = deviationVariance(closed.pointDeviationMm, from, total);
    Eigen::VectorXd varOpen = varClosed;
    if (options.controller != ControllerKind::Open) {
        LoopConfig openLoop = closedLoop;
        openLoop.systematicModel.reset();
        LatheStudyOptions plain = options;
        plain.profileZMm.clear();
        const LatheRunRecord open = runOnce(
            shop, openLoop, makeRunToRunController(control, plant, ControllerKind::Open, ewmaWeight), plain, false);
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
        result.profileFromPart = std::min<std::int64_t>(2 * plant.delay + 6, total - 1);
        result.profileToPart = total;
        const ProfileStatistics s = profileStatistics(closed.profileDeviationMm, result.profileFromPart, total);
        result.profileZMm = options.profileZMm;
        result.profileMeanMm.assign(s.meanMm.data(), s.meanMm.data() + s.meanMm.size());
        result.profileStdMm.assign(s.stdMm.data(), s.stdMm.data() + s.stdMm.size());
    }
    return result;
}

}  // namespace tt::core
