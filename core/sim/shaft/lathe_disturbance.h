#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include <Eigen/Core>

#include "core/model/disturbance_model.h"

namespace tt::core {

/// A linear model of the part-to-part random variation of the diameter at N control points, in the
/// state-space form the controller is designed on (paper 000, shaping filter + white noise):
/// s(k+1) = A s(k) + G w(k), f(k) = C s(k) + H w(k), w(k) ~ N(0, W) white, f in mm of diameter.
/// With no states (A empty) f = H w is white.
struct LatheDisturbanceModel {
    Eigen::MatrixXd A;  ///< n x n (n may be 0)
    Eigen::MatrixXd G;  ///< n x q
    Eigen::MatrixXd C;  ///< N x n
    Eigen::MatrixXd H;  ///< N x q
    Eigen::MatrixXd W;  ///< q x q covariance of w, symmetric positive semi-definite

    /// N, the number of control points.
    int pointCount() const { return static_cast<int>(H.rows()); }
    /// No variation at N points.
    static LatheDisturbanceModel none(int points);
    /// The per-point disturbance models of the controller's plant (core/model), stacked block-diagonally:
    /// point i's output is its model's realisation, independent of the other points.
    static LatheDisturbanceModel fromPointModels(const std::vector<DisturbanceModel>& points);
    /// The same per-point models with a share `commonShare` (0 .. 1) of every point's variance driven by
    /// noise common to all points: f_i = sqrt(c) a_i + sqrt(1 - c) b_i, where a_i and b_i are realisations
    /// of point i's model, the a_i from one shared white noise (a tool offset, warm-up or a new edge moves
    /// the whole shaft), the b_i independent. Each point keeps exactly its model's process, so a
    /// controller designed per point sees what it was designed for. The models must have the same
    /// number of noise inputs when commonShare > 0.
    static LatheDisturbanceModel fromPointModels(const std::vector<DisturbanceModel>& points, double commonShare);
    /// The same model with every output multiplied by `factor` (variances by factor²).
    LatheDisturbanceModel scaled(double factor) const;
    /// Adds white noise of variance `varianceMm2[i]` at point i (direct feed-through H).
    LatheDisturbanceModel withWhiteNoise(const std::vector<double>& varianceMm2) const;
};

/// The disturbance sequence f(1), f(2), ... of one seeded run. Deterministic: the same seed gives the
/// same sequence whatever order the parts are asked for. Stationary models start in their stationary
/// distribution (no start-up transient); models with a pole on the unit circle (random walk) start at 0.
class LatheDisturbance {
public:
    /// Throws std::invalid_argument on inconsistent sizes, non-finite values or a W that is not a
    /// covariance.
    LatheDisturbance(LatheDisturbanceModel model, std::uint64_t seed);

    /// Number of control points N.
    int pointCount() const { return m_model.pointCount(); }
    /// f(partNumber), diameter mm per control point; partNumber >= 1.
    Eigen::VectorXd diameterMm(std::int64_t partNumber);
    /// Stationary variance of f per point (C P C' + H W H', P from the Lyapunov equation), mm²;
    /// throws std::logic_error for a model without a stationary distribution.
    Eigen::VectorXd stationaryVarianceMm2() const;

private:
    void restart();
    void advance();

    LatheDisturbanceModel m_model;
    std::uint64_t m_seed;
    Eigen::MatrixXd m_noiseFactor;  ///< L with L L' = W
    bool m_stationary = false;
    Eigen::VectorXd m_state;               ///< s(m_nextPart)
    std::int64_t m_nextPart = 1;           ///< the part whose f is produced next
    std::deque<Eigen::VectorXd> m_recent;  ///< f of the most recent parts, last = m_nextPart - 1
};

}  // namespace tt::core
