#include "core/sim/feed_drives/friction_identification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/brent_minimum.h"

namespace tt::core {

namespace {

constexpr double kFactorTolerance = 1e-3;
constexpr int kMaxEvaluations = 30;

// Sum of squared encoder differences of `axis` between the model with its friction scaled and the record.
double mismatch(const FeedDrivesConfig& model, const CornerCostSettings& cost, const PulseSettings& pulse,
                const std::vector<RecordedCorner>& corners, FeedAxis axis, double factor, int traceEvery,
                long& samples) {
    FeedDrivesConfig scaled = model;
    scaleFriction(scaled, axis, factor);
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = traceEvery;
    double sum = 0.0;
    samples = 0;
    for (const RecordedCorner& c : corners) {
        const CornerTrace t = simulateCorner(scaled, cost, c.move, pulse, c.amplitudeV, options).trace;
        const std::vector<double>& simulated = axis == FeedAxis::X ? t.encoderXMm : t.encoderZMm;
        const std::vector<double>& recorded = axis == FeedAxis::X ? c.trace.encoderXMm : c.trace.encoderZMm;
        const std::size_t n = std::min(simulated.size(), recorded.size());
        for (std::size_t i = 0; i < n; ++i)
            sum += (simulated[i] - recorded[i]) * (simulated[i] - recorded[i]);
        samples += static_cast<long>(n);
    }
    return sum;
}

}  // namespace

FrictionEstimate identifyFriction(const FeedDrivesConfig& model, const CornerCostSettings& cost,
                                  const PulseSettings& pulse, const std::vector<RecordedCorner>& corners,
                                  double factorMin, double factorMax, int traceEvery) {
    if (corners.empty()) throw std::invalid_argument("friction identification needs at least one recorded corner");
    if (!(factorMin > 0.0 && factorMin < factorMax))
        throw std::invalid_argument("friction identification: the factor bracket is empty");
    FrictionEstimate e;
    for (FeedAxis axis : {FeedAxis::X, FeedAxis::Z}) {
        long samples = 0;
        const auto f = [&](double factor) {
            return mismatch(model, cost, pulse, corners, axis, factor, traceEvery, samples);
        };
        const ScalarMinimum m = minimiseBrent(f, factorMin, factorMax, kFactorTolerance, kMaxEvaluations);
        f(m.x);  // for the sample count at the optimum
        const double rmsUm = 1e3 * std::sqrt(m.value / static_cast<double>(std::max(samples, 1L)));
        (axis == FeedAxis::X ? e.xFactor : e.zFactor) = m.x;
        (axis == FeedAxis::X ? e.xRmsUm : e.zRmsUm) = rmsUm;
        e.simulations += (m.evaluations + 1) * static_cast<int>(corners.size());
    }
    return e;
}

}  // namespace tt::core
