// The MDI lines TrueTurn sends to LinuxCNC: exact text, units and X mode, the checks LinuxCNC evaluates, limits.
// That LinuxCNC reads them as intended is shown against the real controller in tests/devices/linuxcnc.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/parsers/linuxcnc_mdi.h"

namespace {

using namespace tt::devices::linuxcnc;

TEST(LinuxCncMdi, WritesRadialMillimetresWithSixDecimalsAndThePartNumberLast) {
    const std::vector<double> values{0.0123, -0.0211, 0.0, 0.03094, -0.0087};
    const ParameterWrite w = parameterWrite(500, values, 12, {});
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_EQ(w.lines[0], "#500=0.012300 #501=-0.021100 #502=0.000000 #503=0.030940 #504=-0.008700 #505=12");
    ASSERT_EQ(w.checks.size(), 2u) << "five values a check line, then the part number";
    EXPECT_EQ(w.checks[0],
              "#<_trueturn_check>=[1/[[ABS[#500-0.012300]+ABS[#501--0.021100]+ABS[#502-0.000000]+ABS[#503-0.030940]"
              "+ABS[#504--0.008700]] LT 0.0000001]]");
    EXPECT_EQ(w.checks[1], "#<_trueturn_check>=[1/[[ABS[#505-12]] LT 0.0000001]]");
    EXPECT_EQ(w.writtenMm, values);
    for (const std::string& line : w.lines)
        EXPECT_LE(line.size(), kMaxMdiLength);
    for (const std::string& line : w.checks)
        EXPECT_LE(line.size(), kMaxMdiLength);
}

TEST(LinuxCncMdi, WritesDiameterValuesInDiameterModeAndInchesInInchPrograms) {
    const std::vector<double> values{0.0127};
    const ParameterWrite diameter = parameterWrite(600, values, 1, {false, true});
    EXPECT_EQ(diameter.lines[0], "#600=0.025400 #601=1") << "a diameter correction is twice the radial one";
    EXPECT_EQ(diameter.writtenMm[0], 0.0127);
    const ParameterWrite inch = parameterWrite(600, values, 1, {true, false});
    EXPECT_EQ(inch.lines[0], "#600=0.000500 #601=1") << "0.0127 mm = 0.0005 in";
    EXPECT_NEAR(inch.writtenMm[0], 0.0127, 1e-15);
    // Six decimals of an inch: what LinuxCNC holds is the rounded value, reported as written.
    const ParameterWrite rounded = parameterWrite(600, std::vector<double>{0.01}, 1, {true, true});
    EXPECT_EQ(rounded.literals[0], "0.000787");
    EXPECT_NEAR(rounded.writtenMm[0], 0.000787 / 2.0 * 25.4, 1e-15);
}

TEST(LinuxCncMdi, SplitsLongWritesAndKeepsThePartNumberInTheLastLine) {
    const std::vector<double> values(11, -0.123456);
    const ParameterWrite w = parameterWrite(31, values, 99999, {});
    ASSERT_EQ(w.lines.size(), 2u);
    EXPECT_EQ(w.lines[0].rfind("#31=", 0), 0u);
    EXPECT_NE(w.lines[1].find("#42=99999"), std::string::npos);
    EXPECT_EQ(w.lines[1].find("#42=99999") + 9, w.lines[1].size()) << "the part number is the last word";
    EXPECT_EQ(w.checks.size(), 3u);
    for (const std::string& line : w.lines)
        EXPECT_LE(line.size(), kMaxMdiLength);
    for (const std::string& line : w.checks)
        EXPECT_LE(line.size(), kMaxMdiLength);
}

TEST(LinuxCncMdi, RefusesParametersOutsideTheFreeRangeAndBadValues) {
    const std::vector<double> five(5, 0.01);
    EXPECT_THROW(parameterWrite(30, five, 1, {}), std::invalid_argument);
    EXPECT_THROW(parameterWrite(4996, five, 1, {}), std::invalid_argument) << "#4996 .. #5001";
    EXPECT_NO_THROW(parameterWrite(4995, five, 1, {}));
    EXPECT_THROW(parameterWrite(500, five, 0, {}), std::invalid_argument) << "part numbers start at 1";
    EXPECT_THROW(parameterWrite(500, std::vector<double>{}, 1, {}), std::invalid_argument);
    EXPECT_THROW(parameterWrite(500, std::vector<double>{std::nan("")}, 1, {}), std::invalid_argument);
}

TEST(LinuxCncMdi, WritesTheWearAndChecksItThroughTheProgrammedX) {
    const WearWrite radius = wearWrite(1, 10001, -0.0105, {});
    EXPECT_EQ(radius.modes, "G21 G8");
    EXPECT_EQ(radius.line, "G10 L1 P10001 X-0.010500");
    EXPECT_EQ(radius.writtenMm, -0.0105);
    ASSERT_EQ(radius.verify.size(), 4u);
    EXPECT_EQ(radius.verify[0], "G43 H1");
    EXPECT_EQ(radius.verify[1], "#<_trueturn_x_before_wear>=#5420");
    EXPECT_EQ(radius.verify[2], "G43.2 H10001");
    EXPECT_EQ(radius.verify[3],
              "#<_trueturn_check>=[1/[[ABS[[#<_trueturn_x_before_wear>-#5420]--0.010500]] LT 0.0000001]]");
    // Diameter mode: LinuxCNC stores half the X word of G10 L1 (a radius), so the word is the diameter correction.
    const WearWrite diameter = wearWrite(3, 7, -0.0105, {true, true});
    EXPECT_EQ(diameter.modes, "G20 G7");
    EXPECT_EQ(diameter.line, "G10 L1 P7 X-0.000827");
    EXPECT_NEAR(diameter.writtenMm, -0.000827 / 2.0 * 25.4, 1e-15);
    EXPECT_EQ(diameter.verify[3],
              "#<_trueturn_check>=[1/[[ABS[[#<_trueturn_x_before_wear>-#5420]-[-0.000827/2]]] LT 0.0000001]]");
    EXPECT_THROW(wearWrite(0, 7, 0.0, {}), std::invalid_argument);
    EXPECT_THROW(wearWrite(1, 7, std::nan(""), {}), std::invalid_argument);
}

TEST(LinuxCncMdi, AsksForParametersInATaggedMessage) {
    const std::vector<std::string> names{parameterName(500), "#5420"};
    EXPECT_EQ(debugLine("TRUETURN3", names), "(DEBUG,TRUETURN3 #500 #5420)");
    EXPECT_EQ(sixDecimals(-0.0000001), "0.000000");
}

}  // namespace
