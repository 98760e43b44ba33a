// The simulated station behind the ports: part timing, readings in point order, a silent gauge,
// injected readings, parts measured elsewhere; and the statistical plant as a machine.
#include <gtest/gtest.h>

#include <cmath>

#include "core/loop/loop_clock.h"
#include "core/model/disturbance_model.h"
#include "core/sim/shaft/lathe_shop.h"
#include "core/sim/shaft/lathe_simulator.h"
#include "core/sim/shaft/lathe_station.h"
#include "core/sim/shaft/lathe_statistical_process.h"

namespace tt::core {
namespace {

struct Bench {
    Bench()
        : sim(setup(), {0.0, 162.5, 325.0}, LatheDisturbanceModel::none(3)),
          station(sim, LatheMicrometer{}, 7, clock, {0.0, 162.5, 325.0}) {}
    static LatheSetup setup() {
        LatheSetup s;
        s.beamElementMm = 5.0;
        return s;
    }
    ManualClock clock;
    LatheSimulator sim;
    LatheStation station;
};

TEST(LatheStation, APartTakesSixMinutesAndIsMeasuredPointByPoint) {
    Bench b;
    ASSERT_TRUE(b.station.output().sendPartCorrection(PartCorrection{1, {}, {}, {}}).ok);
    ASSERT_TRUE(b.station.machine().startPart(1).ok);
    EXPECT_FALSE(b.station.machine().startPart(2).ok) << "busy";
    EXPECT_EQ(b.station.nextEventTimeS(), 360.0);
    b.clock.advanceTo(359.0);
    EXPECT_FALSE(b.station.machine().takeFinishedPart().has_value());
    b.clock.advanceTo(360.0);
    const auto finished = b.station.machine().takeFinishedPart();
    ASSERT_TRUE(finished.has_value());
    EXPECT_EQ(finished->partNumber, 1);
    // Readings 20 s after the end, then every 5 s, in point order, of the true diameter.
    EXPECT_EQ(b.station.nextEventTimeS(), 380.0);
    b.clock.advanceTo(400.0);
    const TurnedPart& part = b.station.machinedParts().back();
    const double expected[] = {part.diameterAtMm(0.0), part.diameterAtMm(162.5), part.diameterAtMm(325.0)};
    for (int i = 0; i < 3; ++i) {
        const auto r = b.station.gauge().takeReading();
        ASSERT_TRUE(r.has_value());
        EXPECT_EQ(r->timeS, 380.0 + 5.0 * i);
        EXPECT_NEAR(r->diameterMm, expected[i], 0.003) << "micrometer: 0.001 mm at 95 %, rounded to 0.001";
    }
    EXPECT_FALSE(b.station.gauge().takeReading().has_value());
}

TEST(LatheStation, ASilentGaugeDelaysItsReadingsUntilItIsBack) {
    Bench b;
    b.station.silenceGauge(370.0, 1000.0);
    b.station.machine().startPart(1);
    b.clock.advanceTo(500.0);
    b.station.machine().takeFinishedPart();
    EXPECT_EQ(b.station.gauge().health().state, DeviceState::Disconnected);
    EXPECT_FALSE(b.station.gauge().takeReading().has_value());
    EXPECT_EQ(b.station.nextEventTimeS(), 1000.0) << "the next thing that happens: the gauge comes back";
    b.clock.advanceTo(1000.0);
    EXPECT_TRUE(b.station.gauge().health().ready());
    const auto r = b.station.gauge().takeReading();
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->timeS, 1000.0);
}

TEST(LatheStation, InjectedReadingsForgottenPartsAndARefusingCnc) {
    Bench b;
    b.station.injectReading(1, 1, 29.0);
    b.station.machine().startPart(1);
    b.clock.advanceTo(400.0);
    b.station.machine().takeFinishedPart();
    b.station.gauge().takeReading();
    EXPECT_EQ(b.station.gauge().takeReading()->diameterMm, 29.0);
    b.station.machine().startPart(2);
    b.clock.advanceTo(800.0);
    b.station.machine().takeFinishedPart();
    b.station.gauge().takeReading();  // the rest of part 1
    b.station.forgetPart(2);          // measured by hand
    EXPECT_FALSE(b.station.gauge().takeReading().has_value());
    b.station.setOutputFault("program protected");
    EXPECT_FALSE(b.station.output().sendPartCorrection(PartCorrection{3, {}, {}, {}}).ok);
    EXPECT_EQ(b.station.output().health().state, DeviceState::Error);
    PartCorrection bad{3, {}, {}, {}};
    b.station.setOutputFault({});
    bad.path.zMm = {0.0, 325.0};
    bad.path.xCorrectionMm = {0.0, std::nan("")};
    EXPECT_FALSE(b.station.output().sendPartCorrection(bad).ok) << "a path with a NaN never reaches the machine";
}

TEST(LatheStatisticalProcess, IsTheDesignModelGainTimesCorrectionPlusDisturbance) {
    const std::vector<DisturbanceModel> points(2, DisturbanceModel({DisturbanceComponent::ar1(0.9, 0.0013)}));
    Eigen::VectorXd gains(2);
    gains << 2.0, 1.5;
    LatheStatisticalProcess process({0.0, 325.0}, gains, LatheDisturbanceModel::fromPointModels(points), 27.0, 325.0,
                                    4);
    LatheDisturbance reference(LatheDisturbanceModel::fromPointModels(points), 4);
    const Eigen::VectorXd f = reference.diameterMm(12);
    const TurnedPart part = process.machine(PartCorrection{12, {0.0, 325.0}, {-0.01, 0.02}, {}});
    EXPECT_NEAR(part.diameterMm[0], 27.0 + 2.0 * -0.01 + f(0), 1e-12);
    EXPECT_NEAR(part.diameterMm[1], 27.0 + 1.5 * 0.02 + f(1), 1e-12);
    EXPECT_THROW(process.machine(PartCorrection{13, {0.0}, {0.1}, {}}), std::invalid_argument);
}

TEST(LatheShop, BuildsThePhysicalLatheOrTheStatisticalPlantWithTheGaugeNoise) {
    ManualClock clock;
    LatheShopSpec spec;
    spec.plant.delay = 1;
    for (double x : {0.0, 162.5, 325.0})
        spec.plant.points.push_back({x, 2.0, DisturbanceModel({DisturbanceComponent::white(1e-4)}), 4e-6});
    LatheShop statistical(spec, clock);
    EXPECT_EQ(statistical.lathe(), nullptr);
    EXPECT_EQ(statistical.pointZMm().size(), 3u);
    spec.lathe = LatheSetup{};
    spec.lathe->beamElementMm = 5.0;
    LatheShop physical(spec, clock);
    ASSERT_NE(physical.lathe(), nullptr);
    EXPECT_EQ(physical.process().nominalDiameterMm(), 27.0);
}

}  // namespace
}  // namespace tt::core
