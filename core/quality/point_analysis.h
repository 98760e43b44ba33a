#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/quality/capability.h"
#include "core/quality/control_chart.h"
#include "core/quality/run_rules.h"
#include "core/quality/series.h"
#include "core/quality/xbar_charts.h"

namespace tt::core {

/// What to compute for one control point (the report command and the Reports page).
struct PointAnalysisSettings {
    int subgroupSize = 1;                           ///< 1: I-MR chart; 2..25: X-bar chart of consecutive parts
    SubgroupSpread spread = SubgroupSpread::Range;  ///< X-bar-R or X-bar-s (subgroups only)
    ChartBaseline baseline;                         ///< phase-I chart points (all by default)
    std::optional<ChartLimits> heldLimits;          ///< phase II against stored limits instead of the baseline
    RuleSet rules = RuleSet::WesternElectric;
    std::optional<SpecLimits> spec;  ///< capability only with specification limits
    double confidence = 0.95;
    double normalityAlpha = 0.05;
};

/// A rule violation with the parts of the points it involves.
struct PointViolation {
    RuleViolation violation;
    std::vector<std::int64_t> partNumbers;  ///< every part of every involved chart point, in order
};

/// Chart, rule violations and capability of one control point.
struct PointAnalysis {
    std::size_t count = 0;
    double meanMm = 0.0;
    double sigmaOverallMm = 0.0;
    std::int64_t firstPart = 0;
    std::int64_t lastPart = 0;
    double firstTimeS = 0.0;
    double lastTimeS = 0.0;
    ControlChart chart;
    std::vector<PointViolation> violations;  ///< run rules on the location chart
    std::optional<CapabilityStudy> capability;
};

/// The chart of the series (I-MR for subgroupSize 1, X-bar-R or X-bar-s otherwise; limits from the
/// baseline or held), its run-rule violations with their parts, and, with specification limits, the
/// capability study with the within sigma of the same chart kind (MR-bar/1.128, R-bar/d2 or s-bar/c4 over
/// all values). Throws std::invalid_argument with the reason on a bad series or settings (see the
/// functions it calls).
PointAnalysis analysePoint(const MeasuredSeries& series, const PointAnalysisSettings& settings);

}  // namespace tt::core
