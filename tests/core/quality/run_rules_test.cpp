#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <vector>

#include "core/quality/run_rules.h"

namespace tt::core {
namespace {

// Constructed cases (no published source needed: each rule's definition is applied by hand). The points
// are in units of sigma about a centre line of 0 (centre 0, sigma 1), so zone boundaries are at 1, 2, 3.
// The quiet base repeats 0.5, -1.5, -0.5, 1.5: never more than 2 points on one side, 3 rising, 2 alternating
// steps, 1 point in a row within 1 sigma... so it fires no rule of either set; each case overwrites a few
// points so that exactly one rule fires, at known points. Exact comparisons (indices).

constexpr std::size_t kLength = 48;

std::vector<double> quietWith(const std::map<std::size_t, double>& changes) {
    constexpr double kPattern[4] = {0.5, -1.5, -0.5, 1.5};
    std::vector<double> v(kLength);
    for (std::size_t i = 0; i < kLength; ++i)
        v[i] = kPattern[i % 4];
    for (const auto& [i, value] : changes)
        v[i] = value;
    return v;
}

std::map<std::size_t, double> run(std::size_t first, const std::vector<double>& values) {
    std::map<std::size_t, double> changes;
    for (std::size_t k = 0; k < values.size(); ++k)
        changes[first + k] = values[k];
    return changes;
}

std::vector<std::size_t> indices(std::size_t first, std::size_t last) {
    std::vector<std::size_t> v;
    for (std::size_t i = first; i <= last; ++i)
        v.push_back(i);
    return v;
}

void expectOnly(const std::vector<double>& points, RuleSet set, int rule, int side, std::size_t signal,
                const std::vector<std::size_t>& involved) {
    const std::vector<RuleViolation> found = findRuleViolations(points, 0.0, 1.0, set);
    ASSERT_EQ(found.size(), 1u) << "expected only " << ruleCode(set, rule) << ", found "
                                << (found.empty() ? std::string("none") : ruleCode(found[0].set, found[0].rule))
                                << (found.size() > 1 ? " and " + ruleCode(found[1].set, found[1].rule) : "");
    EXPECT_EQ(found[0].set, set);
    EXPECT_EQ(found[0].rule, rule);
    EXPECT_EQ(found[0].side, side);
    EXPECT_EQ(found[0].signalPoint, signal);
    EXPECT_EQ(found[0].points, involved);
}

TEST(RunRules, TheQuietBaseFiresNothing) {
    EXPECT_TRUE(findRuleViolations(quietWith({}), 0.0, 1.0, RuleSet::WesternElectric).empty());
    EXPECT_TRUE(findRuleViolations(quietWith({}), 0.0, 1.0, RuleSet::Nelson).empty());
}

// One point at 3.5 sigma: WE1 and Nelson 1 at that point only.
TEST(RunRules, OnePointBeyondThreeSigma) {
    const auto points = quietWith({{20, 3.5}});
    expectOnly(points, RuleSet::WesternElectric, 1, 1, 20, {20});
    expectOnly(points, RuleSet::Nelson, 1, 1, 20, {20});
    // Exactly on the limit is not beyond it.
    EXPECT_TRUE(findRuleViolations(quietWith({{20, 3.0}}), 0.0, 1.0, RuleSet::Nelson).empty());
}

// Two consecutive points at -2.5 sigma (points 21, 22): WE2 / Nelson 5 on the lower side, first firing
// when the second arrives.
TEST(RunRules, TwoOfThreeBeyondTwoSigma) {
    const auto points = quietWith({{21, -2.5}, {22, -2.5}});
    expectOnly(points, RuleSet::WesternElectric, 2, -1, 22, {21, 22});
    expectOnly(points, RuleSet::Nelson, 5, -1, 22, {21, 22});
}

// Points 19, 20, 21, 23 above 1 sigma (1.5, 1.2, 1.8, 1.5; point 22 at 0.5): WE3 / Nelson 6 at point 23.
TEST(RunRules, FourOfFiveBeyondOneSigma) {
    const auto points = quietWith({{20, 1.2}, {21, 1.8}, {22, 0.5}});
    expectOnly(points, RuleSet::WesternElectric, 3, 1, 23, {19, 20, 21, 23});
    expectOnly(points, RuleSet::Nelson, 6, 1, 23, {19, 20, 21, 23});
}

// Eight points above the centre within 1 sigma (19..26), a point below after them: WE4 at 26.
TEST(RunRules, EightInARowOnOneSide) {
    auto changes = run(19, {0.5, 0.2, 0.7, 0.3, 0.6, 0.4, 0.8, 0.1});
    changes[27] = -0.5;
    expectOnly(quietWith(changes), RuleSet::WesternElectric, 4, 1, 26, indices(19, 26));
}

// Nine points above the centre (19..27): Nelson 2 at 27.
TEST(RunRules, NineInARowOnOneSide) {
    auto changes = run(19, {0.5, 0.2, 0.7, 0.3, 0.6, 0.4, 0.8, 0.1, 0.6});
    changes[28] = -0.5;
    expectOnly(quietWith(changes), RuleSet::Nelson, 2, 1, 27, indices(19, 27));
}

// Six points rising (20..25, -0.9 to 0.9) after a fall and before one: Nelson 3 at 25.
TEST(RunRules, SixInARowIncreasing) {
    expectOnly(quietWith(run(20, {-0.9, -0.6, -0.2, 0.1, 0.4, 0.9})), RuleSet::Nelson, 3, 1, 25, indices(20, 25));
}

// Fourteen points alternating up and down (20..33), ended by an equal neighbour: Nelson 4 at 33.
TEST(RunRules, FourteenAlternating) {
    const auto points =
        quietWith(run(20, {0.6, -0.6, 0.4, -0.4, 1.2, -0.6, 0.5, -0.5, 0.7, -1.3, 0.6, -0.6, 0.5, -0.5}));
    expectOnly(points, RuleSet::Nelson, 4, 0, 33, indices(20, 33));
}

// Fifteen points within 1 sigma (20..34), between points at 1.5: Nelson 7 at 34.
TEST(RunRules, FifteenWithinOneSigma) {
    const auto points =
        quietWith(run(20, {0.5, -0.5, -0.3, 0.4, 0.2, -0.6, -0.1, 0.3, 0.6, -0.2, -0.4, 0.1, 0.5, -0.5, -0.3}));
    expectOnly(points, RuleSet::Nelson, 7, 0, 34, indices(20, 34));
}

// Eight points beyond 1 sigma alternating sides (21..28): Nelson 8 at 28.
TEST(RunRules, EightBeyondOneSigmaEitherSide) {
    auto changes = run(21, {-1.5, 1.5, -1.2, 1.8, -1.5, 1.2, -1.8, 1.5});
    changes[29] = -0.5;
    expectOnly(quietWith(changes), RuleSet::Nelson, 8, 0, 28, indices(21, 28));
}

// Overlapping firings are one violation: twelve points above the centre (19..30) are one WE4 violation
// signalled at the eighth point (26) and involving all twelve.
TEST(RunRules, OverlappingFiringsMerge) {
    auto changes = run(19, {0.5, 0.2, 0.7, 0.3, 0.6, 0.4, 0.8, 0.1, 0.6, 0.2, 0.7, 0.3});
    changes[31] = -0.5;
    expectOnly(quietWith(changes), RuleSet::WesternElectric, 4, 1, 26, indices(19, 30));
}

// Zones scale with the centre and sigma of the plotted statistic: the 3.5-sigma case in mm.
TEST(RunRules, ZonesUseCentreAndSigma) {
    std::vector<double> mm;
    for (const double z : quietWith({{20, 3.5}}))
        mm.push_back(74.0 + 0.004 * z);
    const auto found = findRuleViolations(mm, 74.0, 0.004, RuleSet::WesternElectric);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].signalPoint, 20u);
}

TEST(RunRules, CodesAndBadInput) {
    EXPECT_EQ(ruleCode(RuleSet::WesternElectric, 4), "WE4");
    EXPECT_EQ(ruleCode(RuleSet::Nelson, 8), "N8");
    EXPECT_THROW(ruleCode(RuleSet::WesternElectric, 5), std::invalid_argument);
    EXPECT_THROW(findRuleViolations(quietWith({}), 0.0, 0.0, RuleSet::Nelson), std::invalid_argument);
    EXPECT_TRUE(findRuleViolations(std::vector<double>{}, 0.0, 1.0, RuleSet::Nelson).empty());
}

}  // namespace
}  // namespace tt::core
