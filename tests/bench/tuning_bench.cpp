// The Controller page's re-synthesis per change (issue 13 item 6, docs/BENCHMARKS.md): the whole preview
// (LQG design, analytic k_eff of LQG / best EWMA / open loop, margins, step response, |S|) and its parts,
// on the paper-2012 plant (5 points, z = 4).
#include <benchmark/benchmark.h>

#include "core/control/lqg_design.h"
#include "core/control/margins.h"
#include "core/run/tuning_preview.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace {

using namespace tt::core;

RunToRunSetup paperSetup(int delay) {
    RunToRunSetup s;
    s.plant.delay = delay;
    const DisturbanceModel d({DisturbanceComponent::shapingFilterWithVariance(
        ShapingFilter::fromRoots({1.0, 0.246}, {{0.9215, 0.0}}), 0.0013)});
    for (double x : paperControlPointsMm(325.0))
        s.plant.points.push_back(ControlPointSpec{x, 2.0, d, 2.5e-7});
    s.weights = {Eigen::MatrixXd::Identity(5, 5), 0.01 * Eigen::MatrixXd::Identity(5, 5)};
    s.limits = {0.3, 0.1};
    return s;
}

void BM_TuningPreviewPaperZ4(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    for (auto _ : state)
        benchmark::DoNotOptimize(computeTuningPreview(s));
}
BENCHMARK(BM_TuningPreviewPaperZ4)->Unit(benchmark::kMillisecond);

/// What a weight drag costs on the page: the EWMA and open-loop part reused from the previous preview.
void BM_TuningPreviewWeightChangePaperZ4(benchmark::State& state) {
    RunToRunSetup s = paperSetup(4);
    const TuningPreview first = computeTuningPreview(s);
    s.weights.R2(0, 0) = 0.02;
    for (auto _ : state)
        benchmark::DoNotOptimize(computeTuningPreview(s, &first));
}
BENCHMARK(BM_TuningPreviewWeightChangePaperZ4)->Unit(benchmark::kMillisecond);

void BM_LqgMarginsPaperZ4(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    const LqgDesign design = designLqg(plant, s.weights);
    for (auto _ : state)
        benchmark::DoNotOptimize(lqgMargins(plant, design));
}
BENCHMARK(BM_LqgMarginsPaperZ4)->Unit(benchmark::kMillisecond);

void BM_BestEwmaWeightPaperZ4(benchmark::State& state) {
    const RunToRunPlant plant = buildRunToRunPlant(paperSetup(4).plant);
    for (auto _ : state)
        benchmark::DoNotOptimize(bestEwmaWeight(plant, defaultEwmaWeightGrid()));
}
BENCHMARK(BM_BestEwmaWeightPaperZ4)->Unit(benchmark::kMillisecond);

void BM_LqgSteadyStatePaperZ4(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    const LqgDesign design = designLqg(plant, s.weights);
    for (auto _ : state)
        benchmark::DoNotOptimize(analyseSteadyState(plant, lqgControllerModel(plant, design)));
}
BENCHMARK(BM_LqgSteadyStatePaperZ4)->Unit(benchmark::kMillisecond);

}  // namespace
