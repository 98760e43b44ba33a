// The loop's model-mismatch monitor (core/loop/mismatch_monitor.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/loop/mismatch_monitor.h"
#include "core/quality/distributions.h"

namespace tt::core {
namespace {

// The Chernoff limit is never below the exact chi-square quantile (Boost.Math) at 1 - alpha, so the
// variance test's false-alarm probability is at most alpha; and not far above it (the bound is tight
// to within a few tens of per cent for n >= 10).
TEST(MismatchMonitor, ChernoffLimitBoundsTheChiSquareQuantile) {
    for (int n : {10, 50, 250, 1000}) {
        for (double alpha : {1e-3, 1e-6}) {
            const double limit = chernoffChiSquareFactor(n, alpha) * n;
            const double exact = chiSquareQuantile(1.0 - alpha, n);
            EXPECT_GE(limit, exact) << n << " " << alpha;
            EXPECT_LT(limit, 1.6 * exact) << n << " " << alpha;
        }
    }
}

// The correlation statistic of one regressor equal to the innovation: b = M = sum x^2, T = sum x^2.
TEST(MismatchMonitor, CorrelationStatisticIsTheScoreStatistic) {
    Eigen::Matrix2d M;
    M << 4.0, 0.0, 0.0, 9.0;
    const Eigen::Vector2d b(2.0, 3.0);
    EXPECT_NEAR(correlationStatistic(M, b), 4.0 / 4.0 + 9.0 / 9.0, 1e-9);
    EXPECT_EQ(correlationStatistic(Eigen::Matrix2d::Zero(), Eigen::Vector2d::Zero()), 0.0);
}

/// Feeds `parts` parts: corrections u ~ N(0, 1) per point, innovations nu = effect(u(k), u(k-1)) + N(0, S).
template <typename Effect>
std::optional<MismatchFinding> feed(MismatchMonitor& monitor, int parts, std::uint64_t seed, Effect effect) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    constexpr int kPoints = 5;
    constexpr double kVariance = 0.25;
    std::vector<double> previous(kPoints, 0.0);
    monitor.partStarted(0, previous);
    for (int k = 1; k <= parts; ++k) {
        std::vector<double> u(kPoints);
        for (double& x : u)
            x = n01(rng);
        monitor.partStarted(k, u);
        Innovation inn{k, Eigen::VectorXd(kPoints), Eigen::VectorXd::Constant(kPoints, kVariance)};
        for (int i = 0; i < kPoints; ++i)
            inn.valueMm(i) = effect(u[i], previous[i]) + std::sqrt(kVariance) * n01(rng);
        previous = u;
        if (auto f = monitor.add(inn)) return f;
    }
    return std::nullopt;
}

// A matching plant (innovations white and independent of the corrections): no alarm in 20,000 parts
// at alpha = 1e-6 per test (expected false alarms at most 2 x 20,000 x 1e-6 = 0.04).
TEST(MismatchMonitor, NoFalseAlarmOnAMatchingPlant) {
    MismatchMonitor monitor(MismatchMonitorConfig{});
    EXPECT_FALSE(feed(monitor, 20000, 11, [](double, double) { return 0.0; }));
}

// A plant gain half the model's leaves -0.5 u(k) in the innovation; a plant one part slower leaves
// u(k-1) - u(k): both found by the correlation test within 50 parts.
TEST(MismatchMonitor, FindsGainAndDelayMismatch) {
    MismatchMonitor gain(MismatchMonitorConfig{});
    const auto g = feed(gain, 50, 12, [](double u, double) { return -0.5 * u; });
    ASSERT_TRUE(g);
    EXPECT_TRUE(g->correlation);
    EXPECT_LE(g->partNumber, 50);
    EXPECT_TRUE(gain.tripped());
    MismatchMonitor delay(MismatchMonitorConfig{});
    const auto d = feed(delay, 50, 13, [](double u, double before) { return before - u; });
    ASSERT_TRUE(d);
    EXPECT_LE(d->partNumber, 50);
}

// Innovations sqrt(10) times as large as the model says (a disturbance larger than modelled) are found;
// both statistics are normalised by the model's variance, so either test may be the first to fire.
TEST(MismatchMonitor, FindsATooLargeDisturbance) {
    MismatchMonitor monitor(MismatchMonitorConfig{});
    std::mt19937_64 rng(14);
    std::normal_distribution<double> n01(0.0, 1.0);
    const auto f = feed(monitor, 50, 15, [&](double, double) { return 1.5 * n01(rng); });
    ASSERT_TRUE(f);
    EXPECT_GT(f->statistic, f->threshold);
}

/// Feeds `parts` parts of innovations whose points share `common` of their variance (a lathe whose points move
/// together), the corrections unrelated to them.
std::optional<MismatchFinding> feedTogether(MismatchMonitor& monitor, int parts, std::uint64_t seed, double common) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    constexpr int kPoints = 5;
    monitor.partStarted(0, std::vector<double>(kPoints, 0.0));
    for (int k = 1; k <= parts; ++k) {
        std::vector<double> u(kPoints);
        for (double& x : u)
            x = n01(rng);
        monitor.partStarted(k, u);
        Innovation inn{k, Eigen::VectorXd(kPoints), Eigen::VectorXd::Ones(kPoints)};
        const double shared = n01(rng);
        for (int i = 0; i < kPoints; ++i)
            inn.valueMm(i) = std::sqrt(common) * shared + std::sqrt(1.0 - common) * n01(rng);
        if (auto f = monitor.add(inn)) return f;
    }
    return std::nullopt;
}

// Points that move together (80 % of the variance common, as on the physical lathe) fail the independence test of a
// model of independent points within 20 parts; a monitor told to expect that correlation (point_correlation 0.8)
// stays quiet over 20,000 parts, and finds points that do not move together when it expects them to (whitened with
// the wrong correlation their normalised sum of squares is too large).
TEST(MismatchMonitor, ExpectsThePointsToMoveTogetherWhenToldSo) {
    MismatchMonitor independent(MismatchMonitorConfig{});
    const auto f = feedTogether(independent, 50, 21, 0.8);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->test, MismatchTest::Independence);
    EXPECT_LE(f->partNumber, 20);

    MismatchMonitorConfig together;
    together.pointCorrelation = 0.8;
    MismatchMonitor expecting(together);
    EXPECT_FALSE(feedTogether(expecting, 20000, 22, 0.8));
    MismatchMonitor wrong(together);
    const auto g = feedTogether(wrong, 200, 23, 0.0);  // whitened with the wrong correlation: the variance test
    ASSERT_TRUE(g);
    EXPECT_LE(g->partNumber, 50);
}

TEST(MismatchMonitor, RefusesBadSettings) {
    MismatchMonitorConfig c;
    c.windowParts = 5;
    EXPECT_THROW(c.validate(), std::invalid_argument);
    c = {};
    c.falseAlarmProbability = 0.5;
    EXPECT_THROW(c.validate(), std::invalid_argument);
    for (double bad : {-0.1, 0.96, std::nan("")}) {
        c = {};
        c.pointCorrelation = bad;
        EXPECT_THROW(c.validate(), std::invalid_argument) << bad;
    }
    EXPECT_THROW(mismatchActionFromName("stop"), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
