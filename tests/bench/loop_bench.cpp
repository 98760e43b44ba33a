// The closed loop on the built-in shop (the path of `trueturn simulate` and the GUI's loop thread):
// parts through the engine per second, physical lathe and statistical plant; one part of the lathe
// simulator; the shaft model's set-up.
#include <benchmark/benchmark.h>

#include <memory>

#include "core/control/run_to_run_plant.h"
#include "core/control/run_to_run_setup.h"
#include "core/model/disturbance_model.h"
#include "core/run/shaft_run.h"
#include "core/sim/shaft/lathe_simulator.h"

namespace tt::core {
namespace {

/// The paper-2012 controller set-up at z = 2 (its disturbance: ARMA(1,1), pole 0.9215, zero -0.246).
RunToRunSetup paperSetup() {
    RunToRunSetup s;
    s.plant.delay = 2;
    const ShapingFilter filter = ShapingFilter::fromRoots({1.0, 0.246}, {{0.9215, 0.0}});
    for (double x : paperControlPointsMm(325.0))
        s.plant.points.push_back(
            {x, 2.0, DisturbanceModel({DisturbanceComponent::shapingFilterWithVariance(filter, 0.0013)}), 2.5e-7});
    s.weights.R1 = Eigen::MatrixXd::Identity(5, 5);
    s.weights.R2 = 0.01 * Eigen::MatrixXd::Identity(5, 5);
    s.limits = {0.3, 0.1};
    return s;
}

void runLoop(benchmark::State& state, bool physical) {
    ShaftScenario scenario;
    scenario.control = paperSetup();
    if (physical) scenario.lathe = LatheSetup{};
    const std::int64_t parts = state.range(0);
    for (auto _ : state) {
        LatheRunSpec spec;
        spec.scenario = scenario;
        spec.plan = planShaftRun(scenario, {ControllerKind::Lqg, std::nullopt, parts});
        const LatheRunRecord record = runLatheLoop(std::move(spec));
        benchmark::DoNotOptimize(record.pointDeviationMm.data());
    }
    state.SetItemsProcessed(state.iterations() * parts);
}

void BM_LoopEnginePhysicalLathe(benchmark::State& state) {
    runLoop(state, true);
}
BENCHMARK(BM_LoopEnginePhysicalLathe)->Arg(2000)->Unit(benchmark::kMillisecond);

void BM_LoopEngineStatisticalPlant(benchmark::State& state) {
    runLoop(state, false);
}
BENCHMARK(BM_LoopEngineStatisticalPlant)->Arg(2000)->Unit(benchmark::kMillisecond);

void BM_LatheSimulatorOnePart(benchmark::State& state) {
    LatheSimulator sim(LatheSetup{}, paperControlPointsMm(325.0), LatheDisturbanceModel::none(5));
    PartCorrection c{1, {}, {}, {}};
    for (int i = 0; i <= 650; ++i) {
        c.path.zMm.push_back(0.5 * i);
        c.path.xCorrectionMm.push_back(-0.05);
    }
    std::int64_t part = 1;
    for (auto _ : state) {
        c.partNumber = part++;
        benchmark::DoNotOptimize(sim.machine(c).diameterMm.data());
    }
}
BENCHMARK(BM_LatheSimulatorOnePart)->Unit(benchmark::kMicrosecond);

void BM_LatheShaftModelSetUp(benchmark::State& state) {
    for (auto _ : state) {
        LatheSimulator sim(LatheSetup{}, paperControlPointsMm(325.0), LatheDisturbanceModel::none(5));
        benchmark::DoNotOptimize(sim.complianceMmPerN().data());
    }
}
BENCHMARK(BM_LatheShaftModelSetUp)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tt::core
