// Run-to-run LQG hot paths (docs/BENCHMARKS.md): synthesis for the paper plant at z = 4, the controller
// update per part, the statistical plant, the Monte-Carlo loop, and the scaling of synthesis with the
// number of states.
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "core/control/kalman_filter.h"
#include "core/control/lq_regulator.h"
#include "core/control/lqg_controller.h"
#include "core/control/lqg_design.h"
#include "core/control/run_to_run_setup.h"
#include "core/linalg/dare.h"
#include "core/sim/statistics/run_to_run_monte_carlo.h"
#include "core/sim/statistics/stochastic_plant.h"

namespace {

using namespace tt::core;

/// The paper-2012 scenario (resources/presets/paper-2012.json, calibration in docs/DECISIONS.md) with
/// `points` control points (5 in the paper) and delay z.
RunToRunSetup paperSetup(int delay, int points = 5) {
    RunToRunSetup s;
    s.plant.delay = delay;
    const DisturbanceModel d({DisturbanceComponent::shapingFilterWithVariance(
        ShapingFilter::fromRoots({1.0, 0.246}, {{0.9215, 0.0}}), 0.0013)});
    for (int i = 0; i < points; ++i)
        s.plant.points.push_back(ControlPointSpec{325.0 * i / std::max(1, points - 1), 2.0, d, 2.5e-7});
    s.weights = {Eigen::MatrixXd::Identity(points, points), 0.01 * Eigen::MatrixXd::Identity(points, points)};
    s.limits = {0.3, 0.1};
    return s;
}

void BM_LqgSynthesisPaperZ4(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    for (auto _ : state)
        benchmark::DoNotOptimize(designLqg(plant, s.weights));
    state.counters["states"] = static_cast<double>(plant.stateCount());
}
BENCHMARK(BM_LqgSynthesisPaperZ4)->Unit(benchmark::kMicrosecond);

// The same plant through lqry + kalman on the whole 30-state plant (no structure exploited).
void BM_LqgSynthesisPaperZ4WholePlant(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    for (auto _ : state)
        benchmark::DoNotOptimize(designLqgDense(plant, s.weights));
}
BENCHMARK(BM_LqgSynthesisPaperZ4WholePlant)->Unit(benchmark::kMicrosecond);

// One part of the controller: the measurement of part p - z arrives, the correction of part p is computed.
void BM_LqgControllerUpdatePaperZ4(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    LqgController controller(plant, designLqg(plant, s.weights), s.limits);
    // A recorded disturbance (4096 parts, reused cyclically) so that only the controller is timed.
    StochasticPlant source(plant, 3);
    std::vector<Eigen::VectorXd> disturbance;
    for (int p = 1; p <= 4096; ++p)
        disturbance.push_back(source.draw(p).disturbanceMm);
    std::vector<Eigen::VectorXd> inFlight(4, Eigen::VectorXd::Zero(5));
    PartMeasurement m{0, Eigen::VectorXd::Zero(5)};
    std::int64_t part = 0;
    for (auto _ : state) {
        ++part;
        const std::size_t slot = static_cast<std::size_t>(part % 4);
        if (part > 4) {
            m.partNumber = part - 4;
            m.deviationMm = inFlight[slot];
            benchmark::DoNotOptimize(controller.addMeasurement(m));
        }
        const Eigen::VectorXd u = controller.nextCorrection(part);
        inFlight[slot] = disturbance[static_cast<std::size_t>(part % 4096)] + plant.gain.cwiseProduct(u);
    }
}
BENCHMARK(BM_LqgControllerUpdatePaperZ4)->Unit(benchmark::kNanosecond);

// One part of the statistical plant (5 points: disturbance filters and gauge noise).
void BM_StochasticPlantPart(benchmark::State& state) {
    const RunToRunPlant plant = buildRunToRunPlant(paperSetup(4).plant);
    StochasticPlant sim(plant, 5);
    std::int64_t part = 0;
    for (auto _ : state)
        benchmark::DoNotOptimize(sim.draw(++part).disturbanceMm(0));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_StochasticPlantPart)->Unit(benchmark::kNanosecond);

// The closed-loop Monte-Carlo run of `simulate` (20 000 parts, LQG, z = 4).
void BM_MonteCarloLqg20000Parts(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(4);
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    const LqgDesign design = designLqg(plant, s.weights);
    MonteCarloOptions o;
    o.parts = 20000;
    for (auto _ : state) {
        LqgController c(plant, design, s.limits);
        benchmark::DoNotOptimize(runMonteCarlo(plant, c, o));
    }
    state.SetItemsProcessed(state.iterations() * (o.parts + o.warmupParts));
}
BENCHMARK(BM_MonteCarloLqg20000Parts)->Unit(benchmark::kMillisecond);

// Scaling, structured: run-to-run plants of `points` points at z = 8 (n = points * (8 + 2) states).
void BM_LqgSynthesisRunToRunScaling(benchmark::State& state) {
    const RunToRunSetup s = paperSetup(8, static_cast<int>(state.range(0)));
    const RunToRunPlant plant = buildRunToRunPlant(s.plant);
    for (auto _ : state)
        benchmark::DoNotOptimize(designLqg(plant, s.weights));
    state.counters["states"] = static_cast<double>(plant.stateCount());
}
BENCHMARK(BM_LqgSynthesisRunToRunScaling)->Arg(1)->Arg(2)->Arg(5)->Arg(10)->Arg(16)->Unit(benchmark::kMicrosecond);

// Scaling, dense: LQG synthesis (LQ Riccati + filter Riccati by SDA) of a random stable system with n
// states, 5 inputs and 5 outputs (spectral radius 0.9), n = 10 .. 400.
void BM_LqgSynthesisDenseScaling(benchmark::State& state) {
    const Eigen::Index n = state.range(0);
    std::mt19937_64 engine(42);
    std::normal_distribution<double> normal;
    auto random = [&](Eigen::Index r, Eigen::Index c) {
        Eigen::MatrixXd m(r, c);
        for (Eigen::Index i = 0; i < m.size(); ++i)
            m.data()[i] = normal(engine);
        return m;
    };
    Eigen::MatrixXd A = random(n, n);
    A *= 0.9 / Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues().cwiseAbs().maxCoeff();
    const Eigen::MatrixXd B = random(n, 5);
    const Eigen::MatrixXd C = random(5, n);
    const Eigen::MatrixXd I5 = Eigen::MatrixXd::Identity(5, 5);
    for (auto _ : state) {
        benchmark::DoNotOptimize(lqry(A, B, C, Eigen::MatrixXd::Zero(5, 5), I5, I5));
        benchmark::DoNotOptimize(
            designKalman(A, C, Eigen::MatrixXd::Identity(n, n), 0.01 * Eigen::MatrixXd::Identity(n, n), I5));
    }
}
BENCHMARK(BM_LqgSynthesisDenseScaling)
    ->Arg(10)
    ->Arg(20)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Unit(benchmark::kMillisecond);

}  // namespace
