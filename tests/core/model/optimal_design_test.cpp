// The prediction variance of a least-squares fit and the sequential I-optimal design built on it, checked
// against statsmodels' OLS (scripts/crosscheck-design.py: statsmodels 0.13.5, Debian 12) on a fixed
// design in two coded factors, and the greedy choice checked against an exhaustive search.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/model/optimal_design.h"
#include "core/model/polynomial_regression.h"

namespace tt::core {
namespace {

/// Terms 1, f, z, f z, f², z² at coded (f, z).
Eigen::RowVectorXd row(double f, double z) {
    Eigen::RowVectorXd r(6);
    r << 1.0, f, z, f * z, f * f, z * z;
    return r;
}

Eigen::MatrixXd rows(const std::vector<std::pair<double, double>>& points) {
    Eigen::MatrixXd x(static_cast<Eigen::Index>(points.size()), 6);
    for (std::size_t i = 0; i < points.size(); ++i)
        x.row(static_cast<Eigen::Index>(i)) = row(points[i].first, points[i].second);
    return x;
}

/// The design of scripts/crosscheck-design.py (13 points) and its responses.
Eigen::MatrixXd measured() {
    return rows({{-1, -1},
                 {-1, 0},
                 {-1, 1},
                 {-0.5, -0.5},
                 {-0.5, 0.5},
                 {0, -1},
                 {0, 0},
                 {0, 1},
                 {0.5, -0.5},
                 {0.5, 0.5},
                 {1, -1},
                 {1, 0},
                 {1, 1}});
}

Eigen::VectorXd responses() {
    Eigen::VectorXd y(13);
    y << 3.1, 4.0, 5.2, 4.4, 5.3, 4.9, 5.6, 6.8, 6.1, 6.9, 6.5, 7.4, 8.9;
    return y;
}

Eigen::MatrixXd prediction() {
    return rows({{0.25, 0.75}, {-0.8, 0.9}, {1.0, -1.0}});
}

TEST(RegressionBands, ConfidenceOfTheMeanAsStatsmodels) {
    const LinearRegression fit = fitLinearRegression(measured(), responses());
    // statsmodels OLS: params, sqrt(scale), get_prediction().se_mean and conf_int(alpha=0.05) half widths.
    const double coefficients[6] = {5.6,           1.73571428571, 1.03571428571, 0.0647058823529, 0.0892857142857,
                                    0.239285714286};
    for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(fit.coefficients(k), coefficients[k], 1e-10) << k;
    EXPECT_NEAR(fit.residualSigma, 0.122511238674, 1e-11);
    const double halfWidth[3] = {0.150935913492, 0.19145322377, 0.249504200695};
    const double seMean[3] = {0.0638308236194, 0.0809656010627, 0.105515369128};
    const Eigen::MatrixXd p = prediction();
    for (int k = 0; k < 3; ++k) {
        const Eigen::VectorXd x = p.row(k).transpose();
        EXPECT_NEAR(fit.confidenceHalfWidth(x), halfWidth[k], 1e-10) << k;
        EXPECT_NEAR(fit.residualSigma * std::sqrt(x.dot(fit.covarianceFactor * x)), seMean[k], 1e-11) << k;
        EXPECT_GT(fit.predictionHalfWidth(x), fit.confidenceHalfWidth(x));
    }
    EXPECT_THROW(fit.confidenceHalfWidth(Eigen::VectorXd::Ones(3)), std::invalid_argument);
    EXPECT_THROW(fit.confidenceHalfWidth(p.row(0).transpose(), 1.0), std::invalid_argument);
}

TEST(PredictionVarianceDesign, FactorsAndTheirFallAsStatsmodelsRefit) {
    PredictionVarianceDesign design(measured(), prediction());
    // se_mean² / scale of statsmodels before and after the rows (0.25, 0.75) and (-0.75, 1) are added.
    // The design's weak prior (1e-6 on the diagonal of X'X) moves them by less than 1e-6 relative.
    const double before[3] = {0.271461993888, 0.436766405653, 0.741787624141};
    const Eigen::VectorXd factors = design.varianceFactors();
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(factors(k), before[k], 1e-6 * before[k]) << k;
    EXPECT_NEAR(design.averageVarianceFactor(), 0.483338674561, 1e-6);
    EXPECT_NEAR(design.largestVarianceFactor(), 0.741787624141, 1e-6);
    const Eigen::MatrixXd added = rows({{0.25, 0.75}, {-0.75, 1.0}});
    EXPECT_NEAR(design.reductionOf(added), 0.0759765399369, 1e-6);
    design.add(added);
    const double after[3] = {0.205232204839, 0.289952950616, 0.726901248417};
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(design.varianceFactors()(k), after[k], 1e-6 * after[k]) << k;
    EXPECT_NEAR(design.averageVarianceFactor(), 0.407362134624, 1e-6);
}

TEST(PredictionVarianceDesign, GreedyChoiceIsTheBestSingleRowEachTime) {
    // Candidates on a 9 x 9 grid; the first pick must be the row whose reduction is largest (exhaustive), and
    // the second the best given the first (the definition of the sequential design).
    Eigen::MatrixXd candidates(81, 6);
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
            candidates.row(9 * i + j) = row(-1.0 + 0.25 * i, -1.0 + 0.25 * j);
    PredictionVarianceDesign design(measured(), prediction());
    const auto best = [&](const PredictionVarianceDesign& d) {
        Eigen::Index arg = 0;
        for (Eigen::Index i = 1; i < candidates.rows(); ++i)
            if (d.reductionOf(candidates.row(i)) > d.reductionOf(candidates.row(arg))) arg = i;
        return arg;
    };
    const Eigen::Index first = best(design);
    const std::vector<Eigen::Index> one = design.chooseRows(candidates, 1);
    ASSERT_EQ(one.size(), 1U);
    EXPECT_EQ(one[0], first);
    PredictionVarianceDesign withFirst = design;
    withFirst.add(candidates.row(first));
    const Eigen::Index second = best(withFirst);
    std::vector<Eigen::Index> two = design.chooseRows(candidates, 2);
    ASSERT_EQ(two.size(), 2U);
    EXPECT_TRUE((two[0] == first && two[1] == second) || (two[0] == second && two[1] == first));
    // More than the candidates: each at most once.
    EXPECT_EQ(design.chooseRows(candidates.topRows(3), 10).size(), 3U);
}

TEST(PredictionVarianceDesign, StartsWithoutDataAndRefusesWhatDoesNotFit) {
    // No measurement yet: the prior keeps (X'X)^-1 finite and the first rows bring the factors down by orders.
    PredictionVarianceDesign design(Eigen::MatrixXd(0, 6), prediction());
    EXPECT_GT(design.largestVarianceFactor(), 1e3);
    design.add(measured());
    EXPECT_NEAR(design.largestVarianceFactor(), 0.741787624141, 1e-6);
    EXPECT_THROW(PredictionVarianceDesign(measured(), Eigen::MatrixXd(0, 6)), std::invalid_argument);
    EXPECT_THROW(PredictionVarianceDesign(measured(), Eigen::MatrixXd::Ones(2, 5)), std::invalid_argument);
    EXPECT_THROW(design.reductionOf(Eigen::MatrixXd::Ones(1, 4)), std::invalid_argument);
    EXPECT_THROW(design.chooseRows(prediction(), 0), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
