#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// Weights of the LQG criterion J = E sum( y'R1 y + u'R2 u ) (paper 000, eq. (3)); R1, R2 diagonal
/// in the paper. Units: y in mm of diameter, u in mm of radial cutter move.
struct LqgWeights {
    Eigen::MatrixXd R1;  ///< points x points, symmetric, >= 0
    Eigen::MatrixXd R2;  ///< points x points, symmetric, > 0
};

/// One independent part of the controller: a group of control points whose weights and noises do not
/// couple them to any other point (with diagonal R1, R2, one block per point). The matrices are in the
/// block's own state order: the points' delay chains first, then their disturbance states.
struct LqgBlock {
    std::vector<int> points;           ///< control points (inputs and outputs) of the block
    std::vector<Eigen::Index> states;  ///< the plant state index of each block state
    Eigen::MatrixXd A, B, C, K, L;     ///< block plant, LQ gain and innovation gain
    Eigen::MatrixXd P;                 ///< steady-state a-priori error covariance
    Eigen::MatrixXd Q;                 ///< process noise covariance G W G'
    Eigen::MatrixXd V;                 ///< gauge noise covariance of the block's points
    Eigen::MatrixXd P0;                ///< covariance before the first measurement (stationary prior)
};

/// Prior variance given to a random-walk disturbance state before the first measurement, mm^2
/// (a random walk has no stationary variance; 1 mm^2 admits any plausible first reading).
inline constexpr double kRandomWalkPriorMm2 = 1.0;

/// The LQG controller: LQ output regulator (MATLAB `lqry`) + steady-state Kalman filter in current
/// form (MATLAB `kalman`): u(k) = -K x(k|k), L = P C'(C P C' + V)^-1, P the a-priori covariance.
struct LqgDesign {
    Eigen::MatrixXd K;  ///< points x states
    Eigen::MatrixXd L;  ///< states x points
    Eigen::MatrixXd P;  ///< states x states
    std::vector<LqgBlock> blocks;
    int riccatiIterations = 0;         ///< doubling steps over all Riccati equations solved
    double maxRelativeResidual = 0.0;  ///< worst relative DARE residual
};

/// Checks the weights against the plant (sizes, symmetry, R1 >= 0, R2 > 0, finite); throws
/// std::invalid_argument naming the problem.
void validateWeights(const RunToRunPlant& plant, const LqgWeights& weights);

/// Designs the LQG controller exploiting the plant's structure (DECISIONS.md, "LQG synthesis by
/// blocks"): points not coupled by R1, R2 or V are designed separately, and within a block the delay
/// chains (known past inputs, no noise) and the disturbance (uncontrollable, unaffected by u) split
/// the two Riccati equations: an LQ Riccati equation on the delay chains, a Stein equation for the
/// disturbance feed-forward, and a filter Riccati equation on the disturbance states only. The result
/// equals `lqry` + `kalman` on the whole plant (tested) and also exists for a random-walk disturbance,
/// where the whole-plant LQ problem is not stabilisable.
LqgDesign designLqg(const RunToRunPlant& plant, const LqgWeights& weights);

/// Reference design on the whole plant: `lqry(A, B, C, D, R1, R2)` + `kalman(A, C, G, W, V)`, one
/// block. Needs a stationary disturbance (no random walk). Used by tests and the scaling benchmark.
LqgDesign designLqgDense(const RunToRunPlant& plant, const LqgWeights& weights);

}  // namespace tt::core
