#include "devices/parsers/gcode_writer.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

namespace tt::devices {
namespace {

core::PartCorrection correction() {
    core::PartCorrection c;
    c.partNumber = 12;
    c.pointZMm = {5.0, 162.5, 320.0};
    c.pointCorrectionMm = {-0.010, -0.075, -0.005};
    c.path.zMm = {0.0, 100.0, 162.5, 325.0};
    c.path.xCorrectionMm = {-0.010, -0.050, -0.075, -0.005};
    return c;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        out.push_back(l);
    return out;
}

TEST(GCodeWriter, StatesUnitsModeAndPartInTheHeader) {
    const std::string g = writeCorrectionGCode(correction(), GCodeJob{});
    EXPECT_NE(g.find("(PART 12)"), std::string::npos);
    EXPECT_NE(g.find("G21"), std::string::npos);
    EXPECT_NE(g.find("DIAMETER MODE"), std::string::npos);
    EXPECT_NE(g.find("NOMINAL DIAMETER 27.000 MM, FEED 0.250 MM/REV"), std::string::npos);
    EXPECT_NE(g.find("X5.000=-0.010 X162.500=-0.075 X320.000=-0.005"), std::string::npos);
    EXPECT_EQ(lines(g).front(), "%");
    EXPECT_EQ(lines(g).back(), "%");
}

TEST(GCodeWriter, OneSegmentPerPathPointWithItsCorrection) {
    // Diameter mode: X = 27 + 2 * correction; machine Z = -x.
    const auto l = lines(writeCorrectionGCode(correction(), GCodeJob{}));
    std::vector<std::string> segments;
    for (const auto& s : l)
        if (s.rfind("G1 X", 0) == 0) segments.push_back(s);
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_EQ(segments[0], "G1 X26.900 Z-100.000 (SEG 1 X100.000 DX-0.050)");
    EXPECT_EQ(segments[1], "G1 X26.850 Z-162.500 (SEG 2 X162.500 DX-0.075)");
    EXPECT_EQ(segments[2], "G1 X26.990 Z-325.000 (SEG 3 X325.000 DX-0.005)");
    EXPECT_NE(std::find(l.begin(), l.end(), "G0 X26.980"), l.end());  // approach to the first point
}

TEST(GCodeWriter, RadiusModeWritesRadii) {
    GCodeJob job;
    job.diameterMode = false;
    job.emitModeCode = true;
    job.zDirection = 1;
    job.zOriginMm = 10.0;
    const std::string g = writeCorrectionGCode(correction(), job);
    EXPECT_NE(g.find("RADIUS MODE"), std::string::npos);
    EXPECT_NE(g.find("G18 G21 G40 G90 G95 G8"), std::string::npos);
    EXPECT_NE(g.find("G1 X13.425 Z172.500 (SEG 2"), std::string::npos);  // 13.5 - 0.075; 10 + 162.5
}

TEST(GCodeWriter, RefusesBadPathsInTheUsersTerms) {
    auto c = correction();
    c.path.xCorrectionMm.pop_back();
    EXPECT_THROW(writeCorrectionGCode(c, GCodeJob{}), std::invalid_argument);
    c = correction();
    c.path.zMm[2] = 50.0;
    EXPECT_THROW(writeCorrectionGCode(c, GCodeJob{}), std::invalid_argument);
    c = correction();
    c.path.xCorrectionMm[1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(writeCorrectionGCode(c, GCodeJob{}), std::invalid_argument);
    c = correction();
    c.path.xCorrectionMm[1] = -0.8;
    try {
        writeCorrectionGCode(c, GCodeJob{});
        FAIL() << "a correction beyond the limit was written";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("exceeds the limit of 0.500 mm"), std::string::npos) << e.what();
    }
    GCodeJob job;
    job.feedMmPerRev = 0.0;
    EXPECT_THROW(writeCorrectionGCode(correction(), job), std::invalid_argument);
}

}  // namespace
}  // namespace tt::devices
