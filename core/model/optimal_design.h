#pragma once

#include <vector>

#include <Eigen/Core>

namespace tt::core {

/// A sequential I-optimal design for a linear regression y = X b (Atkinson, Donev & Tobias, "Optimum
/// Experimental Designs, with SAS", 2007, ch. 10–12): the measurements already made (rows of X), the
/// rows x where the model must predict, and the choice of new rows that most reduce the average
/// prediction variance of the mean there, var(x'b) = sigma² x'(X'X)^-1 x. The variance factors
/// x'(X'X)^-1 x are the leverages of the prediction rows; sigma² is the caller's.
///
/// So that a design can start where X'X is singular (no data yet at a new depth), X'X carries a weak
/// prior kPriorPrecision * I on the coded coefficients; once the terms are estimable it changes the
/// factors by less than 1e-6 relative (coded rows have entries in [-1, 1]).
class PredictionVarianceDesign {
public:
    /// Weight of the prior on the coded coefficients (added to the diagonal of X'X).
    static constexpr double kPriorPrecision = 1e-6;

    /// `measured`: the rows of X already measured (n x p, n may be 0); `prediction`: the rows where
    /// the model must predict (k x p, k >= 1). Throws std::invalid_argument when the column counts
    /// differ, p is 0, there is no prediction row, or a value is not finite.
    PredictionVarianceDesign(const Eigen::MatrixXd& measured, const Eigen::MatrixXd& prediction);

    /// x'(X'X)^-1 x at every prediction row (dimensionless; times sigma² it is var of the fitted mean).
    Eigen::VectorXd varianceFactors() const;
    /// The I-criterion: the mean of varianceFactors().
    double averageVarianceFactor() const;
    /// The largest of varianceFactors().
    double largestVarianceFactor() const;

    /// How much averageVarianceFactor() would fall if `rows` (m x p) were measured too: the
    /// Sherman–Morrison–Woodbury update trace(W A'(I + A B')^-1 A), A = B (X'X)^-1, W = P'P / k.
    /// Throws std::invalid_argument on a column count that differs.
    double reductionOf(const Eigen::MatrixXd& rows) const;
    /// Up to `count` of `candidates`' rows (each at most once), chosen one at a time, each the one
    /// that most reduces the average variance with the ones chosen before; their indices, ascending.
    /// Throws std::invalid_argument when count < 1 or the column count differs.
    std::vector<Eigen::Index> chooseRows(const Eigen::MatrixXd& candidates, int count) const;
    /// Adds `rows` to the measured ones. Throws std::invalid_argument on a column count that differs.
    void add(const Eigen::MatrixXd& rows);

    /// Number of terms p.
    Eigen::Index termCount() const { return m_information.rows(); }

private:
    void requireColumns(const Eigen::MatrixXd& rows) const;
    void invert();

    Eigen::MatrixXd m_prediction;
    Eigen::MatrixXd m_weight;       ///< W = P'P / k
    Eigen::MatrixXd m_information;  ///< X'X + prior
    Eigen::MatrixXd m_inverse;      ///< (X'X + prior)^-1
};

}  // namespace tt::core
