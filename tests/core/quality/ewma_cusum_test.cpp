#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/quality/ewma_cusum.h"
#include "support/published_data.h"

namespace tt::core {
namespace {

using test::kCusumTable91;

// Montgomery (2009), Example 9.1 and Table 9.2: tabular CUSUM of Table 9.1 with mu0 = 10, sigma = 1,
// k = 0.5 (K = 0.5), h = 5 (H = 5). The book: C-_1 = 0.05, C-_2 = 1.56, C-_3 = 1.77, C+_4 = 1.16; C+ first
// exceeds H at observation 29 with C+ = 5.28 and N+ = 7, so the shift began after observation 22, and the
// new mean is estimated as 10 + 0.5 + 5.28/7 = 11.25. Tolerance 0.005 (the table's two decimals).
TEST(Cusum, MontgomeryTable92) {
    CusumSettings settings;
    settings.k = 0.5;
    settings.h = 5.0;
    settings.reference.targetMm = 10.0;
    settings.reference.sigmaMm = 1.0;
    const CusumChart chart = cusumChart(kCusumTable91, settings);
    EXPECT_DOUBLE_EQ(chart.referenceKMm, 0.5);
    EXPECT_DOUBLE_EQ(chart.decisionHMm, 5.0);
    EXPECT_NEAR(chart.lowerMm[0], 0.05, 0.005);
    EXPECT_NEAR(chart.lowerMm[1], 1.56, 0.005);
    EXPECT_NEAR(chart.lowerMm[2], 1.77, 0.005);
    EXPECT_NEAR(chart.upperMm[3], 1.16, 0.005);
    EXPECT_NEAR(chart.upperMm[28], 5.28, 0.005);
    EXPECT_EQ(chart.upperRun[28], 7u);
    ASSERT_EQ(chart.signals.size(), 1u);
    const CusumSignal& s = chart.signals[0];
    EXPECT_EQ(s.excursion.first, 28u);  // observation 29 (zero-based 28)
    EXPECT_EQ(s.excursion.last, 29u);   // still above H at observation 30
    EXPECT_EQ(s.excursion.side, 1);
    EXPECT_EQ(s.runLength, 7u);
    EXPECT_EQ(s.shiftStart, 22u);  // observation 23, the first after 22
    EXPECT_NEAR(s.shiftedMeanMm, 11.25, 0.005);
}

// Montgomery (2009), Example 9.2 (EWMA of the Table 9.1 data, lambda = 0.1, L = 2.7, mu0 = 10, sigma = 1):
// z_1 = 9.945, z_2 = 9.7495; limits at i = 1: 9.73 .. 10.27, i = 2: 9.64 .. 10.36, tending to 9.38 ..
// 10.62. Tolerances: 1e-9 on z (exact decimals), 0.005 on the limits (two decimals). The first alarm
// follows from the recursion on the book's data (z_29 = 10.6468 above 10.6187); it is checked against the
// limits, not quoted from the book.
TEST(Ewma, MontgomeryExample92) {
    EwmaSettings settings;
    settings.lambda = 0.1;
    settings.widthL = 2.7;
    settings.reference.targetMm = 10.0;
    settings.reference.sigmaMm = 1.0;
    const EwmaChart chart = ewmaChart(kCusumTable91, settings);
    EXPECT_NEAR(chart.ewmaMm[0], 9.945, 1e-9);
    EXPECT_NEAR(chart.ewmaMm[1], 9.7495, 1e-9);
    EXPECT_NEAR(chart.upperMm[0], 10.27, 0.005);
    EXPECT_NEAR(chart.lowerMm[0], 9.73, 0.005);
    EXPECT_NEAR(chart.upperMm[1], 10.36, 0.005);
    EXPECT_NEAR(chart.lowerMm[1], 9.64, 0.005);
    EXPECT_NEAR(chart.upperMm.back(), 10.62, 0.005);
    EXPECT_NEAR(chart.lowerMm.back(), 9.38, 0.005);
    ASSERT_EQ(chart.excursions.size(), 1u);
    EXPECT_EQ(chart.excursions[0].first, 28u);
    EXPECT_EQ(chart.excursions[0].last, 29u);
    EXPECT_EQ(chart.excursions[0].side, 1);
    EXPECT_NEAR(chart.ewmaMm[28], 10.6468, 0.00005);
}

// NIST/SEMATECH e-Handbook, section 6.3.2.4 (EWMA example): target 50, s = 2.0539, lambda = 0.3, L = 3:
// UCL = 50 + 3 (0.4201)(2.0539) = 52.5884, LCL = 47.4115 (the asymptotic limits). The exact limits reach
// them within 1e-4 by the 20th point ((1 - 0.3)^40 = 6e-7). Tolerance 1e-4 (the handbook's four decimals).
TEST(Ewma, ExactLimitsTendToTheHandbookAsymptoticLimits) {
    EwmaSettings settings;
    settings.lambda = 0.3;
    settings.widthL = 3.0;
    settings.reference.targetMm = 50.0;
    settings.reference.sigmaMm = 2.0539;
    const EwmaChart chart = ewmaChart(std::vector<double>(20, 50.0), settings);
    EXPECT_NEAR(chart.upperMm.back(), 52.5884, 1e-4);
    EXPECT_NEAR(chart.lowerMm.back(), 47.4115, 1e-4);
    // At i = 1 the exact variance is lambda^2 sigma^2: the limits are 50 +- 3 * 0.3 * 2.0539.
    EXPECT_NEAR(chart.upperMm[0], 50.0 + 0.9 * 2.0539, 1e-12);
    EXPECT_TRUE(chart.excursions.empty());
}

// Without a given target and sigma, both come from the baseline: its mean and MR-bar/1.128. A baseline of
// alternating 11 and 9 has mean 10 and MR-bar 2, sigma 2/1.128; the CUSUM of a following step to 13 is 0 at
// the last baseline value (9), so the estimated start of the shift is the first 13.
TEST(EwmaCusum, ReferenceEstimatedFromTheBaseline) {
    std::vector<double> values;
    for (int i = 0; i < 20; ++i)
        values.push_back(i % 2 == 0 ? 11.0 : 9.0);
    CusumSettings cusum;
    cusum.reference.baseline = ChartBaseline{0, 20};
    for (int i = 0; i < 10; ++i)
        values.push_back(13.0);
    const CusumChart c = cusumChart(values, cusum);
    EXPECT_DOUBLE_EQ(c.targetMm, 10.0);
    EXPECT_NEAR(c.sigmaMm, 2.0 / 1.128, 1e-12);
    ASSERT_FALSE(c.signals.empty());
    EXPECT_EQ(c.signals[0].excursion.side, 1);
    EXPECT_EQ(c.signals[0].shiftStart, 20u);
    EwmaSettings ewma;
    ewma.reference.baseline = ChartBaseline{0, 20};
    const EwmaChart e = ewmaChart(values, ewma);
    EXPECT_DOUBLE_EQ(e.targetMm, 10.0);
    ASSERT_FALSE(e.excursions.empty());
    EXPECT_GE(e.excursions[0].first, 20u);
}

TEST(EwmaCusum, BadSettingsAreRefused) {
    const std::vector<double> v = {1.0, 2.0, 3.0};
    EwmaSettings ewma;
    ewma.lambda = 0.0;
    EXPECT_THROW(ewmaChart(v, ewma), std::invalid_argument);
    ewma.lambda = 0.2;
    ewma.widthL = 7.0;
    EXPECT_THROW(ewmaChart(v, ewma), std::invalid_argument);
    ewma.widthL = 3.0;
    ewma.reference.sigmaMm = 0.0;
    EXPECT_THROW(ewmaChart(v, ewma), std::invalid_argument);
    CusumSettings cusum;
    cusum.h = 0.0;
    EXPECT_THROW(cusumChart(v, cusum), std::invalid_argument);
    cusum.h = 5.0;
    EXPECT_THROW(cusumChart(std::vector<double>(5, 1.0), cusum), std::invalid_argument);  // MR-bar = 0
}

}  // namespace
}  // namespace tt::core
