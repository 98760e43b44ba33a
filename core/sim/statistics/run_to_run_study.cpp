#include "core/sim/statistics/run_to_run_study.h"

#include <limits>

#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

StudyResult runRunToRunStudy(const RunToRunSetup& setup, const StudyOptions& options) {
    const RunToRunPlant plant = buildRunToRunPlant(setup.plant);
    StudyResult result;
    result.controller = options.controller;
    result.delay = plant.delay;
    result.parts = options.monteCarlo.parts;

    const double ewmaWeight = options.controller == ControllerKind::Ewma
                                  ? chooseEwmaWeight(setup, plant, options.ewmaWeight)
                                  : setup.ewma.weight;
    if (options.controller == ControllerKind::Ewma) result.ewmaWeight = ewmaWeight;
    const SteadyStateVariances analytic =
        analyseSteadyState(plant, controllerModel(setup, plant, options.controller, ewmaWeight));
    std::unique_ptr<RunToRunController> controller =
        makeRunToRunController(setup, plant, options.controller, ewmaWeight);
    const MonteCarloResult mc = runMonteCarlo(plant, *controller, options.monteCarlo);

    for (std::size_t i = 0; i < mc.points.size(); ++i) {
        const MonteCarloPoint& p = mc.points[i];
        result.points.push_back({p.xMm, p.varOpenMm2, p.varClosedMm2, p.kEff,
                                 analytic.available ? analytic.kEff(static_cast<Eigen::Index>(i))
                                                    : std::numeric_limits<double>::quiet_NaN()});
    }
    result.kEff = mc.kEff;
    result.kEffAnalytic = analytic.available ? analytic.kEffOverall : std::numeric_limits<double>::quiet_NaN();
    result.rejectedValues = mc.rejectedValues;
    return result;
}

}  // namespace tt::core
