#include "core/sim/feed_drives/corner_retraining.h"

#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

CornerRetrainEvent retrainOnCorners(const CornerScenario& scenario, FeedDrivesConfig& model, CorrectiveNet& net,
                                    std::vector<NetSample>& oldSet, const std::vector<RecordedCorner>& corners,
                                    int move, const std::string& why, const CornerProgress& progress) {
    if (corners.empty()) throw std::invalid_argument("retraining needs at least one recorded corner");
    const CornerRetrainSettings& r = scenario.retraining;
    CornerRetrainEvent event;
    event.move = move;
    event.corners = static_cast<int>(corners.size());
    event.friction = identifyFriction(model, scenario.cost, scenario.pulse, corners, r.frictionFactorMin,
                                      r.frictionFactorMax, kCornerRecordEvery);
    scaleFriction(model, FeedAxis::X, event.friction.xFactor);
    scaleFriction(model, FeedAxis::Z, event.friction.zFactor);
    std::vector<CornerMove> moves;
    for (const RecordedCorner& c : corners)
        moves.push_back(c.move);
    const std::vector<CornerExample> examples =
        findPulseTargets(model, scenario.cost, scenario.pulse, scenario.training.search, moves);
    std::vector<NetSample> samples = toNetSamples(examples, 1.0);
    for (NetSample s : oldSet) {
        s.weight *= r.oldSetWeight;
        samples.push_back(s);
    }
    const NetTrainingSettings& settings = scenario.training.network;
    const NetTrainingProgress epochs = [&](int epoch, double, double) {
        return !progress || progress("retraining", epoch, settings.maxEpochs);
    };
    net = retrainCorrectiveNet(net, samples, settings, epochs);
    const std::size_t earlier = oldSet.size();
    for (const NetSample& s : toNetSamples(examples, 1.0))
        oldSet.push_back(s);
    event.reason = why + "; friction identified from " + std::to_string(corners.size()) + " corners: X x" +
                   formatFixed(event.friction.xFactor, 3) + ", Z x" + formatFixed(event.friction.zFactor, 3) +
                   "; network retrained on them and " + std::to_string(earlier) + " earlier samples weighted " +
                   formatFixed(r.oldSetWeight, 2);
    return event;
}

}  // namespace tt::core
