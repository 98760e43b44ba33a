// Hot paths of the boring feature (paper 001): one PLC cycle of the force estimator and of the
// compensator, building a linearisation table, and a whole simulated bore.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/calibration/probe_linearisation.h"
#include "core/control/deflection_compensator.h"
#include "core/control/dither_force_estimator.h"
#include "core/run/boring_simulation.h"
#include "core/sim/boring/dither_profile.h"

namespace {

using namespace tt::core;

std::vector<DriveSample> ditherSamples(int count) {
    const DitherProfile profile({0.01, 0.5, 0.6});
    std::vector<DriveSample> out;
    for (int i = 1; i <= count; ++i) {
        const double t = 0.02 * i;
        const DitherState s = profile.at(t);
        const double friction = s.velocityMmPerS > 0 ? 975.0 : (s.velocityMmPerS < 0 ? -975.0 : 0.0);
        out.push_back({t, (friction + 50.0 * s.velocityMmPerS + 300.0) / 150.0, s.velocityMmPerS, s.positionMm});
    }
    return out;
}

// One PLC cycle (20 ms) of the force-from-current estimator with the heavy-boring dither.
void BM_DitherEstimatorCycle(benchmark::State& state) {
    const std::vector<DriveSample> samples = ditherSamples(5000);
    DitherEstimatorConfig config;
    config.currentToForceNPerA = 150.0;
    config.stiffnessNPerMm = 2474.0;
    DitherForceEstimator estimator(config);
    std::size_t i = 0;
    double shift = 0.0;
    for (auto _ : state) {
        DriveSample s = samples[i];
        s.timeS += shift;
        benchmark::DoNotOptimize(estimator.update(s));
        if (++i == samples.size()) {
            i = 0;
            shift += 100.0;
        }
    }
}
BENCHMARK(BM_DitherEstimatorCycle);

// One PLC cycle of the rate- and range-limited compensator.
void BM_CompensatorCycle(benchmark::State& state) {
    DeflectionCompensator c({0.5, 0.05});
    double d = -0.1;
    for (auto _ : state) {
        d = -d;
        benchmark::DoNotOptimize(c.step(0.02, d));
    }
}
BENCHMARK(BM_CompensatorCycle);

// Fit (auto degree, LOO for 2..4) and table of 2^bits entries from 41 points.
void BM_Linearise(benchmark::State& state) {
    const int bits = static_cast<int>(state.range(0));
    const double mid = std::ldexp(1.0, bits - 1);
    const double gain = mid * 0.7 / 500.0;  // ±500 µm spans ±79 % of the codes
    std::vector<CalibrationPoint> points;
    for (int i = 0; i <= 40; ++i) {
        const double um = -500.0 + 25.0 * i;
        points.push_back({um, mid + gain * (um + 0.5e-6 * um * um * um), 0});
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(linearise(points, bits, kAutoDegree));
}
BENCHMARK(BM_Linearise)->Arg(10)->Arg(12)->Arg(16)->Unit(benchmark::kMillisecond);

// A whole 500 mm bore of the heavy-boring scenario (about 26 000 PLC cycles, 5.3 million drive steps).
void BM_BoringRun(benchmark::State& state) {
    BoringScenario s;
    s.tool.id = "T12";
    s.tool.section = HolderSection::round(80.0);
    s.tool.overhangMm = 800.0;
    s.tool.youngsModulusMpa = 210'000.0;
    s.tool.currentToForceGainNPerA = 150.0;
    s.trueStiffnessFactor = 0.97;
    s.dither = DitherConfig{0.01, 0.5, 0.6};
    s.limits = CompensatorLimits{0.5, 0.05};
    const BoringMethod method = static_cast<BoringMethod>(state.range(0));
    for (auto _ : state)
        benchmark::DoNotOptimize(runBoring(s, method));
}
BENCHMARK(BM_BoringRun)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
