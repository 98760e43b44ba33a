#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace tt::core {

/// The two classic sets of run rules for a Shewhart location chart (X-bar or individuals).
enum class RuleSet {
    WesternElectric,  ///< Western Electric Statistical Quality Control Handbook (1956), rules 1-4
    Nelson,           ///< Nelson (1984), "The Shewhart control chart - tests for special causes", JQT 16(4), rules 1-8
};

/// One rule violation: the rule, where a live chart would first have alarmed, and the points involved.
/// Overlapping firings of the same rule on the same side are one violation (a run of 12 points on one side
/// is one violation of "8 in a row", involving all 12 points).
struct RuleViolation {
    RuleSet set = RuleSet::WesternElectric;
    int rule = 0;  ///< 1..4 (Western Electric) or 1..8 (Nelson)
    int side = 0;  ///< +1 above the centre line or increasing, -1 below or decreasing, 0 for either-side rules
    std::size_t signalPoint = 0;      ///< the point at which the rule first fired
    std::vector<std::size_t> points;  ///< ascending: the points meeting the rule's condition
};

/// The rule's short code for reports and JSON: "WE1".."WE4", "N1".."N8". Throws std::invalid_argument for
/// a rule outside the set.
std::string ruleCode(RuleSet set, int rule);

/// Every violation of the rule set among the plotted points of a location chart with centre line
/// `centreMm` and sigma `sigmaMm` of the plotted statistic (ChartLimits::locationSigmaMm), zones A/B/C at
/// 3/2/1 sigma; "beyond k sigma" is strictly beyond, a point on the centre line is on neither side, equal
/// neighbours break a trend or an alternation. A window rule (m of w) also fires on the first w - 1 points
/// as soon as m of them qualify. Sorted by signal point, then rule.
///
/// Western Electric: 1 one point beyond 3 sigma; 2 two of three consecutive beyond 2 sigma on one side;
/// 3 four of five beyond 1 sigma on one side; 4 eight in a row on one side.
/// Nelson: 1 one point beyond 3 sigma; 2 nine in a row on one side; 3 six in a row steadily increasing or
/// decreasing; 4 fourteen in a row alternating up and down; 5 two of three beyond 2 sigma on one side;
/// 6 four of five beyond 1 sigma on one side; 7 fifteen in a row within 1 sigma (either side); 8 eight in
/// a row beyond 1 sigma (either side).
///
/// Throws std::invalid_argument when a point or the centre is not finite or sigma is not above 0.
std::vector<RuleViolation> findRuleViolations(std::span<const double> pointsMm, double centreMm, double sigmaMm,
                                              RuleSet set);

}  // namespace tt::core
