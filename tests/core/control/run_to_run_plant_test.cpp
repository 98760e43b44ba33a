#include "core/control/run_to_run_plant.h"

#include <gtest/gtest.h>

#include "support/lqg_test_support.h"

namespace tt::core {
namespace {

TEST(RunToRunPlant, PaperControlPointsOnA325MmShaft) {
    // Paper 000: both ends, inflection points 25-30 mm from the left and 50-75 mm from the right end,
    // the middle.
    const std::vector<double> x = paperControlPointsMm(325.0);
    ASSERT_EQ(x.size(), 5u);
    EXPECT_DOUBLE_EQ(x[0], 0.0);
    EXPECT_GE(x[1], 25.0);
    EXPECT_LE(x[1], 30.0);
    EXPECT_DOUBLE_EQ(x[2], 162.5);
    EXPECT_GE(325.0 - x[3], 50.0);
    EXPECT_LE(325.0 - x[3], 75.0);
    EXPECT_DOUBLE_EQ(x[4], 325.0);
}

TEST(RunToRunPlant, DelayChainsHaveThePapersTwentyStatesAtZ4) {
    const RunToRunPlant p = buildRunToRunPlant(test::paper2012Setup(4).plant);
    Eigen::Index delayStates = 0;
    for (const auto& L : p.layout)
        delayStates += L.delayCount;
    EXPECT_EQ(delayStates, 20);  // paper: n = 20 for z = 4, 5 points
    EXPECT_EQ(p.stateCount(), 20 + 5 * 2);
    EXPECT_EQ(p.B.cols(), 5);
    EXPECT_EQ(p.C.rows(), 5);
    EXPECT_TRUE(p.D.isZero(0.0));
    EXPECT_DOUBLE_EQ(p.V(2, 2), 2.5e-7);
}

// y_i(k) = k_i u_i(k - z) + f_i(k) (paper 000, eq. (2)): a unit correction at point i shows as
// exactly 2 mm of diameter at that point z steps later and nowhere else.
TEST(RunToRunPlant, UnitCorrectionAppearsAsTwiceItsSizeExactlyZPartsLater) {
    for (int z = 1; z <= 8; ++z) {
        const RunToRunPlant p = buildRunToRunPlant(test::paper2012Setup(z).plant);
        for (int i = 0; i < p.pointCount(); ++i) {
            Eigen::VectorXd x = Eigen::VectorXd::Zero(p.stateCount());
            Eigen::VectorXd u = Eigen::VectorXd::Zero(p.pointCount());
            u(i) = 1.0;
            for (int k = 1; k <= z + 2; ++k) {
                x = (p.A * x + p.B * (k == 1 ? u : Eigen::VectorXd::Zero(p.pointCount()))).eval();
                const Eigen::VectorXd y = p.C * x;
                for (int j = 0; j < p.pointCount(); ++j)
                    EXPECT_DOUBLE_EQ(y(j), (k == z && j == i) ? 2.0 : 0.0) << "z " << z << " k " << k;
            }
        }
    }
}

TEST(RunToRunPlant, RefusesOutOfRangeInput) {
    RunToRunPlantSpec spec = test::paper2012Setup(4).plant;
    auto expectError = [](RunToRunPlantSpec s, const std::string& text) {
        try {
            buildRunToRunPlant(s);
            FAIL() << "expected: " << text;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    RunToRunPlantSpec s = spec;
    s.delay = 0;
    expectError(s, "the delay must be 1 .. 8 parts, got 0");
    s.delay = 9;
    expectError(s, "got 9");
    s = spec;
    s.points.clear();
    expectError(s, "1 .. 16, got 0");
    s = spec;
    while (s.points.size() < 17)
        s.points.push_back(s.points.front());
    expectError(s, "got 17");
    s = spec;
    s.points[2].gain = 0.0;
    expectError(s, "control point 3: the gain");
    s = spec;
    s.points[1].measurementNoiseVarianceMm2 = 0.0;
    expectError(s, "control point 2: the gauge noise variance must be > 0");
    s = spec;
    s.points[0].xMm = std::nan("");
    expectError(s, "control point 1: the position");
}

}  // namespace
}  // namespace tt::core
