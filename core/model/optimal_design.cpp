#include "core/model/optimal_design.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace tt::core {

PredictionVarianceDesign::PredictionVarianceDesign(const Eigen::MatrixXd& measured, const Eigen::MatrixXd& prediction)
    : m_prediction(prediction) {
    const Eigen::Index p = prediction.cols();
    if (p < 1) throw std::invalid_argument("a design needs at least one term");
    if (prediction.rows() < 1) throw std::invalid_argument("a design needs at least one row to predict at");
    if (measured.rows() > 0 && measured.cols() != p)
        throw std::invalid_argument("the measured rows have " + std::to_string(measured.cols()) +
                                    " terms but the prediction rows " + std::to_string(p));
    if (!prediction.allFinite() || !measured.allFinite())
        throw std::invalid_argument("a row of the design is not a finite number");
    m_weight = prediction.transpose() * prediction / static_cast<double>(prediction.rows());
    m_information = kPriorPrecision * Eigen::MatrixXd::Identity(p, p);
    if (measured.rows() > 0) m_information += measured.transpose() * measured;
    invert();
}

void PredictionVarianceDesign::requireColumns(const Eigen::MatrixXd& rows) const {
    if (rows.cols() != termCount())
        throw std::invalid_argument("rows of " + std::to_string(rows.cols()) + " terms for a design of " +
                                    std::to_string(termCount()));
    if (!rows.allFinite()) throw std::invalid_argument("a row of the design is not a finite number");
}

void PredictionVarianceDesign::invert() {
    // X'X + prior is symmetric positive definite: LDLT is stable for it and cheap at these sizes.
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(m_information);
    m_inverse = ldlt.solve(Eigen::MatrixXd::Identity(termCount(), termCount()));
}

Eigen::VectorXd PredictionVarianceDesign::varianceFactors() const {
    return (m_prediction * m_inverse).cwiseProduct(m_prediction).rowwise().sum().cwiseMax(0.0);
}

double PredictionVarianceDesign::averageVarianceFactor() const {
    return varianceFactors().mean();
}

double PredictionVarianceDesign::largestVarianceFactor() const {
    return varianceFactors().maxCoeff();
}

double PredictionVarianceDesign::reductionOf(const Eigen::MatrixXd& rows) const {
    requireColumns(rows);
    if (rows.rows() == 0) return 0.0;
    const Eigen::MatrixXd a = rows * m_inverse;  // m x p
    Eigen::MatrixXd s = a * rows.transpose();    // m x m
    s.diagonal().array() += 1.0;
    const Eigen::MatrixXd aw = a * m_weight * a.transpose();
    return s.ldlt().solve(aw).trace();
}

std::vector<Eigen::Index> PredictionVarianceDesign::chooseRows(const Eigen::MatrixXd& candidates, int count) const {
    if (count < 1) throw std::invalid_argument("choose at least one row");
    requireColumns(candidates);
    Eigen::MatrixXd inverse = m_inverse;
    std::vector<bool> taken(static_cast<std::size_t>(candidates.rows()), false);
    std::vector<Eigen::Index> chosen;
    const Eigen::Index n = std::min<Eigen::Index>(count, candidates.rows());
    for (Eigen::Index pick = 0; pick < n; ++pick) {
        // One row x: the average falls by x' M^-1 W M^-1 x / (1 + x' M^-1 x) (Sherman–Morrison).
        const Eigen::MatrixXd a = candidates * inverse;
        const Eigen::VectorXd leverage = a.cwiseProduct(candidates).rowwise().sum();
        const Eigen::VectorXd gain = (a * m_weight).cwiseProduct(a).rowwise().sum();
        Eigen::Index best = -1;
        double bestGain = -1.0;
        for (Eigen::Index i = 0; i < candidates.rows(); ++i) {
            const double g = gain(i) / (1.0 + leverage(i));
            if (!taken[static_cast<std::size_t>(i)] && g > bestGain) {
                bestGain = g;
                best = i;
            }
        }
        taken[static_cast<std::size_t>(best)] = true;
        chosen.push_back(best);
        const Eigen::VectorXd v = inverse * candidates.row(best).transpose();
        inverse -= v * v.transpose() / (1.0 + leverage(best));
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

void PredictionVarianceDesign::add(const Eigen::MatrixXd& rows) {
    requireColumns(rows);
    if (rows.rows() == 0) return;
    m_information += rows.transpose() * rows;
    invert();
}

}  // namespace tt::core
