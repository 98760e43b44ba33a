#include <benchmark/benchmark.h>

#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/deformation_experiment.h"

namespace {

// The set-up of resources/presets/feed-scheduling.json (copied: the benchmark does not read presets):
// 400 mm shaft to 50 mm, 120 m/min, Kienzle k = 650 N/mm², m = 0.4, kappa 75°, centres 60 / 8 kN/mm,
// cutter 30 kN/mm, micrometer 0.001 mm / 0.002 mm at 95 %; 4 depths x 8 feeds x 38 positions.
tt::core::LatheSetup presetLathe() {
    tt::core::LatheSetup s;
    s.workpiece.lengthMm = 400.0;
    s.workpiece.finishDiameterMm = 50.0;
    s.cutting.cuttingSpeedMPerMin = 120.0;
    s.force.specificForceNPerMm2 = 650.0;
    s.force.exponent = 0.4;
    s.force.leadAngleDeg = 75.0;
    s.stiffness = {60000.0, 8000.0, 30000.0};
    s.micrometer = {0.001, 0.002};
    return s;
}

tt::core::DeformationExperimentPlan presetPlan() {
    tt::core::DeformationExperimentPlan p;
    p.depthsMm = {0.5, 1.0, 1.5, 2.0};
    p.feedsMmPerRev = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
    for (double z = 20.0; z <= 390.0; z += 10.0)
        p.zMm.push_back(z);
    p.seed = 4;
    return p;
}

const tt::core::DeformationSamples& samples() {
    static const tt::core::DeformationSamples s = tt::core::runDeformationExperiment(presetLathe(), presetPlan());
    return s;
}

void BM_DeformationExperiment32Bars(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::runDeformationExperiment(presetLathe(), presetPlan()));
}
BENCHMARK(BM_DeformationExperiment32Bars)->Unit(benchmark::kMillisecond);

void BM_DeformationFitCubicZStepwise1216Rows(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::fitDeformationModel(samples(), tt::core::DeformationTermSet::CubicZ, true));
}
BENCHMARK(BM_DeformationFitCubicZStepwise1216Rows)->Unit(benchmark::kMillisecond);

// What the Feed schedule tab does for every move of the Yc slider: the preset's pass, 41 segments.
void BM_FeedSchedulePresetPass(benchmark::State& state) {
    const tt::core::DeformationFit fit =
        tt::core::fitDeformationModel(samples(), tt::core::DeformationTermSet::CubicZ, true);
    tt::core::FeedScheduleRequest r;
    r.depthMm = 1.5;
    r.feedMinMmPerRev = 0.05;
    r.feedMaxMmPerRev = 0.4;
    r.feedStepMmPerRev = 0.005;
    r.zStartMm = 380.0;
    r.zEndMm = 60.0;
    r.levelFraction = 0.5;
    r.minLengthMm = 5.0;
    std::size_t segments = 0;
    for (auto _ : state) {
        const tt::core::FeedSchedule s = tt::core::scheduleFeed(fit.model, r);
        segments = s.segments.size();
        benchmark::DoNotOptimize(s);
    }
    state.counters["segments"] = static_cast<double>(segments);
}
BENCHMARK(BM_FeedSchedulePresetPass)->Unit(benchmark::kMicrosecond);

}  // namespace
