#include "core/sim/feed_drives/corner_work_run.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>

#include "core/common/operation_cancelled.h"
#include "core/sim/shaft/lathe_random.h"
#include "core/sim/statistics/normal_stream.h"

namespace tt::core {

namespace {

double uniform01(std::mt19937_64& engine) {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

double meanError(const std::vector<CornerWorkMove>& moves, std::size_t from, bool with) {
    double sum = 0.0;
    for (std::size_t i = from; i < moves.size(); ++i)
        sum += with ? moves[i].with.meanErrorMm : moves[i].without.meanErrorMm;
    return moves.size() > from ? sum / static_cast<double>(moves.size() - from) : 0.0;
}

double reduction(const std::vector<CornerWorkMove>& moves, std::size_t from) {
    const double without = meanError(moves, from, false);
    return without > 0.0 ? 100.0 * (1.0 - meanError(moves, from, true) / without) : 0.0;
}

}  // namespace

CornerMachine machineForCorner(const FeedDrivesConfig& base, const MachineVariation& variation, int index) {
    const std::uint64_t seed = splitMix64(splitMix64(variation.seed) ^ static_cast<std::uint64_t>(index));
    NormalStream normals(seed);
    std::mt19937_64 engine(splitMix64(seed));
    CornerMachine m{base, std::nullopt};
    // Within four standard deviations (and never below half): a drift the run accepted stays runnable.
    const auto scatter = [&] {
        return std::clamp(1.0 + variation.frictionScatter * normals.next(), 0.5, 1.0 + 4.0 * variation.frictionScatter);
    };
    scaleFriction(m.drives, FeedAxis::X, scatter());
    scaleFriction(m.drives, FeedAxis::Z, scatter());
    if (uniform01(engine) < variation.outlierProbability) {
        LoadTorquePulse load;
        load.axis = FeedAxis::Z;
        load.startS = -0.02 + 0.1 * uniform01(engine);
        load.durationS = variation.outlierDurationS;
        load.torqueNm = (uniform01(engine) < 0.5 ? 1.0 : -1.0) * variation.outlierTorqueNm;
        m.load = load;
    }
    return m;
}

CornerWorkResult runCornerWork(const CornerScenario& scenario, CorrectiveNet& net, std::vector<NetSample> oldSet,
                               const std::vector<CornerMove>& moves, const CornerDrift& drift, bool retrain,
                               const CornerProgress& progress) {
    validateCornerScenario(scenario);
    CornerWorkResult result;
    const int count = static_cast<int>(moves.size());
    if (drift.factor != 1.0) result.driftAtMove = drift.atMove < 0 ? count / 2 : drift.atMove;
    const FeedDrivesConfig drifted =
        drift.factor != 1.0 ? scaledDrives(scenario.drives, driftFactors(drift.kind, drift.axis, drift.factor))
                            : scenario.drives;
    FeedDrivesFactors modelFactors;
    FeedDrivesConfig model = scenario.drives;
    CornerDriftMonitor monitor(scenario.retraining.monitor);
    std::deque<RecordedCorner> recent;
    CornerSimulationOptions recordOptions;
    recordOptions.keepTrace = true;
    recordOptions.traceEvery = kCornerRecordEvery;
    for (int i = 0; i < count; ++i) {
        const CornerMove& move = moves[static_cast<std::size_t>(i)];
        const bool isDrifted = result.driftAtMove >= 0 && i >= result.driftAtMove;
        const CornerMachine machine = machineForCorner(isDrifted ? drifted : scenario.drives, scenario.machine, i);
        CornerWorkMove m;
        m.move = move;
        m.hitByLoad = machine.load.has_value();
        m.amplitudeV = pulseAmplitudeV(net, scenario.pulse, move);
        CornerSimulationOptions options = recordOptions;
        options.disturbance = machine.load;
        const CornerRun with =
            simulateCorner(machine.drives, scenario.cost, move, scenario.pulse, m.amplitudeV, options);
        options.keepTrace = false;
        m.with = with.cost;
        m.without = simulateCorner(machine.drives, scenario.cost, move, scenario.pulse, 0.0, options).cost;
        m.predicted = simulateCorner(model, scenario.cost, move, scenario.pulse, m.amplitudeV).cost;
        result.moves.push_back(m);
        monitor.add(m.predicted.cost, m.with.cost);
        recent.push_back({move, m.amplitudeV, with.trace});
        while (static_cast<int>(recent.size()) > monitor.settings().windowCorners)
            recent.pop_front();
        const DriftCheck check = monitor.check();
        result.checks.push_back(check);
        if (retrain && check.retrain) {
            // The corners since the change the monitor sees, misses among them left out.
            const int from = monitor.changeStart((monitor.settings().windowCorners + 1) / 2);
            const std::vector<bool> outliers = monitor.outlierFlagsFrom(from);
            std::vector<RecordedCorner> kept;
            for (std::size_t k = static_cast<std::size_t>(from); k < recent.size(); ++k)
                if (!outliers[k]) kept.push_back(recent[k]);
            result.retrains.push_back(
                retrainOnCorners(scenario, modelFactors, net, oldSet, kept, i, check.reason, progress));
            model = scaledDrives(scenario.drives, modelFactors);
            monitor.clear();
            recent.clear();
        }
        if (progress && !progress("work", i + 1, count)) throw OperationCancelled();
    }
    result.model = modelFactors;
    result.samples = std::move(oldSet);
    const std::vector<bool> outliers = monitor.outlierFlags();
    for (std::size_t k = 0; k < recent.size(); ++k)
        if (!outliers[k]) result.recent.push_back(recent[k]);
    result.meanWithoutMm = meanError(result.moves, 0, false);
    result.meanWithMm = meanError(result.moves, 0, true);
    result.reductionPct = reduction(result.moves, 0);
    if (!result.retrains.empty()) {
        const auto from = static_cast<std::size_t>(result.retrains.front().move) + 1;
        if (from < result.moves.size()) result.reductionAfterRetrainPct = reduction(result.moves, from);
    }
    return result;
}

}  // namespace tt::core
