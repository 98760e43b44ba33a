#include "core/loop/measurement_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tt::core {
namespace {

// Paper 000: five control points on a 325 mm shaft (both ends, the middle and the two
// inflection points 25-30 mm from the left and 50-75 mm from the right end), nominal 27 mm.
const std::vector<double> kPoints{5.0, 30.0, 162.5, 262.5, 320.0};

GaugeReading at(double d, double t = 0.0) {
    return {d, t};
}

TEST(MeasurementSession, AssignsReadingsToPointsInOrderAndShowsTheirPosition) {
    MeasurementSession session(kPoints, 27.0);
    ASSERT_EQ(session.pointCount(), 5u);
    for (std::size_t i = 0; i < kPoints.size(); ++i) {
        ASSERT_EQ(session.currentPoint(), i);
        EXPECT_DOUBLE_EQ(session.pointXMm(*session.currentPoint()), kPoints[i]);
        const SessionAccept r = session.accept(at(27.0 + 0.01 * static_cast<double>(i)));
        EXPECT_TRUE(r.accepted) << describe(r.refusal);
        EXPECT_EQ(r.pointIndex, i);
    }
    EXPECT_TRUE(session.complete());
    const auto d = session.diametersMm();
    ASSERT_EQ(d.size(), 5u);
    EXPECT_DOUBLE_EQ(d[0], 27.0);
    EXPECT_DOUBLE_EQ(d[4], 27.04);
}

TEST(MeasurementSession, RetakeReplacesOnePointAndThenContinuesWhereItWas) {
    MeasurementSession session(kPoints, 27.0);
    session.accept(at(27.010));
    session.accept(at(27.020));
    session.accept(at(27.030));
    session.retake(1);
    EXPECT_EQ(session.currentPoint(), 1u);
    EXPECT_FALSE(session.reading(1).has_value());
    EXPECT_EQ(session.accept(at(27.025)).pointIndex, 1u);
    EXPECT_EQ(session.currentPoint(), 3u);  // continues with the first open point
    session.accept(at(27.040));
    session.accept(at(27.050));
    ASSERT_TRUE(session.complete());
    EXPECT_DOUBLE_EQ(session.diametersMm()[1], 27.025);
    session.retake(4);  // re-taking after completion re-opens only that point
    EXPECT_FALSE(session.complete());
    EXPECT_EQ(session.accept(at(27.055)).pointIndex, 4u);
    EXPECT_DOUBLE_EQ(session.diametersMm()[4], 27.055);
}

TEST(MeasurementSession, RefusesImplausibleReadingsAndKeepsThePointOpen) {
    MeasurementSession session(kPoints, 27.0, 0.5);
    // An inch reading taken for mm (27 mm = 1.063 in) must never be assigned to a point.
    const SessionAccept inch = session.accept(at(1.063));
    EXPECT_FALSE(inch.accepted);
    EXPECT_NE(describe(inch.refusal).find("x = 5.000 mm"), std::string::npos) << describe(inch.refusal);
    EXPECT_FALSE(session.accept(at(std::numeric_limits<double>::quiet_NaN())).accepted);
    EXPECT_EQ(session.currentPoint(), 0u);
    EXPECT_TRUE(session.accept(at(27.4)).accepted);
    EXPECT_THROW((void)session.diametersMm(), std::logic_error);
}

TEST(MeasurementSession, RefusesReadingsOnceCompleteAndBadConstruction) {
    MeasurementSession session({100.0}, 20.0);
    EXPECT_TRUE(session.accept(at(20.0)).accepted);
    EXPECT_FALSE(session.accept(at(20.0)).accepted);
    EXPECT_THROW(MeasurementSession({}, 27.0), std::invalid_argument);
    EXPECT_THROW(MeasurementSession(kPoints, -1.0), std::invalid_argument);
    EXPECT_THROW(MeasurementSession(kPoints, 27.0, 0.0), std::invalid_argument);
    EXPECT_THROW(session.retake(3), std::out_of_range);
}

}  // namespace
}  // namespace tt::core
