// The simulated plant that differs from the model (core/sim/shaft/plant_mismatch.h).
#include <gtest/gtest.h>

#include "core/sim/shaft/plant_mismatch.h"

namespace tt::core {
namespace {

/// A process whose part diameter at every point is 10 + the first point correction (deterministic).
class EchoProcess final : public LathePartProcess {
public:
    TurnedPart machine(const PartCorrection& c) override {
        TurnedPart p;
        p.partNumber = c.partNumber;
        p.zMm = {0.0, 100.0};
        const double u = c.pointCorrectionMm.empty() ? 0.0 : c.pointCorrectionMm[0];
        p.diameterMm = {10.0 + u, 10.0 + u};
        return p;
    }
    double nominalDiameterMm() const override { return 10.0; }
    double partLengthMm() const override { return 100.0; }
};

PartCorrection correction(std::int64_t part, double u) {
    return PartCorrection{part, {0.0, 100.0}, {u, u}, {}};
}

// A plant one part slower machines part n with the correction sent for part n - 1 (part 1 with its own:
// nothing was sent before); a step at point 2 from part 3 on shifts that point only.
TEST(PlantMismatch, LagAndStep) {
    MismatchedProcess p(std::make_unique<EchoProcess>(), 1, PlantStep{3, 0.02, 1}, {0.0, 100.0});
    EXPECT_DOUBLE_EQ(p.machine(correction(1, 0.1)).diameterMm[0], 10.1);
    EXPECT_DOUBLE_EQ(p.machine(correction(2, 0.2)).diameterMm[0], 10.1);
    const TurnedPart third = p.machine(correction(3, 0.3));
    EXPECT_EQ(third.partNumber, 3);
    EXPECT_DOUBLE_EQ(third.diameterMm[0], 10.2);
    EXPECT_DOUBLE_EQ(third.diameterMm[1], 10.22);
}

TEST(PlantMismatch, RefusesWhatCannotBeSimulated) {
    PlantMismatch m;
    m.delayParts = 1;
    EXPECT_THROW(m.validate(2, 5), std::invalid_argument);  // shorter than the model's delay
    m = {};
    m.gainFactor = 0.05;
    EXPECT_THROW(m.validate(2, 5), std::invalid_argument);
    m = {};
    m.step = PlantStep{1, 0.0, std::nullopt};
    EXPECT_THROW(m.validate(2, 5), std::invalid_argument);
    m.step = PlantStep{1, 0.02, 5};
    EXPECT_THROW(m.validate(2, 5), std::invalid_argument);  // points 0 .. 4
    m.step = PlantStep{1, 0.02, 4};
    EXPECT_NO_THROW(m.validate(2, 5));
    EXPECT_TRUE(m.any());
}

}  // namespace
}  // namespace tt::core
