#include "core/run/stored_run_tuning.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tt::core {

namespace {

/// The deviation the controller used at each point of a stored part (NaN elsewhere).
Eigen::VectorXd usedDeviations(const StoredPart& part, std::size_t points) {
    Eigen::VectorXd d =
        Eigen::VectorXd::Constant(static_cast<Eigen::Index>(points), std::numeric_limits<double>::quiet_NaN());
    if (!part.measurement) return d;
    for (const PointMeasurementRecord& p : part.measurement->points)
        if (p.accepted && p.measuredMm && p.pointIndex >= 0 && static_cast<std::size_t>(p.pointIndex) < points)
            d(p.pointIndex) = *p.measuredMm - p.nominalMm;
    return d;
}

SteadyStateVariances onPlant(const RunToRunPlant& truth, const RunToRunSetup& setup) {
    const RunToRunPlantSpec spec = designPlantSpec(setup);
    const RunToRunPlant design =
        buildRunToRunPlant(setup.integral.enabled ? withIntegralAction(spec, setup.integral) : spec);
    return analyseSteadyState(truth, lqgControllerModel(design, designLqg(design, setup.weights)));
}

}  // namespace

LoopHistory storedLoopHistory(HistoryStore& history, std::int64_t runId, std::optional<std::int64_t> lastParts) {
    bool known = false;
    for (const RunSummary& r : history.runs())
        known = known || r.runId == runId;
    if (!known) throw std::invalid_argument("the history has no run " + std::to_string(runId));
    const std::vector<StoredPart> parts = history.parts(runId);
    if (parts.empty()) throw IdentificationRefused("run " + std::to_string(runId) + " has no stored part", 0);
    std::size_t first = 0;
    // The newest stretch of consecutive part numbers (a resumed run has them all; a gap starts the record again).
    for (std::size_t i = 1; i < parts.size(); ++i)
        if (parts[i].partNumber != parts[i - 1].partNumber + 1) first = i;
    if (lastParts && static_cast<std::int64_t>(parts.size() - first) > *lastParts)
        first = parts.size() - static_cast<std::size_t>(*lastParts);
    const std::size_t points = parts.front().corrections.size();
    LoopHistory h;
    h.firstPart = parts[first].partNumber;
    for (std::size_t i = first; i < parts.size(); ++i) {
        Eigen::VectorXd applied(static_cast<Eigen::Index>(points));
        for (std::size_t k = 0; k < points; ++k)
            applied(static_cast<Eigen::Index>(k)) = k < parts[i].corrections.size()
                                                        ? parts[i].corrections[k].appliedMm
                                                        : std::numeric_limits<double>::quiet_NaN();
        h.appliedMm.push_back(applied);
        h.deviationMm.push_back(usedDeviations(parts[i], points));
    }
    return h;
}

StoredRunTuning tuneFromStoredRun(HistoryStore& history, std::int64_t runId, const RunToRunSetup& setup,
                                  const AdaptationConfig& config, std::optional<std::int64_t> lastParts) {
    const LoopHistory h = storedLoopHistory(history, runId, lastParts);
    StoredRunTuning t;
    t.runId = runId;
    t.firstPart = h.firstPart;
    t.lastPart = h.firstPart + static_cast<std::int64_t>(h.size()) - 1;
    t.identification = identifyPlant(h, config.identification(setup.plant.delay, designPlantSpec(setup)));
    const std::string source =
        "run " + std::to_string(runId) + ", parts " + std::to_string(t.firstPart) + " .. " + std::to_string(t.lastPart);
    t.model = modelRecord(t.identification, source);
    t.design = designAdapted(setup, t.identification, source, config.minGainMargin);
    // The identified plant as the truth: its delay z + lag, gains and disturbances.
    const RunToRunPlant truth = buildRunToRunPlant(designPlantSpec(t.design.setup));
    t.current = onPlant(truth, setup);
    t.adapted = onPlant(truth, t.design.setup);
    t.ewmaWeight = bestEwmaWeight(truth, defaultEwmaWeightGrid()).weight;
    t.ewma = analyseSteadyState(truth, ewmaControllerModel(truth, t.ewmaWeight));
    return t;
}

}  // namespace tt::core
