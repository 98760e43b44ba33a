#include "core/sim/feed_drives/corner_training.h"

#include <algorithm>
#include <cmath>

#include "core/common/operation_cancelled.h"

namespace tt::core {

NetInputs netInputs(const CornerMove& m) {
    return {m.x1RadPerS, m.z1RadPerS, m.x2RadPerS, m.z2RadPerS};
}

std::vector<CornerExample> findPulseTargets(const FeedDrivesConfig& drives, const CornerCostSettings& cost,
                                            const PulseSettings& pulse, const PulseSearchSettings& search,
                                            const std::vector<CornerMove>& moves, const CornerProgress& progress) {
    std::vector<CornerExample> out;
    out.reserve(moves.size());
    const int total = static_cast<int>(moves.size());
    for (const CornerMove& m : moves) {
        out.push_back({m, findBestPulse(drives, cost, m, pulse, search)});
        if (progress && !progress("targets", static_cast<int>(out.size()), total)) throw OperationCancelled();
    }
    return out;
}

std::vector<NetSample> toNetSamples(const std::vector<CornerExample>& examples, double weight) {
    std::vector<NetSample> out;
    out.reserve(examples.size());
    for (const CornerExample& e : examples)
        out.push_back({netInputs(e.move), e.optimum.amplitudeV, weight});
    return out;
}

CornerNetTraining trainCornerNet(const CornerScenario& scenario, int moves, unsigned long long seed,
                                 const CornerProgress& progress) {
    validateCornerScenario(scenario);
    const std::vector<CornerMove> drawn = drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, moves, seed);
    std::vector<CornerExample> examples =
        findPulseTargets(scenario.drives, scenario.cost, scenario.pulse, scenario.training.search, drawn, progress);
    NetTrainingSettings settings = scenario.training.network;
    const NetTrainingProgress epochs = [&](int epoch, double, double) {
        return !progress || progress("network", epoch, settings.maxEpochs);
    };
    CorrectiveNet net = trainCorrectiveNet(toNetSamples(examples), settings, epochs);
    return {std::move(net), std::move(examples)};
}

double pulseAmplitudeV(const CorrectiveNet& net, const PulseSettings& pulse, const CornerMove& move) {
    return std::clamp(net.amplitudeV(netInputs(move)), -pulse.limitV, pulse.limitV);
}

AxisPulseSummary summarisePulses(FeedAxis axis, const std::vector<CornerExample>& examples) {
    AxisPulseSummary s;
    s.axis = axis;
    if (examples.empty()) return s;
    for (const CornerExample& e : examples) {
        s.meanAbsAmplitudeV += std::abs(e.optimum.amplitudeV);
        s.meanWithoutMm += e.optimum.without.meanErrorMm;
        s.meanWithMm += e.optimum.with.meanErrorMm;
    }
    const double n = static_cast<double>(examples.size());
    s.meanAbsAmplitudeV /= n;
    s.meanWithoutMm /= n;
    s.meanWithMm /= n;
    s.reductionPct = s.meanWithoutMm > 0.0 ? 100.0 * (1.0 - s.meanWithMm / s.meanWithoutMm) : 0.0;
    return s;
}

}  // namespace tt::core
