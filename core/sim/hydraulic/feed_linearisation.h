#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "core/sim/hydraulic/hydraulic_feed_model.h"

namespace tt::core {

/// The chain linearised about its steady state under a constant load: d(dx)/dt = A dx + B dR with
/// x = (i, h, dh/dt, v) in SI units.
struct FeedLinearisation {
    double loadN = 0.0;
    FeedEquilibrium equilibrium;
    Eigen::MatrixXd A;             ///< 4 x 4 Jacobian of HydraulicFeedModel::derivative in x
    Eigen::VectorXd B;             ///< its derivative in the load, per N
    Eigen::VectorXcd eigenvalues;  ///< of A, 1/s
    /// The static gain of the loop the regulator closes through the cutting force: how much the feed
    /// the regulator's flow adds grows per unit of feed, d(k_0 Q_r)/dv at the steady state. The
    /// feedback is positive (more feed, more force, more flow), so the steady state is lost at 1.
    double loopGain = 0.0;

    /// Whether every eigenvalue has a negative real part.
    bool stable() const;
};

/// Linearises `model` about its steady state under `loadN` (HydraulicFeedModel::equilibrium), with the
/// analytic partial derivatives of the blocks. Eigenvalues by Eigen's EigenSolver.
FeedLinearisation linearise(const HydraulicFeedModel& model, double loadN);

/// The analytic solution of the linearised chain for a load step dR at t = 0 from its steady state:
/// dx(t) = V diag((e^{lambda t} - 1) / lambda) V^-1 B dR (modal form, A = V diag(lambda) V^-1), at
/// each time (s), as deviations from the steady state. Throws std::runtime_error when A has repeated
/// poles (a defective A, e.g. the spool at xi = 1 exactly), where the modal form does not exist.
std::vector<FeedState> linearStepResponse(const FeedLinearisation& lin, double deltaLoadN,
                                          const std::vector<double>& timesS);

/// Stability of the regulator loop under a load (issue 16's design aid).
struct FeedStability {
    FeedLinearisation atGain;  ///< the linearisation at the parameters' amplifier gain
    /// The stability boundary of the amplifier gain K_a: the largest gain whose steady state is stable
    /// (an eigenvalue reaches the imaginary axis there). None when the chain stays stable up to the
    /// gain's upper limit (1e5) or the slot opens fully first.
    std::optional<double> gainLimit;
    /// The gain above which the steady state needs the slot fully open while still stable (the
    /// regulator then over-compensates as much as it can); none when instability comes first.
    std::optional<double> fullOpeningGain;
    double designGain = 0.0;  ///< the gain that makes up exactly the leakage of this load
};

/// Eigenvalues at the parameters' gain, the stability boundary of the amplifier gain (by bisection on
/// the eigenvalues of the linearised chain at each gain's steady state) and the design gain, for the
/// load `loadN` (> 0). Throws std::invalid_argument for a load the slot cannot make up.
FeedStability analyseStability(const HydraulicFeedParams& params, double loadN);

}  // namespace tt::core
