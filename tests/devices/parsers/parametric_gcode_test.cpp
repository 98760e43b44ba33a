// The parametric LinuxCNC part program: its structure and its refusals. That rs274 cuts the approximation unit's
// path from it is tests/app/cnc_program; that LinuxCNC does is tests/devices/linuxcnc.
#include <gtest/gtest.h>

#include "devices/parsers/parametric_gcode.h"

namespace {

using namespace tt::devices;

ParametricProgramJob job() {
    ParametricProgramJob j;
    j.pointZMm = {25.0, 87.5, 162.5, 237.5, 300.0};
    for (int k = 0; k <= 650; ++k)
        j.pathZMm.push_back(0.5 * k);
    return j;
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

TEST(ParametricGCode, GuardsTheCutReadsEachParameterAndClearsThePartNumber) {
    const std::string p = writeParametricProgram(job());
    EXPECT_EQ(p.rfind("%\n", 0), 0u);
    EXPECT_NE(p.find("G18 G40 G90 G21 G8 G95 G64 P0.00002000 Q0.00002000\n"), std::string::npos);
    EXPECT_NE(p.find("T1 M6 G43\n"), std::string::npos);
    EXPECT_NE(p.find("O100 if [#505 LT 1]\n(ABORT, TRUETURN: NO CORRECTIONS WERE WRITTEN FOR THIS PART"),
              std::string::npos);
    EXPECT_NE(p.find("O103 if [ABS[#502] GT 0.50000000]\n(ABORT,"), std::string::npos) << p.substr(0, 3000);
    EXPECT_NE(p.find("\n#505=0\n"), std::string::npos);
    EXPECT_LT(p.find("\n#505=0\n"), p.find("G1 ")) << "cleared before the cut";
    EXPECT_EQ(count(p, "\nG1 X"), 650) << "one move per path sample after the first";
    EXPECT_NE(p.find("G1 Z1.000000 F0.250000\nG4 P0.05\nG1 Z0.000000\n"), std::string::npos)
        << "onto the part with a dwell in the air";
    // At a control point the path is the parameter itself.
    EXPECT_NE(p.find("G1 X[13.5000000+1.000000000*#502] Z-162.500000\n"), std::string::npos);
    // Before the first and after the last point the end values are held.
    EXPECT_NE(p.find("G1 X[13.5000000+#500] Z-10.000000\n"), std::string::npos);
    EXPECT_NE(p.find("G1 X[13.5000000+#504] Z-325.000000\n"), std::string::npos);
    EXPECT_EQ(p.substr(p.size() - 5), "M2\n%\n");
    for (std::size_t start = 0, end; (end = p.find('\n', start)) != std::string::npos; start = end + 1)
        EXPECT_LE(end - start, 254u) << p.substr(start, end - start);
}

TEST(ParametricGCode, DiameterModeInchesFeedPerMinuteAndTheSplineSlopes) {
    ParametricProgramJob j = job();
    j.conventions = {true, true};
    j.feedPerMinute = true;
    j.feed = 2540.0;
    j.spindleRpm = 0;
    j.slopes = ParametricSlopes::Weights;
    j.slopeWeights.assign(5, std::vector<double>(5, 0.0));
    j.slopeWeights[2][1] = -0.01;
    j.slopeWeights[2][3] = 0.01;
    const std::string p = writeParametricProgram(j);
    EXPECT_NE(p.find("G20 G7 G94"), std::string::npos);
    EXPECT_NE(p.find("F100.000\n"), std::string::npos) << "2540 mm/min = 100 in/min";
    EXPECT_EQ(p.find("M3"), std::string::npos) << "no spindle words at 0 rpm";
    EXPECT_NE(p.find("#<_tt_d2>=[[-0.254000000000*#501]+[0.254000000000*#503]]\n"), std::string::npos)
        << "slopes per inch";
    EXPECT_NE(p.find("#<_tt_d0>=[0]\n"), std::string::npos);
    EXPECT_NE(p.find("G1 X[1.06299213+1.000000000*#502] Z-6.397638\n"), std::string::npos)
        << "27 mm = 1.06299213 in on diameter, z 162.5 mm = 6.397638 in towards the chuck";
}

TEST(ParametricGCode, WearModeCutsTheNominalPathWithTheWearApplied) {
    ParametricProgramJob j = job();
    j.firstParameter = 0;
    j.wearTool = 10001;
    j.feedForwardMm.assign(j.pathZMm.size(), -0.01);
    const std::string p = writeParametricProgram(j);
    EXPECT_NE(p.find("T1 M6 G43\nG43.2 H10001\n"), std::string::npos);
    EXPECT_EQ(p.find('#'), std::string::npos) << "no parameter is read";
    EXPECT_NE(p.find("G1 X13.4900000 Z-162.500000\n"), std::string::npos);
}

TEST(ParametricGCode, RefusesABadJob) {
    ParametricProgramJob j = job();
    j.pointZMm = {25.0, 25.0};
    EXPECT_THROW(writeParametricProgram(j), std::invalid_argument);
    j = job();
    j.firstParameter = 4996;
    EXPECT_THROW(writeParametricProgram(j), std::invalid_argument) << "#4996..#5001";
    j = job();
    j.feedForwardMm = {0.1};
    EXPECT_THROW(writeParametricProgram(j), std::invalid_argument);
    j = job();
    j.feed = 6.0;
    EXPECT_THROW(writeParametricProgram(j), std::invalid_argument) << "6 mm/rev";
    j = job();
    j.slopes = ParametricSlopes::Weights;
    EXPECT_THROW(writeParametricProgram(j), std::invalid_argument) << "no weights";
}

}  // namespace
