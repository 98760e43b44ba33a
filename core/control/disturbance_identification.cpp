#include "core/control/disturbance_identification.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

/// d(k) of one part at the point, none when the controller did not use a reading there.
std::optional<double> partDisturbance(const StoredPart& part, int point, double gain) {
    if (!part.measurement) return std::nullopt;
    const auto i = static_cast<std::size_t>(point);
    if (i >= part.measurement->points.size() || i >= part.corrections.size()) return std::nullopt;
    const PointMeasurementRecord& m = part.measurement->points[i];
    if (!m.accepted || !m.measuredMm || !std::isfinite(*m.measuredMm)) return std::nullopt;
    return *m.measuredMm - m.nominalMm - gain * part.corrections[i].appliedMm;
}

}  // namespace

DisturbanceSeries storedDisturbance(HistoryStore& history, std::optional<std::int64_t> runId, int point, double gain) {
    if (!std::isfinite(gain) || gain <= 0.0 || gain > 100.0)
        throw std::invalid_argument("the gain k_i must be in (0, 100] (2 = radial move to diameter)");
    if (!runId) {
        const std::vector<RunSummary> runs = history.runs();
        if (runs.empty()) throw std::invalid_argument("the history holds no run");
        std::int64_t newest = runs.front().runId;
        for (const RunSummary& r : runs)
            newest = std::max(newest, r.runId);
        runId = newest;
    }
    const std::vector<StoredPart> parts = history.parts(*runId);
    if (parts.empty()) throw std::invalid_argument("run " + std::to_string(*runId) + " has no stored part");
    const std::size_t points = parts.front().corrections.size();
    if (point < 0 || static_cast<std::size_t>(point) >= points)
        throw std::invalid_argument("run " + std::to_string(*runId) + " has control points 1 .. " +
                                    std::to_string(points) + ", not " + std::to_string(point + 1));
    std::map<std::int64_t, double> values;
    for (const StoredPart& part : parts)
        if (const auto d = partDisturbance(part, point, gain)) values[part.partNumber] = *d;
    DisturbanceSeries best{*runId, point, 0, 0, {}, parts.size()};
    DisturbanceSeries current = best;
    std::int64_t previous = 0;
    for (const auto& [partNumber, d] : values) {
        if (current.valuesMm.empty() || partNumber != previous + 1) {
            current.valuesMm.clear();
            current.firstPart = partNumber;
        }
        current.valuesMm.push_back(d);
        current.lastPart = partNumber;
        previous = partNumber;
        if (current.valuesMm.size() > best.valuesMm.size()) best = current;
    }
    if (best.valuesMm.size() < kMinArmaValues)
        throw std::invalid_argument("run " + std::to_string(*runId) + ", point " + std::to_string(point + 1) +
                                    ": the longest stretch of consecutive measured parts is " +
                                    std::to_string(best.valuesMm.size()) + ", an identification needs " +
                                    std::to_string(kMinArmaValues));
    return best;
}

DisturbanceIdentification identifyStoredDisturbance(HistoryStore& history, std::optional<std::int64_t> runId, int point,
                                                    ArmaOrders orders, double gain) {
    DisturbanceIdentification out;
    out.series = storedDisturbance(history, runId, point, gain);
    out.fit = fitArma(out.series.valuesMm, orders);
    return out;
}

}  // namespace tt::core
