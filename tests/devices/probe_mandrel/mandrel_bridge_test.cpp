// The emulated mandrel's bridge (devices/simulator/mandrel_emulator.h) is a plausible differential
// bridge over its whole 16-bit ADC range (paper 001: static characteristic of degree 2..4,
// symmetric about the middle): monotonic up to the ADC's limits, so a full-range table of it is
// accepted; its delivery table inverts it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "devices/simulator/mandrel_emulator.h"

namespace tt::devices {
namespace {

TEST(MandrelBridge, IsMonotonicAndSymmetricUpToTheAdcLimits) {
    const double fullScale = MandrelEmulator::fullScaleDeflectionMm();
    // u = 1 at the tip deflection 0.25 mm / (0.9² (3 − 0.9) / 2) = 0.29394 mm.
    EXPECT_NEAR(fullScale, 0.29394, 1e-5);
    double previous = -1.0;
    for (int i = 0; i <= 2000; ++i) {
        const double mm = -fullScale + fullScale * i / 1000.0;
        const double code = MandrelEmulator::exactCode(mm);
        EXPECT_GT(code, previous) << "not increasing at " << mm << " mm";
        previous = code;
        // Symmetric about the middle code 32767.5.
        EXPECT_NEAR(code - 32767.5, 32767.5 - MandrelEmulator::exactCode(-mm), 1e-6);
    }
    EXPECT_NEAR(MandrelEmulator::exactCode(fullScale), 65535.0, 1e-6);
    EXPECT_NEAR(MandrelEmulator::exactCode(-fullScale), 0.0, 1e-6);
    // Beyond full scale the ADC sits at its limit (flagged over range), never turns back.
    EXPECT_EQ(MandrelEmulator::adcCode(0.35), 65535);
    EXPECT_EQ(MandrelEmulator::adcCode(-0.35), 0);
    // Sensitivity at the middle: 1.15 * 0.8505 / 0.25 mm * 65535 / 2 = 128 200 codes/mm (7.8 nm a code).
    EXPECT_NEAR((MandrelEmulator::exactCode(1e-4) - MandrelEmulator::exactCode(-1e-4)) / 2e-4, 128200.0, 5.0);
}

TEST(MandrelBridge, AFullRangeTableIsAcceptedAsMonotonic) {
    // The characteristic the first emulator had (code = 32768 + 2e5 d − 5e6 d³) turned at
    // ±0.115 mm inside its ADC range and was refused; this one covers ±95 % of full scale.
    std::vector<core::CalibrationPoint> points;
    const double span = 0.95 * MandrelEmulator::fullScaleDeflectionMm();
    for (int i = 0; i <= 30; ++i) {
        const double mm = -span + 2.0 * span * i / 30.0;
        points.push_back({mm * 1000.0, static_cast<double>(MandrelEmulator::adcCode(mm)), 0});
    }
    const core::Linearisation lin = core::linearise(points, 16, core::kAutoDegree);
    EXPECT_TRUE(lin.fit.monotonicity.monotonic) << lin.fit.monotonicity.message;
    EXPECT_EQ(lin.fit.degree, 3);  // the bridge is an odd cubic in the deflection
    // Rounding the codes is the only error: half a code is 3.9 nm at the middle, 7 nm at the ends.
    EXPECT_LT(lin.maxTableErrorUm, 0.02);
}

TEST(MandrelBridge, TheDeliveryTableInvertsTheBridge) {
    const core::TableImage image = core::decodeTableImage(MandrelEmulator::deliveryTableImage());
    EXPECT_EQ(image.format, core::kTableImageFormat);
    EXPECT_EQ(image.table.adcBits, 16);
    EXPECT_EQ(image.info.version, 1);
    for (double mm = -0.26; mm <= 0.26; mm += 0.01) {
        const int code = MandrelEmulator::adcCode(mm);
        // Table unit (scale) and the code's rounding: well under 0.05 µm.
        EXPECT_NEAR(image.table.deflectionUm(code), mm * 1000.0, 0.05) << "at " << mm << " mm";
    }
}

}  // namespace
}  // namespace tt::devices
