// The CNC program of a feed schedule (devices/parsers/gcode_writer: writeFeedScheduleGCode) line by line,
// in both dialects. That a real interpreter accepts it is tested in tests/app/feed_schedule (rs274).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "devices/parsers/gcode_writer.h"

namespace tt::devices {
namespace {

FeedPassProgram program() {
    FeedPassProgram p;
    // The hand schedule of feed_scheduler_test: 100 -> 50 at 0.15, 50 -> 20 at 0.2, 20 -> 0 at 0.25 mm/rev.
    p.segments = {{100.0, 50.0, 0.15, 30.0, 22.5}, {50.0, 20.0, 0.2, 30.0, 24.0}, {20.0, 0.0, 0.25, 30.0, 25.0}};
    p.notes = {"Yc 30 um (Y1 20, Y2 40)"};
    return p;
}

FeedPassJob job(GCodeDialect dialect) {
    FeedPassJob j;
    j.finishDiameterMm = 40.0;
    j.depthMm = 1.0;
    j.spindleRpm = 600;
    j.zOriginMm = -100.0;  // machine Z = z - 100: Z0 at the tailstock end
    j.zDirection = 1;
    j.dialect = dialect;
    return j;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        out.push_back(l);
    return out;
}

/// The lines after the header comments.
std::vector<std::string> body(const std::string& text) {
    std::vector<std::string> out;
    for (const std::string& l : lines(text))
        if (l.empty() || l.front() != '(') out.push_back(l);
    return out;
}

TEST(FeedProgram, FanucStyleProgram) {
    const std::string g = writeFeedScheduleGCode(program(), job(GCodeDialect::Fanuc));
    const std::vector<std::string> expected = {
        "%",
        "O4004 (TRUETURN FEED SCHEDULE)",
        "G18 G21 G40 G90 G95",
        "T0101",
        "G97 S600 M3",
        "M8",
        "G0 X46.000 Z2.000",  // safe X = 40 + 2 * 1 + 2 * 2; a clearance before z = 100 (Z0)
        "G0 X40.000",
        "G1 Z0.000 F0.1500",
        "G1 Z-50.000 F0.1500",
        "G1 Z-80.000 F0.2000",
        "G1 Z-100.000 F0.2500",
        "G0 X46.000",
        "G0 Z2.000",
        "M9",
        "M5",
        "M30",
        "%",
    };
    EXPECT_EQ(body(g), expected);
    const auto l = lines(g);
    EXPECT_NE(std::find(l.begin(), l.end(), "(YC 30 UM <Y1 20, Y2 40>)"), l.end()) << g;  // no nested parentheses
    EXPECT_NE(std::find(l.begin(), l.end(), "(SEG 2 Z-50.000 TO Z-80.000 F0.2000 Y 30.0 TO 24.0 UM)"), l.end()) << g;
    EXPECT_NE(g.find("G-CODE SYSTEM B"), std::string::npos);
}

TEST(FeedProgram, LinuxCncProgram) {
    FeedPassJob j = job(GCodeDialect::LinuxCnc);
    j.coolant = false;
    const std::string g = writeFeedScheduleGCode(program(), j);
    const std::vector<std::string> b = body(g);
    ASSERT_GE(b.size(), 4U);
    EXPECT_EQ(b[0], "%");
    EXPECT_EQ(b[1], "G18 G21 G40 G90 G95 G7");  // no O word: rs274ngc's O words are subroutine labels
    EXPECT_EQ(b[2], "T1 M6 G43");
    EXPECT_EQ(std::count(b.begin(), b.end(), "M8"), 0);  // coolant off in this job
    EXPECT_EQ(std::count(b.begin(), b.end(), "M9"), 0);
    EXPECT_NE(g.find("(PROGRAM 4004 TRUETURN FEED SCHEDULE)"), std::string::npos);
}

TEST(FeedProgram, FeedsAreRoundedDownAndZFollowsTheMachineAxis) {
    FeedPassProgram p = program();
    p.segments[0].feedMmPerRev = 0.064199;  // never more than scheduled: 0.0641, not 0.0642
    FeedPassJob j = job(GCodeDialect::Fanuc);
    j.zOriginMm = 0.0;
    j.zDirection = -1;  // machine Z = -z
    const auto b = body(writeFeedScheduleGCode(p, j));
    EXPECT_NE(std::find(b.begin(), b.end(), "G1 Z-50.000 F0.0641"), b.end());
    EXPECT_NE(std::find(b.begin(), b.end(), "G1 Z0.000 F0.2500"), b.end()) << "z = 0 is Z0, never -0.000";
}

TEST(FeedProgram, RefusesWhatIsNotAPass) {
    const FeedPassJob j = job(GCodeDialect::Fanuc);
    EXPECT_THROW(writeFeedScheduleGCode(FeedPassProgram{}, j), std::invalid_argument);
    FeedPassProgram gap = program();
    gap.segments[1].zFromMm = 49.0;
    EXPECT_THROW(writeFeedScheduleGCode(gap, j), std::invalid_argument);
    FeedPassProgram back = program();
    back.segments[2].zToMm = 30.0;  // turns round
    EXPECT_THROW(writeFeedScheduleGCode(back, j), std::invalid_argument);
    FeedPassProgram fast = program();
    fast.segments[0].feedMmPerRev = 6.0;
    EXPECT_THROW(writeFeedScheduleGCode(fast, j), std::invalid_argument);
    FeedPassJob bad = j;
    bad.spindleRpm = 0;
    EXPECT_THROW(writeFeedScheduleGCode(program(), bad), std::invalid_argument);
    bad = j;
    bad.zDirection = 0;
    EXPECT_THROW(writeFeedScheduleGCode(program(), bad), std::invalid_argument);
    EXPECT_EQ(gcodeDialectFromName("linuxcnc"), GCodeDialect::LinuxCnc);
    EXPECT_EQ(gcodeDialectName(GCodeDialect::Fanuc), "fanuc");
    EXPECT_THROW(gcodeDialectFromName("sinumerik"), std::invalid_argument);
}

}  // namespace
}  // namespace tt::devices
