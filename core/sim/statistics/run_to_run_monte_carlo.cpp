#include "core/sim/statistics/run_to_run_monte_carlo.h"

#include <stdexcept>
#include <string>

#include "core/sim/statistics/stochastic_plant.h"

namespace tt::core {

namespace {

/// Welford's running mean and variance.
struct RunningVariance {
    double mean = 0.0;
    double m2 = 0.0;
    std::int64_t count = 0;
    void add(double x) {
        ++count;
        const double delta = x - mean;
        mean += delta / static_cast<double>(count);
        m2 += delta * (x - mean);
    }
    double variance() const { return count > 1 ? m2 / static_cast<double>(count - 1) : 0.0; }
};

}  // namespace

MonteCarloResult runMonteCarlo(const RunToRunPlant& plant, RunToRunController& controller,
                               const MonteCarloOptions& options) {
    const int m = plant.pointCount();
    if (controller.pointCount() != m)
        throw std::invalid_argument("Monte-Carlo: the controller has " + std::to_string(controller.pointCount()) +
                                    " points, the plant " + std::to_string(m));
    if (options.parts < 2) throw std::invalid_argument("Monte-Carlo: at least 2 parts are needed");
    if (options.warmupParts < 0) throw std::invalid_argument("Monte-Carlo: the warm-up must be >= 0 parts");
    const int z = plant.delay;
    StochasticPlant sim(plant, options.seed);
    std::vector<Eigen::VectorXd> inFlight(static_cast<std::size_t>(z), Eigen::VectorXd::Zero(m));
    PartMeasurement measurement{0, Eigen::VectorXd::Zero(m)};
    std::vector<RunningVariance> open(static_cast<std::size_t>(m)), closed(static_cast<std::size_t>(m));
    MonteCarloResult result;
    const std::int64_t total = options.warmupParts + options.parts;
    for (std::int64_t p = 1; p <= total; ++p) {
        const std::size_t slot = static_cast<std::size_t>(p % z);
        if (p - z >= 1) {
            measurement.partNumber = p - z;
            measurement.deviationMm = inFlight[slot];
            const MeasurementVerdict verdict = controller.addMeasurement(measurement);
            for (bool accepted : verdict.accepted)
                result.rejectedValues += accepted ? 0 : 1;
        }
        const Eigen::VectorXd correction = controller.nextCorrection(p);
        const PartDraw& draw = sim.draw(p);
        const bool counted = p > options.warmupParts;
        for (int i = 0; i < m; ++i) {
            const double d = draw.disturbanceMm(i);
            const double deviation = d + plant.gain(i) * correction(i);
            inFlight[slot](i) = deviation + draw.gaugeNoiseMm(i);
            if (counted) {
                open[static_cast<std::size_t>(i)].add(d);
                closed[static_cast<std::size_t>(i)].add(deviation);
            }
        }
    }
    double sumOpen = 0.0;
    double sumClosed = 0.0;
    for (int i = 0; i < m; ++i) {
        MonteCarloPoint point;
        point.xMm = plant.xMm[static_cast<std::size_t>(i)];
        point.varOpenMm2 = open[static_cast<std::size_t>(i)].variance();
        point.varClosedMm2 = closed[static_cast<std::size_t>(i)].variance();
        point.kEff = point.varOpenMm2 / point.varClosedMm2;
        sumOpen += point.varOpenMm2;
        sumClosed += point.varClosedMm2;
        result.points.push_back(point);
    }
    result.kEff = sumOpen / sumClosed;
    result.parts = options.parts;
    return result;
}

}  // namespace tt::core
