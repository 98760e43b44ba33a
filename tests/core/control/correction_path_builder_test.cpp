#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/control/correction_path_builder.h"

namespace tt::core {
namespace {

// Table 1 of paper 000 (shared/SEEDS.md, section 000), group 1: d(x) in mm, x in mm.
ScaledPolynomial tableOneGroupOne() {
    Eigen::VectorXd b(6);
    b << 0.071, -0.000132, 2.379e-5, -2.09e-7, 6.42e-10, -6.6e-13;
    return ScaledPolynomial::fromPowerCoefficients(b);
}

// The five control points of paper 000 on a 325 mm shaft: both ends, the two inflection points
// (25-30 mm from the left, 50-75 mm from the right end) and the middle.
CorrectionPathRequest paperRequest() {
    CorrectionPathRequest r;
    r.pointZMm = {0.0, 27.5, 162.5, 262.5, 325.0};
    r.pointCorrectionMm = {0.004, -0.010, 0.015, -0.006, 0.002};
    r.partLengthMm = 325.0;
    r.stepMm = 0.5;
    return r;
}

TEST(CorrectionPath, SamplesThePartFromZeroToItsLengthAtTheStep) {
    const CorrectionPath path = buildCorrectionPath(paperRequest());
    ASSERT_EQ(path.zMm.size(), 651U);  // 325 / 0.5 + 1
    ASSERT_EQ(path.xCorrectionMm.size(), path.zMm.size());
    EXPECT_DOUBLE_EQ(path.zMm.front(), 0.0);
    EXPECT_DOUBLE_EQ(path.zMm.back(), 325.0);
    for (std::size_t i = 1; i < path.zMm.size(); ++i)
        EXPECT_NEAR(path.zMm[i] - path.zMm[i - 1], 0.5, 1e-12);
}

TEST(CorrectionPath, AStepThatDoesNotDivideTheLengthStillEndsExactlyAtTheEnd) {
    CorrectionPathRequest r;
    r.partLengthMm = 10.0;
    r.stepMm = 3.0;
    const CorrectionPath path = buildCorrectionPath(r);
    EXPECT_EQ(path.zMm, (std::vector<double>{0.0, 3.0, 6.0, 9.0, 10.0}));
    r.stepMm = 50.0;  // coarser than the part: both ends only
    EXPECT_EQ(buildCorrectionPath(r).zMm, (std::vector<double>{0.0, 10.0}));
}

TEST(CorrectionPath, PassesThroughTheControlPointCorrections) {
    const CorrectionPathRequest r = paperRequest();
    const CorrectionProfile profile(r);
    for (std::size_t i = 0; i < r.pointZMm.size(); ++i)
        EXPECT_NEAR(profile.correctionMm(r.pointZMm[i]), r.pointCorrectionMm[i], 1e-15);
}

TEST(CorrectionPath, FeedForwardIsMinusHalfTheDiameterError) {
    // Paper 000: a diameter error d needs a radial move of -d/2; no control points: feed-forward only.
    CorrectionPathRequest r;
    r.partLengthMm = 325.0;
    r.stepMm = 25.0;
    r.diameterErrorModel = tableOneGroupOne();
    const CorrectionPath path = buildCorrectionPath(r);
    ASSERT_EQ(path.zMm.size(), 14U);  // every 25 mm, as the parts were gauged in the paper
    for (std::size_t i = 0; i < path.zMm.size(); ++i) {
        const double x = path.zMm[i];
        const double d = 0.071 - 0.000132 * x + 2.379e-5 * x * x - 2.09e-7 * std::pow(x, 3) +
                         6.42e-10 * std::pow(x, 4) - 6.6e-13 * std::pow(x, 5);
        EXPECT_NEAR(path.xCorrectionMm[i], -d / 2.0, 1e-15) << "at " << x << " mm";
    }
}

TEST(CorrectionPath, SetPointIsFeedForwardPlusInterpolatedCorrection) {
    CorrectionPathRequest r = paperRequest();
    r.diameterErrorModel = tableOneGroupOne();
    const CorrectionPath path = buildCorrectionPath(r);
    const PiecewiseCubic y = PiecewiseCubic::pchip(r.pointZMm, r.pointCorrectionMm);
    const ScaledPolynomial d = tableOneGroupOne();
    for (std::size_t i = 0; i < path.zMm.size(); i += 37)
        EXPECT_NEAR(path.xCorrectionMm[i], -0.5 * d(path.zMm[i]) + y(path.zMm[i]), 1e-15);
}

TEST(CorrectionPath, EndCorrectionsAreHeldBeyondTheOuterControlPoints) {
    CorrectionPathRequest r;
    r.pointZMm = {30.0, 160.0, 270.0};
    r.pointCorrectionMm = {0.01, -0.02, 0.005};
    r.partLengthMm = 325.0;
    r.stepMm = 1.0;
    for (InterpolationMethod m : {InterpolationMethod::Pchip, InterpolationMethod::NaturalSpline}) {
        r.method = m;
        const CorrectionPath path = buildCorrectionPath(r);
        for (std::size_t i = 0; i < path.zMm.size(); ++i) {
            if (path.zMm[i] <= 30.0) {
                EXPECT_DOUBLE_EQ(path.xCorrectionMm[i], 0.01);
            }
            if (path.zMm[i] >= 270.0) {
                EXPECT_DOUBLE_EQ(path.xCorrectionMm[i], 0.005);
            }
        }
    }
}

TEST(CorrectionPath, PchipPathStaysWithinTheAppliedCorrections) {
    // Safety of the default: the cutter never moves further than the largest per-point correction.
    const CorrectionPathRequest r = paperRequest();
    const CorrectionPath path = buildCorrectionPath(r);
    const auto [lo, hi] = std::minmax_element(r.pointCorrectionMm.begin(), r.pointCorrectionMm.end());
    for (double v : path.xCorrectionMm) {
        EXPECT_GE(v, *lo - 1e-15);
        EXPECT_LE(v, *hi + 1e-15);
    }
}

TEST(CorrectionPath, OnePointGivesAConstantCorrectionAndNoPointsGiveZero) {
    CorrectionPathRequest r;
    r.pointZMm = {162.5};
    r.pointCorrectionMm = {-0.012};
    r.partLengthMm = 325.0;
    r.stepMm = 5.0;
    for (double v : buildCorrectionPath(r).xCorrectionMm)
        EXPECT_DOUBLE_EQ(v, -0.012);
    r.pointZMm.clear();
    r.pointCorrectionMm.clear();
    for (double v : buildCorrectionPath(r).xCorrectionMm)
        EXPECT_DOUBLE_EQ(v, 0.0);
}

void expectRefused(const CorrectionPathRequest& r, const std::string& phrase) {
    try {
        buildCorrectionPath(r);
        FAIL() << "expected a refusal mentioning '" << phrase << "'";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
}

TEST(CorrectionPath, BadRequestsAreRefusedInTheUsersTerms) {
    CorrectionPathRequest r = paperRequest();
    r.pointCorrectionMm[2] = std::nan("");
    expectRefused(r, "control point 3");
    r = paperRequest();
    r.pointZMm[4] = 400.0;
    expectRefused(r, "outside the part");
    r = paperRequest();
    r.pointZMm[1] = -1.0;
    expectRefused(r, "outside the part");
    r = paperRequest();
    std::swap(r.pointZMm[1], r.pointZMm[2]);
    expectRefused(r, "strictly increasing");
    r = paperRequest();
    r.pointCorrectionMm.pop_back();
    expectRefused(r, "one correction per control point");
    r = paperRequest();
    r.partLengthMm = 0.0;
    expectRefused(r, "part length");
    r = paperRequest();
    r.stepMm = -0.5;
    expectRefused(r, "step");
    r = paperRequest();
    r.stepMm = 1e-5;
    expectRefused(r, "too fine");
}

}  // namespace
}  // namespace tt::core
