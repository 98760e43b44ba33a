#pragma once

// The comparison a run through LinuxCNC must pass against the same run on the built-in simulated lathe: per control
// point, the systematic error (the mean true diameter deviation after the loop's start-up of 2z + 5 parts) within
// 10 % of the built-in one or 2 um, whichever is larger, and the largest of them alike. Shared by the loop test
// (tests/devices/linuxcnc) and the `simulate --cnc` test (tests/app/simulate_cnc).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

namespace tt::test {

/// What a systematic error may differ by from the built-in lathe's: 10 % of it or 2 um, mm.
inline double allowedSystematicDifferenceMm(double builtInMm) {
    return std::max(0.1 * std::fabs(builtInMm), 0.002);
}

/// Expects each point's systematic error through LinuxCNC, and their largest magnitude, within
/// allowedSystematicDifferenceMm of the built-in lathe's; records both per point as test properties
/// (point1_builtin_um, point1_linuxcnc_um, ...).
inline void expectSystematicErrorsMatch(const Eigen::VectorXd& builtInMm, const Eigen::VectorXd& linuxCncMm) {
    ASSERT_EQ(builtInMm.size(), linuxCncMm.size());
    for (Eigen::Index i = 0; i < builtInMm.size(); ++i) {
        const std::string key = "point" + std::to_string(i + 1);
        ::testing::Test::RecordProperty(key + "_builtin_um", std::to_string(1000.0 * builtInMm(i)));
        ::testing::Test::RecordProperty(key + "_linuxcnc_um", std::to_string(1000.0 * linuxCncMm(i)));
        EXPECT_NEAR(linuxCncMm(i), builtInMm(i), allowedSystematicDifferenceMm(builtInMm(i)))
            << "point " << i + 1 << ": systematic error through LinuxCNC " << linuxCncMm(i) * 1000.0 << " um, built-in "
            << builtInMm(i) * 1000.0 << " um";
    }
    const double largestBuiltIn = builtInMm.cwiseAbs().maxCoeff();
    EXPECT_NEAR(linuxCncMm.cwiseAbs().maxCoeff(), largestBuiltIn, allowedSystematicDifferenceMm(largestBuiltIn));
}

}  // namespace tt::test
