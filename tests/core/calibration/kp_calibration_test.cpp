// k_p from known loads (paper 001: k_p "is found experimentally"), on exact data and on the
// simulated cross feed with dither.
#include "core/calibration/kp_calibration.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/control/dither_force_estimator.h"
#include "core/sim/rigs/known_load_rig.h"

namespace tt::core {
namespace {

TEST(KpCalibration, FitsAStraightLineThroughTheLoads) {
    // ΔI = (F − 6) / 150 exactly: k_p = 150 N/A, offset 6 N.
    std::vector<KpPoint> points;
    for (double f : {0.0, 150.0, 300.0, 450.0, 600.0})
        points.push_back({f, (f - 6.0) / 150.0});
    const KpFit fit = fitKp(points);
    EXPECT_NEAR(fit.kpNPerA, 150.0, 1e-9);
    EXPECT_NEAR(fit.offsetN, 6.0, 1e-9);
    EXPECT_NEAR(fit.r2, 1.0, 1e-12);
    EXPECT_NEAR(fit.rmsResidualN, 0.0, 1e-9);
}

TEST(KpCalibration, RefusesTooFewOrContradictoryPoints) {
    auto message = [](const std::vector<KpPoint>& p) {
        try {
            fitKp(p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message({{0, 0}, {100, 1}}), "k_p needs at least 3 known loads, got 2");
    EXPECT_EQ(message({{100, 0.5}, {100, 0.7}, {100, 0.6}}), "k_p needs at least 2 different loads");
    EXPECT_NE(message({{0, 1}, {100, 0}, {200, -1}}).find("falls as the load grows"), std::string::npos);
    EXPECT_NE(message({{0, 1}, {100, 1}, {200, 1}}).find("the same at every load"), std::string::npos);
    EXPECT_EQ(message({{0, 0}, {100, std::nan("")}, {200, 2}}), "point 2: not a number");
}

TEST(KpCalibration, RecoversTheSimulatedDrivesGainThroughTheDitherEstimator) {
    // Heavy-boring cross feed: true k_p 150 N/A, Coulomb friction 975 N, current noise 0.3 A.
    KnownLoadRig rig(CrossFeedDriveConfig{}, DitherConfig{0.01, 0.5, 0.6}, 0.02, 5);
    DitherEstimatorConfig unit;
    unit.currentToForceNPerA = 1.0;  // force = ΔI in A
    unit.stiffnessNPerMm = 1.0;
    std::vector<KpPoint> points;
    for (double load : {0.0, 200.0, 400.0, 600.0}) {
        rig.setLoadN(load);
        DitherForceEstimator estimator(unit);
        rig.advance(1.0);  // settle
        while (rig.takeSample()) {
        }
        double sum = 0.0;
        int n = 0;
        for (int i = 0; i < 400; ++i) {  // 8 s of PLC cycles
            rig.advance(0.02);
            while (const auto s = rig.takeSample()) {
                const DitherUpdate u = estimator.update(*s);
                if (u.newEstimate) {
                    sum += u.estimate->forceN;
                    ++n;
                }
            }
        }
        ASSERT_GT(n, 20) << estimator.state().reason;
        points.push_back({load, sum / n});
    }
    const KpFit fit = fitKp(points);
    EXPECT_NEAR(fit.kpNPerA, 150.0, 150.0 * 0.03);  // within 3 %
    EXPECT_NEAR(fit.offsetN, 0.0, 15.0);
    EXPECT_GT(fit.r2, 0.999);
}

}  // namespace
}  // namespace tt::core
