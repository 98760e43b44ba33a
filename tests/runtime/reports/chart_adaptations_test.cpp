// Where the Reports page marks the adaptive loop's controller changes (runtime/reports/chart_adaptations.h): at the
// chart point of the first reading of the record's run at or after its part, on I-MR and X-bar charts, over several
// runs, never for a record that did not change the controller or lies beyond the chart.
#include <gtest/gtest.h>

#include "runtime/reports/chart_adaptations.h"

namespace tt::runtime {
namespace {

/// A point report of runs 3 (parts 1..10, part 4 missing: an implausible reading) and 5 (parts 1..6), one chart point
/// per `subgroup` readings (the incomplete last subgroup left out, as core/quality does).
PointReport twoRuns(int subgroup) {
    PointReport p;
    for (std::int64_t part = 1; part <= 10; ++part)
        if (part != 4) p.series.partNumbers.push_back(part);
    p.runStarts.push_back({3, 0});
    p.runStarts.push_back({5, p.series.partNumbers.size()});
    for (std::int64_t part = 1; part <= 6; ++part)
        p.series.partNumbers.push_back(part);
    p.series.valuesMm.assign(p.series.partNumbers.size(), 27.0);
    p.analysis.chart.limits.subgroupSize = subgroup;
    p.analysis.chart.locationMm.assign(p.series.partNumbers.size() / static_cast<std::size_t>(subgroup), 27.0);
    return p;
}

core::AdaptationRecord record(const char* kind, std::int64_t part, bool applied = true) {
    core::AdaptationRecord r;
    r.kind = kind;
    r.partNumber = part;
    r.applied = applied;
    return r;
}

std::vector<std::pair<std::int64_t, std::size_t>> placed(const PointReport& p) {
    std::vector<std::pair<std::int64_t, std::size_t>> out;
    for (const ChartAdaptation& a : p.adaptations)
        out.emplace_back(a.record.partNumber, a.chartPoint);
    return out;
}

// Individuals: run 3's part 4 has no reading, so its change shows at part 5 (reading 3); run 5's part 2 is reading 10.
// The proposal that changed nothing and the change after run 5's last part are not marked.
TEST(ChartAdaptations, IndividualsChartMarksTheFirstReadingAtOrAfterThePart) {
    std::vector<PointReport> points{twoRuns(1)};
    RunAdaptations byRun;
    byRun[3] = {record("fallback", 2), record("proposed", 3, false), record("adapted", 4)};
    byRun[5] = {record("refined", 2), record("refined", 7)};
    placeAdaptations(points, byRun);
    const std::vector<std::pair<std::int64_t, std::size_t>> expected{{2, 1}, {4, 3}, {2, 10}};
    EXPECT_EQ(placed(points[0]), expected);
    EXPECT_EQ(points[0].adaptations[2].runId, 5);
}

// Subgroups of 4: 15 readings make 3 chart points; reading 10 (run 5, part 2) is in subgroup 2, reading 14 (run 5,
// part 6) in the incomplete fourth subgroup the chart leaves out.
TEST(ChartAdaptations, SubgroupChartMarksTheSubgroupAndNotTheLeftOverTail) {
    std::vector<PointReport> points{twoRuns(4)};
    RunAdaptations byRun;
    byRun[5] = {record("adapted", 2), record("refined", 6)};
    placeAdaptations(points, byRun);
    const std::vector<std::pair<std::int64_t, std::size_t>> expected{{2, 2}};
    EXPECT_EQ(placed(points[0]), expected);
}

// A run without readings at the point marks nothing; placing again replaces the marks; reportRuns lists each run once.
TEST(ChartAdaptations, RunsWithoutReadingsMarkNothingAndPlacingAgainReplaces) {
    std::vector<PointReport> points{twoRuns(1)};
    RunAdaptations byRun;
    byRun[4] = {record("fallback", 1)};
    placeAdaptations(points, byRun);
    EXPECT_TRUE(points[0].adaptations.empty());
    byRun[3] = {record("fallback", 1)};
    placeAdaptations(points, byRun);
    placeAdaptations(points, byRun);
    EXPECT_EQ(points[0].adaptations.size(), 1u);

    storage::PointReadings a, b;
    a.runStarts = {{3, 0}, {5, 9}};
    b.runStarts = {{5, 0}, {7, 4}};
    EXPECT_EQ(reportRuns({a, b}), (std::vector<std::int64_t>{3, 5, 7}));
}

}  // namespace
}  // namespace tt::runtime
