// Checks shared by the run-to-run controllers (LQG, EWMA, open loop): where a measurement can be
// placed, why a value is refused, the ring-buffer slots and the configuration fingerprint.
#include "core/control/run_to_run_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tt::core {
namespace {

TEST(RunToRunChecks, PlacesAMeasurementOnlyOnAMachinedKeptPart) {
    const MachinedParts parts{true, 10, 20, 8};
    EXPECT_FALSE(partRejection(parts, 15, true));
    EXPECT_EQ(describe(*partRejection(parts, 21, true)), "part 21 has not been machined yet");
    EXPECT_EQ(describe(*partRejection(MachinedParts{}, 1, true)), "part 1 has not been machined yet");
    EXPECT_EQ(describe(*partRejection(parts, 9, true)), "part 9 was not machined under this controller");
    EXPECT_EQ(describe(*partRejection(parts, 11, false)), "part 11 is too late: the controller keeps the last 8 parts");
}

TEST(RunToRunChecks, RefusesNonFiniteAndRepeatedValues) {
    EXPECT_FALSE(valueRejection(0.01, false, 3));
    EXPECT_EQ(describe(*valueRejection(std::numeric_limits<double>::quiet_NaN(), false, 3)), "not measured");
    EXPECT_EQ(describe(*valueRejection(std::numeric_limits<double>::infinity(), true, 3)), "not a finite number");
    EXPECT_EQ(describe(*valueRejection(0.01, true, 3)), "point already measured for part 3");
    const MeasurementVerdict v = rejectEveryPoint(3, Notice(NoticeKind::NotMachinedYet, 4));
    EXPECT_EQ(v.accepted, std::vector<bool>(3, false));
    ASSERT_EQ(v.reasons.size(), 3u);
    for (const Notice& why : v.reasons)
        EXPECT_EQ(describe(why), "part 4 has not been machined yet");
}

TEST(RunToRunChecks, SizesPartOrderAndHistory) {
    EXPECT_NO_THROW(requireMeasurementSize({1, Eigen::VectorXd::Zero(5)}, 5, "X"));
    try {
        requireMeasurementSize({1, Eigen::VectorXd::Zero(4)}, 5, "X");
        FAIL() << "a measurement with 4 values for 5 points must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "X: a measurement needs 5 values, got 4");
    }
    EXPECT_NO_THROW(requireNextPart(false, 0, 17, "X")) << "the first part can have any number";
    EXPECT_NO_THROW(requireNextPart(true, 16, 17, "X"));
    try {
        requireNextPart(true, 16, 18, "X");
        FAIL() << "a skipped part must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "X: part numbers must increase by one (expected 17, got 18)");
    }
    EXPECT_NO_THROW(requireHistoryParts(1, "X"));
    EXPECT_NO_THROW(requireHistoryParts(kMaxHistoryParts, "X"));
    EXPECT_THROW(requireHistoryParts(0, "X"), std::invalid_argument);
    EXPECT_THROW(requireHistoryParts(kMaxHistoryParts + 1, "X"), std::invalid_argument);
}

TEST(RunToRunChecks, RingSlotsWrapNegativeIndicesToo) {
    EXPECT_EQ(ringSlot(0, 4), 0u);
    EXPECT_EQ(ringSlot(5, 4), 1u);
    EXPECT_EQ(ringSlot(-1, 4), 3u);  // the LQG filter starts at step p - z, which can be negative
    EXPECT_EQ(ringSlot(-8, 4), 0u);
}

TEST(RunToRunChecks, FingerprintIsTheCrcOfTheNumbersBytes) {
    const std::vector<double> a{0.3, 0.1, 64.0};
    std::vector<double> b = a;
    EXPECT_EQ(configurationFingerprint(a), configurationFingerprint(b));
    b[2] = 63.0;
    EXPECT_NE(configurationFingerprint(a), configurationFingerprint(b));
    // No numbers: the CRC of no bytes is the initial value 0xFFFF (CRC-16/CCITT-FALSE).
    EXPECT_EQ(configurationFingerprint({}), 0xFFFF);
}

}  // namespace
}  // namespace tt::core
