#include "core/run/run_to_run_timing.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "core/sim/statistics/run_to_run_monte_carlo.h"
#include "core/sim/statistics/stochastic_plant.h"

namespace tt::core {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point from) {
    return std::chrono::duration<double>(Clock::now() - from).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Runs `batch(count)` in batches sized to ~1/10 of the budget; returns the median seconds per item.
template <typename Batch>
double secondsPerItem(double budget, Batch&& batch) {
    long long count = 1;
    for (;;) {  // size a batch to about budget / 10
        const Clock::time_point t0 = Clock::now();
        batch(count);
        if (seconds(t0) >= budget / 10.0 || count >= (1LL << 40)) break;
        count *= 4;
    }
    std::vector<double> perItem;
    const Clock::time_point start = Clock::now();
    while (perItem.size() < 5 || (seconds(start) < budget && perItem.size() < 50)) {
        const Clock::time_point t0 = Clock::now();
        batch(count);
        perItem.push_back(seconds(t0) / static_cast<double>(count));
    }
    return median(perItem);
}

}  // namespace

RunToRunTimings measureRunToRunHotPaths(const RunToRunSetup& setup, double secondsPerPath) {
    const RunToRunPlant plant = buildRunToRunPlant(setup.plant);
    RunToRunTimings t;
    t.points = plant.pointCount();
    t.delay = plant.delay;
    t.states = static_cast<long long>(plant.stateCount());

    volatile double sink = 0.0;
    t.lqgSynthesisUs = 1e6 * secondsPerItem(secondsPerPath, [&](long long n) {
                           for (long long i = 0; i < n; ++i)
                               sink = sink + designLqg(plant, setup.weights).K(0, 0);
                       });

    // Controller update on a recorded closed-loop-like stream of measurements.
    const LqgDesign design = designLqg(plant, setup.weights);
    LqgController controller(plant, design, setup.limits, setup.lqg);
    StochasticPlant source(plant, 7);
    std::int64_t part = 0;
    PartMeasurement measurement{0, Eigen::VectorXd::Zero(plant.pointCount())};
    std::vector<Eigen::VectorXd> inFlight(static_cast<std::size_t>(plant.delay), Eigen::VectorXd::Zero(t.points));
    t.controllerUpdateUs = 1e6 * secondsPerItem(secondsPerPath, [&](long long n) {
                               for (long long i = 0; i < n; ++i) {
                                   ++part;
                                   const std::size_t slot = static_cast<std::size_t>(part % plant.delay);
                                   if (part > plant.delay) {
                                       measurement.partNumber = part - plant.delay;
                                       measurement.deviationMm = inFlight[slot];
                                       controller.addMeasurement(measurement);
                                   }
                                   const Eigen::VectorXd u = controller.nextCorrection(part);
                                   inFlight[slot] = source.draw(part).disturbanceMm + plant.gain.cwiseProduct(u);
                               }
                           });

    StochasticPlant sim(plant, 11);
    std::int64_t simPart = 0;
    t.simPartStepsPerS = 1.0 / secondsPerItem(secondsPerPath, [&](long long n) {
                             for (long long i = 0; i < n; ++i)
                                 sink = sink + sim.draw(++simPart).disturbanceMm(0);
                         });

    MonteCarloOptions mc;
    mc.parts = 20000;
    mc.warmupParts = 0;
    t.monteCarloPartsPerS = 1.0 /
                            secondsPerItem(secondsPerPath,
                                           [&](long long n) {
                                               for (long long i = 0; i < n; ++i) {
                                                   LqgController c(plant, design, setup.limits, setup.lqg);
                                                   mc.seed = static_cast<std::uint64_t>(i + 1);
                                                   sink = sink + runMonteCarlo(plant, c, mc).kEff;
                                               }
                                           }) *
                            static_cast<double>(mc.parts);
    return t;
}

}  // namespace tt::core
