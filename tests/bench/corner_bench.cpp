// Speed of the corrective-pulse work (paper 002): one simulated corner (about 3 000 steps of 0.1 ms
// for both drives), the bracketed amplitude search of one training move, one network epoch.
#include <benchmark/benchmark.h>

#include "core/control/corrective_net_training.h"
#include "core/sim/feed_drives/corner_training.h"

namespace {

using namespace tt::core;

void BM_CornerSimulation(benchmark::State& state) {
    const CornerScenario s;
    const CornerMove move{7.0, 2.5, 1.5, 7.0};
    for (auto _ : state)
        benchmark::DoNotOptimize(simulateCorner(s.drives, s.cost, move, s.pulse, 0.1).cost.cost);
}
BENCHMARK(BM_CornerSimulation);

void BM_CornerBestPulse(benchmark::State& state) {
    const CornerScenario s;
    const CornerMove move{7.0, 2.5, 1.5, 7.0};
    for (auto _ : state)
        benchmark::DoNotOptimize(findBestPulse(s.drives, s.cost, move, s.pulse, s.training.search).amplitudeV);
}
BENCHMARK(BM_CornerBestPulse)->Unit(benchmark::kMillisecond);

void BM_CornerNetEpochs(benchmark::State& state) {
    std::vector<NetSample> samples;
    for (const CornerMove& m : drawCornerMoves({}, {}, 200, 1))
        samples.push_back({netInputs(m), 0.05 * (m.x1RadPerS - m.x2RadPerS), 1.0});
    NetTrainingSettings settings;
    settings.maxEpochs = 100;
    settings.patience = 100;
    for (auto _ : state)
        benchmark::DoNotOptimize(trainCorrectiveNet(samples, settings).record().epochs);
}
BENCHMARK(BM_CornerNetEpochs)->Unit(benchmark::kMillisecond);

}  // namespace
