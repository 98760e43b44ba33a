#include "runtime/reports/chart_adaptations.h"

#include <algorithm>
#include <optional>
#include <set>

namespace tt::runtime {

namespace {

/// The readings [first, last) of run `runId` in the point's series; none when the run has no reading there.
std::optional<std::pair<std::size_t, std::size_t>> runReadings(const PointReport& point, std::int64_t runId) {
    const auto& starts = point.runStarts;
    const auto it = std::find_if(starts.begin(), starts.end(), [runId](const auto& s) { return s.runId == runId; });
    if (it == starts.end()) return std::nullopt;
    const std::size_t last =
        std::next(it) == starts.end() ? point.series.partNumbers.size() : std::next(it)->firstReading;
    return std::make_pair(it->firstReading, last);
}

/// The chart point of the first reading of `runId` at or after `partNumber`; none when there is none on the chart.
std::optional<std::size_t> chartPointOf(const PointReport& point, std::int64_t runId, std::int64_t partNumber) {
    const auto range = runReadings(point, runId);
    if (!range) return std::nullopt;
    const auto& parts = point.series.partNumbers;
    const auto first = parts.begin() + static_cast<std::ptrdiff_t>(range->first);
    const auto last = parts.begin() + static_cast<std::ptrdiff_t>(range->second);
    const auto at = std::lower_bound(first, last, partNumber);
    if (at == last) return std::nullopt;
    const auto reading = static_cast<std::size_t>(at - parts.begin());
    const std::size_t chartPoint =
        reading / static_cast<std::size_t>(std::max(1, point.analysis.chart.limits.subgroupSize));
    if (chartPoint >= point.analysis.chart.locationMm.size()) return std::nullopt;
    return chartPoint;
}

}  // namespace

std::vector<std::int64_t> reportRuns(const std::vector<storage::PointReadings>& points) {
    std::set<std::int64_t> runs;
    for (const storage::PointReadings& p : points)
        for (const storage::RunStart& s : p.runStarts)
            runs.insert(s.runId);
    return {runs.begin(), runs.end()};
}

RunAdaptations readRunAdaptations(core::HistoryStore& store, const std::vector<storage::PointReadings>& readings) {
    RunAdaptations byRun;
    for (const std::int64_t run : reportRuns(readings))
        byRun[run] = store.adaptations(run);
    return byRun;
}

void placeAdaptations(std::vector<PointReport>& points, const RunAdaptations& byRun) {
    for (PointReport& point : points) {
        point.adaptations.clear();
        for (const auto& [runId, records] : byRun) {
            for (const core::AdaptationRecord& record : records) {
                if (!record.applied) continue;
                if (const auto chartPoint = chartPointOf(point, runId, record.partNumber))
                    point.adaptations.push_back({runId, *chartPoint, record});
            }
        }
    }
}

}  // namespace tt::runtime
