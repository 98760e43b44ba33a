#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// Highest polynomial degree the regression offers (paper 000 uses 5).
inline constexpr int kMaxRegressionDegree = 6;

/// A least-squares fit y = X b of several terms (the columns of the design matrix X, the first one
/// the intercept, all ones) with the statistics a planner judges a model by (paper 000, Table 1, for
/// one variable; paper 004 for the force-deformation model Y(a, f, z)).
struct LinearRegression {
    int pointCount = 0;                    ///< n
    int termCount = 0;                     ///< p, the intercept included
    int residualDof = 0;                   ///< n - p
    Eigen::VectorXd coefficients;          ///< b, one per column of X
    Eigen::VectorXd coefficientStdErrors;  ///< sqrt of the diagonal of residualSigma^2 (X'X)^-1
    Eigen::VectorXd tValues;               ///< b_k / SE(b_k); +-infinity where SE is 0 (exact fit)
    double r2 = 0.0;                       ///< 1 - SSE/SST
    double r2Adjusted = 0.0;               ///< 1 - (1 - R^2)(n - 1)/(n - p)
    double fStatistic = 0.0;               ///< (SSR/(p-1)) / (SSE/(n-p)); +infinity for an exact fit
    double fCritical95 = 0.0;              ///< F(0.95; p-1, n-p), the table value (Boost.Math)
    double tCritical95 = 0.0;              ///< t(0.975; n-p): |t| below it means "not significant at 95 %"
    double residualSigma = 0.0;            ///< sqrt(SSE/(n-p)), units of y
    double residualSumOfSquares = 0.0;     ///< SSE
    double totalSumOfSquares = 0.0;        ///< SST about the mean of y
    double press = 0.0;                    ///< leave-one-out prediction error sum of squares
    Eigen::MatrixXd covarianceFactor;      ///< (X'X)^-1: cov(b) = residualSigma^2 * this

    /// Half width of the prediction band of one new observation with design row `row` at `level`
    /// (Student t, n-p degrees of freedom): t sigma sqrt(1 + row' (X'X)^-1 row). Throws
    /// std::invalid_argument for a row of the wrong size or a level outside (0, 1).
    double predictionHalfWidth(const Eigen::VectorXd& row, double level = 0.95) const;
    /// Half width of the confidence band of the fitted mean at design row `row` at `level`:
    /// t sigma sqrt(row' (X'X)^-1 row) (statsmodels: OLSResults.get_prediction().se_mean times t).
    /// Throws std::invalid_argument as predictionHalfWidth does.
    double confidenceHalfWidth(const Eigen::VectorXd& row, double level = 0.95) const;
};

/// Fits y = X b by least squares through column-pivoting Householder QR (never the normal equations)
/// with R^2, adjusted R^2, F against its table value, standard errors and t-values of the
/// coefficients, the residual sigma and PRESS. The caller scales the columns (coded variables in
/// [-1, 1]); column 0 must be the intercept (all ones). Needs at least p + 1 rows so the scatter can
/// be estimated. Throws std::invalid_argument naming the problem: sizes differ, too few points,
/// NaN/Inf, no intercept, all y equal, or columns that are linearly dependent on these data (the
/// message names the first such column, 1-based).
LinearRegression fitLinearRegression(const Eigen::MatrixXd& design, const Eigen::VectorXd& y);

/// A fitted value with its 95 % (or other level) bands at one x.
struct RegressionPrediction {
    double x = 0.0;
    double value = 0.0;                ///< fitted p(x)
    double confidenceHalfWidth = 0.0;  ///< half width of the confidence band of the mean p(x)
    double predictionHalfWidth = 0.0;  ///< half width of the prediction band of one new observation at x
};

/// Least-squares polynomial fit of y along x with its regression statistics (paper 000, eq. (1),
/// Table 1: R^2, F against the tabulated F, residual sigma).
struct PolynomialRegression {
    ScaledPolynomial polynomial;           ///< the fitted model (stored centred and scaled)
    int degree = 0;                        ///< D
    int pointCount = 0;                    ///< n
    int residualDof = 0;                   ///< n - D - 1
    Eigen::VectorXd coefficients;          ///< b0..bD in the original units (power form in x)
    Eigen::VectorXd coefficientStdErrors;  ///< standard errors of b0..bD, same units
    double r2 = 0.0;                       ///< 1 - SSE/SST
    double r2Adjusted = 0.0;               ///< 1 - (1 - R^2)(n - 1)/(n - D - 1)
    double fStatistic = 0.0;               ///< (SSR/D) / (SSE/(n-D-1)); +infinity for an exact fit
    double fCritical95 = 0.0;              ///< F(0.95; D, n-D-1) (Boost.Math Fisher F quantile)
    double residualSigma = 0.0;            ///< sqrt(SSE/(n-D-1)), units of y
    double residualSumOfSquares = 0.0;     ///< SSE
    double totalSumOfSquares = 0.0;        ///< SST about the mean of y
    double press = 0.0;                    ///< leave-one-out prediction error sum of squares, sum (e_i / (1 - h_ii))^2
    /// Unscaled covariance of the scaled coefficients, (X'X)^-1 in the centred/scaled basis:
    /// cov(c) = residualSigma^2 * this.
    Eigen::MatrixXd scaledCovarianceFactor;

    /// The fitted value at x with its confidence and prediction half widths at `level`
    /// (Student t with n-D-1 degrees of freedom). Throws std::invalid_argument unless 0 < level < 1.
    RegressionPrediction predict(double x, double level = 0.95) const;
};

/// Fits a polynomial of `degree` (1..6) to (x_i, y_i) by least squares: x is centred on the
/// mean and scaled to [-1, 1], the Vandermonde matrix is factored by column-pivoting Householder
/// QR (never the normal equations), and the coefficients are mapped back to power form in x.
/// Needs at least degree+2 points (so the residual scatter can be estimated) with at least
/// degree+1 distinct x; throws std::invalid_argument naming the problem otherwise (too few points,
/// NaN/Inf, all x equal, all y equal, sizes differ).
PolynomialRegression fitPolynomialRegression(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree);

/// One degree tried by the automatic choice.
struct DegreeCandidate {
    int degree = 0;
    double press = 0.0;  ///< leave-one-out prediction error sum of squares (infinite when not estimable)
};

/// The automatic degree choice: the fit of the chosen degree and every candidate's score.
struct DegreeSelection {
    PolynomialRegression fit;
    std::vector<DegreeCandidate> candidates;
};

/// Chooses the degree in 1..maxDegree by leave-one-out cross-validation (smallest PRESS, from
/// the hat matrix, exact for least squares); a higher degree must lower PRESS by more than the
/// rounding level to be preferred, so the simplest adequate model wins ties. Degrees the data
/// cannot support (too few points, a point with leverage 1) are skipped. Throws
/// std::invalid_argument when not even degree 1 can be fitted.
DegreeSelection fitPolynomialRegressionAutoDegree(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                                  int maxDegree = kMaxRegressionDegree);

}  // namespace tt::core
