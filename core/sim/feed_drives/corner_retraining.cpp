#include "core/sim/feed_drives/corner_retraining.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/operation_cancelled.h"
#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kStalledCostMm = 1000.0;  // a corner the network in use cannot run counts as 1 m of cost
constexpr unsigned long long kValidationSeedOffset = 1000000;

std::string micrometres(double mm) {
    return formatSignificant(mm * 1e3, 3) + " µm";
}

CornerMove moveOf(const NetSample& s) {
    return {s.speedsRadPerS[0], s.speedsRadPerS[1], s.speedsRadPerS[2], s.speedsRadPerS[3]};
}

// The stage name of the re-targeting for progress reports (findPulseTargets reports "targets").
CornerProgress renamed(const CornerProgress& progress, const std::string& stage) {
    if (!progress) return {};
    return [progress, stage](const std::string&, int done, int total) { return progress(stage, done, total); };
}

std::string identifiedText(const CornerRetrainEvent& e) {
    std::string text = "drives identified from " + std::to_string(e.corners) +
                       " corners: " + describeFactors(e.identified.factors, 3) + " (encoder RMS X " +
                       formatFixed(e.identified.xRmsUm, 2) + " µm, Z " + formatFixed(e.identified.zRmsUm, 2) + " µm)";
    if (!e.modelUpdated) text += ", no closer to the records than the model's: the model is kept";
    return text;
}

struct Targets {
    std::vector<CornerExample> recent;
    std::vector<CornerExample> earlier;
};

// The best amplitude of each recorded corner and each earlier training move on `drives`.
Targets retarget(const CornerScenario& s, const FeedDrivesConfig& drives, const std::vector<RecordedCorner>& corners,
                 const std::vector<NetSample>& trainingSet, const CornerProgress& progress) {
    std::vector<CornerMove> moves;
    for (const RecordedCorner& c : corners)
        moves.push_back(c.move);
    for (const NetSample& sample : trainingSet)
        moves.push_back(moveOf(sample));
    std::vector<CornerExample> all =
        findPulseTargets(drives, s.cost, s.pulse, s.training.search, moves, renamed(progress, "retargeting"));
    const auto split = all.begin() + static_cast<std::ptrdiff_t>(corners.size());
    return {std::vector<CornerExample>(all.begin(), split), std::vector<CornerExample>(split, all.end())};
}

CorrectiveNet trainCandidate(const CornerScenario& s, const CorrectiveNet& net, const Targets& targets,
                             const CornerProgress& progress) {
    std::vector<NetSample> samples = toNetSamples(targets.recent, 1.0);
    for (const NetSample& sample : toNetSamples(targets.earlier, s.retraining.oldSetWeight))
        samples.push_back(sample);
    const NetTrainingSettings& settings = s.training.network;
    const NetTrainingProgress epochs = [&](int epoch, double, double) {
        return !progress || progress("retraining", epoch, settings.maxEpochs);
    };
    return retrainCorrectiveNet(net, samples, settings, epochs);
}

std::string verdictText(const CornerRetrainEvent& e, double oldSetWeight) {
    const CandidateVerdict& v = e.verdict;
    if (!v.accepted) return "the retrained network was refused: " + v.failure + "; the network in use is kept";
    return "network retrained on them and " + std::to_string(e.retargetedMoves) +
           " earlier moves re-targeted on the model (weight " + formatFixed(oldSetWeight, 2) + "): validation cost " +
           micrometres(v.keptCostMm) + " -> " + micrometres(v.candidateCostMm);
}

}  // namespace

CandidateVerdict judgeCandidate(const FeedDrivesConfig& model, const CornerCostSettings& cost,
                                const PulseSettings& pulse, const CorrectiveNet& kept, const CorrectiveNet& candidate,
                                const std::vector<CornerMove>& moves) {
    if (moves.empty()) throw std::invalid_argument("judging a candidate network needs at least one move");
    CandidateVerdict v;
    double keptSum = 0.0;
    double candidateSum = 0.0;
    for (const CornerMove& m : moves) {
        try {
            keptSum += simulateCorner(model, cost, m, pulse, pulseAmplitudeV(kept, pulse, m)).cost.cost;
        } catch (const std::runtime_error&) {
            keptSum += kStalledCostMm;
        }
        const double amplitudeV = pulseAmplitudeV(candidate, pulse, m);
        try {
            const CornerRun run = simulateCorner(model, cost, m, pulse, amplitudeV);
            candidateSum += run.cost.cost;
            v.candidatePeakCurrentA = std::max(v.candidatePeakCurrentA, run.pulseCurrentPeakA);
        } catch (const std::runtime_error& e) {
            v.failure = "its pulse of " + formatFixed(amplitudeV, 3) + " V: " + e.what();
            return v;
        }
    }
    const double n = static_cast<double>(moves.size());
    v.keptCostMm = keptSum / n;
    v.candidateCostMm = candidateSum / n;
    const double limitA = axisConfig(model, pulse.axis).currentLimitA;
    if (v.candidatePeakCurrentA >= limitA * (1.0 - 1e-9))
        v.failure = std::string("its pulses drive the ") + (pulse.axis == FeedAxis::X ? "X" : "Z") +
                    " motor to its current limit of " + formatSignificant(limitA, 4) + " A";
    else if (!(v.candidateCostMm < v.keptCostMm))
        v.failure = "its validation cost " + micrometres(v.candidateCostMm) + " is not below the " +
                    micrometres(v.keptCostMm) + " of the network in use";
    else
        v.accepted = true;
    return v;
}

CornerRetrainEvent retrainOnCorners(const CornerScenario& scenario, FeedDrivesFactors& model, CorrectiveNet& net,
                                    std::vector<NetSample>& trainingSet, const std::vector<RecordedCorner>& corners,
                                    int move, const std::string& why, const CornerProgress& progress) {
    if (corners.empty()) throw std::invalid_argument("retraining needs at least one recorded corner");
    const CornerRetrainSettings& r = scenario.retraining;
    CornerRetrainEvent event;
    event.move = move;
    event.corners = static_cast<int>(corners.size());
    event.reason = why;
    FeedDrivesFactors updated = model;
    try {
        event.identified = identifyDrives(scenario.drives, model, scenario.cost, scenario.pulse, corners,
                                          r.identification, kCornerRecordEvery);
        if (progress && !progress("identification", 1, 1)) throw OperationCancelled();
        const FeedDrivesConfig before = scaledDrives(scenario.drives, model);
        const double beforeUm =
            encoderMismatchUm(before, scenario.cost, scenario.pulse, corners, FeedAxis::X, kCornerRecordEvery) +
            encoderMismatchUm(before, scenario.cost, scenario.pulse, corners, FeedAxis::Z, kCornerRecordEvery);
        event.modelUpdated = event.identified.xRmsUm + event.identified.zRmsUm < beforeUm;
        if (event.modelUpdated) updated = event.identified.factors;
        event.reason += "; " + identifiedText(event);
        const FeedDrivesConfig drives = scaledDrives(scenario.drives, updated);
        const Targets targets = retarget(scenario, drives, corners, trainingSet, progress);
        event.retargetedMoves = static_cast<int>(targets.earlier.size());
        const CorrectiveNet candidate = trainCandidate(scenario, net, targets, progress);
        const std::vector<CornerMove> validation = drawCornerMoves(
            scenario.xSpeeds, scenario.zSpeeds, r.validationMoves,
            scenario.training.seed + kValidationSeedOffset + static_cast<unsigned long long>(std::max(move, 0)));
        event.verdict = judgeCandidate(drives, scenario.cost, scenario.pulse, net, candidate, validation);
        event.reason += "; " + verdictText(event, r.oldSetWeight);
        model = updated;
        if (!event.verdict.accepted) return event;
        net = candidate;
        trainingSet = toNetSamples(targets.earlier, 1.0);
        for (const NetSample& s : toNetSamples(targets.recent, 1.0))
            trainingSet.push_back(s);
    } catch (const OperationCancelled&) {
        throw;
    } catch (const std::exception& e) {
        event.verdict = CandidateVerdict{};
        event.verdict.failure = std::string("the retraining failed: ") + e.what();
        event.reason += "; " + event.verdict.failure + "; the network in use and the model are kept";
    }
    return event;
}

}  // namespace tt::core
