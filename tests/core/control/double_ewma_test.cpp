// The double EWMA (EwmaController with a drift weight; Butler & Stefani 1994) against the EWMA on a drift.
#include <gtest/gtest.h>

#include <cmath>

#include "core/control/ewma_controller.h"

namespace tt::core {
namespace {

/// The error of part `parts` on a plant y = g u + drift k (delay 1: the measurement of part k is used for
/// part k + 1), mm.
double lastError(EwmaController& c, int parts, double driftPerPartMm) {
    const double gain = 2.0;
    double error = 0.0;
    for (int k = 1; k <= parts; ++k) {
        const double u = c.nextCorrection(k)(0);
        error = gain * u + driftPerPartMm * k;
        PartMeasurement m{k, Eigen::VectorXd::Constant(1, error)};
        EXPECT_TRUE(c.addMeasurement(m).allAccepted());
    }
    return error;
}

// On a ramp of 0.001 mm per part the EWMA with weight lambda settles at a lag error of drift x (1 + (1 -
// lambda) / lambda) with delay 1 (0.001 x 1 / 0.3 = 0.00333 mm for lambda = 0.3: the offset estimate
// trails the ramp by (1 - lambda) / lambda parts, and the correction acts one part later); the double EWMA
// removes the lag (offset + drift term predicts the next part), leaving zero error in steady state.
TEST(DoubleEwma, FollowsADriftWithoutLag) {
    const CorrectionLimits limits{10.0, 10.0};
    EwmaOptions ewma;
    ewma.weight = 0.3;
    EwmaController plain(Eigen::VectorXd::Constant(1, 2.0), limits, ewma);
    EwmaOptions dewma = ewma;
    dewma.driftWeight = 0.1;
    dewma.driftHorizonParts = 1;
    EwmaController twice(Eigen::VectorXd::Constant(1, 2.0), limits, dewma);
    EXPECT_EQ(plain.name(), "ewma");
    EXPECT_EQ(twice.name(), "dewma");
    EXPECT_NEAR(lastError(plain, 400, 0.001), 0.001 / 0.3, 1e-6);
    EXPECT_NEAR(lastError(twice, 400, 0.001), 0.0, 1e-6);
    // p tends to D / lambda1 (Butler & Stefani's drift term includes the offset's lag).
    EXPECT_NEAR(twice.driftMm()(0), 0.001 / 0.3, 1e-6);
}

// The state with the drift survives save and restore; an EWMA state does not restore into a double EWMA.
TEST(DoubleEwma, StateRoundTrips) {
    const CorrectionLimits limits{10.0, 10.0};
    EwmaOptions options;
    options.weight = 0.5;
    options.driftWeight = 0.2;
    EwmaController a(Eigen::VectorXd::Constant(1, 2.0), limits, options);
    lastError(a, 20, 0.002);
    EwmaController b(Eigen::VectorXd::Constant(1, 2.0), limits, options);
    b.restoreState(a.saveState());
    EXPECT_DOUBLE_EQ(b.driftMm()(0), a.driftMm()(0));
    EXPECT_DOUBLE_EQ(b.nextCorrection(21)(0), a.nextCorrection(21)(0));
    options.driftWeight = 0.0;
    EwmaController plain(Eigen::VectorXd::Constant(1, 2.0), limits, options);
    EXPECT_THROW(plain.restoreState(a.saveState()), std::invalid_argument);
    options.driftWeight = 1.0;
    EXPECT_THROW(options.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
