#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/control/lqg_design.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// A linear run-to-run controller as the margins see it: `xi(k+1) = Ac xi + Bc y(k)`,
/// `u(k) = Cc xi + Dc y(k)`, u(k) being the correction of part k + z (the same form as the analytic
/// steady state's LinearControllerModel).
struct LoopController {
    Eigen::MatrixXd Ac, Bc, Cc, Dc;
};

/// Robustness of one channel (control point) of the discrete run-to-run loop, loop-at-a-time: the
/// loop broken at this point's correction with every other point closed, L(z) = -K(z) k_i z^-d
/// (MATLAB `allmargin` / `diskmargin` on the loop transfer, frequency in rad per part).
/// A margin that does not exist (no crossing) is empty: the loop tolerates any such change.
struct ChannelMargins {
    std::optional<double> gain;       ///< upper gain margin: the loop gain may grow this many times
    std::optional<double> gainLower;  ///< lower gain margin (< 1) if a gain reduction destabilises
    /// Smallest phase change (lag or lead) that puts a gain crossover on -1, degrees (>= 0; MATLAB's
    /// signed Pm folded to its magnitude).
    std::optional<double> phaseDeg;
    /// Extra delay the loop tolerates, parts, by MATLAB's `allmargin` rule (phase margin / crossover
    /// frequency, smallest over the crossovers). It treats the delay as a continuous lag e^-jwd and can
    /// exceed a whole part that in fact destabilises the discrete loop: see extraPartsTolerated.
    std::optional<double> delayParts;
    /// Whole extra parts of plant delay the loop stays stable with (0 .. kMaxDelay), by the closed-loop
    /// eigenvalues with delay z + 1, z + 2, ...: the figure that matters for a run-to-run process.
    int extraPartsTolerated = 0;
    std::optional<double> crossoverRadPerPart;  ///< gain crossover of the smallest delay margin
    double disk = 0.0;                          ///< balanced disk margin alpha = 1 / max|S - 1/2| (MATLAB `diskmargin`)
    double diskGainUpper = 0.0;                 ///< disk-based gain margin (2 + alpha) / (2 - alpha); 0 when alpha >= 2
    double diskPhaseDeg = 0.0;                  ///< disk-based phase margin 2 atan(alpha / 2), degrees
    double sensitivityPeak = 0.0;               ///< max |S|, S = 1 / (1 + L)
    double sensitivityPeakRadPerPart = 0.0;     ///< where it occurs
};

/// Margins of every channel and of the loop as a whole.
struct LoopMargins {
    std::vector<ChannelMargins> channels;  ///< per control point
    bool closedLoopStable = false;         ///< the nominal loop (all points closed) is stable
    /// True when some channel's delay margin is under one part or one extra part of plant delay
    /// destabilises the loop (or the loop is unstable): flag before apply (issue 13).
    bool delayMarginBelowOnePart = false;
};

/// Limits of the frequency sweep: points of the uniform grid on [0, pi] and of the low-frequency
/// logarithmic grid (1e-4 .. 0.05 rad/part).
inline constexpr int kMarginUniformGrid = 768;
inline constexpr int kMarginLogGrid = 96;

/// Margins of the loop of `controller` around the plant y = diag(gain) z^-delay u. Throws
/// std::invalid_argument for inconsistent sizes, a delay outside 1..kMaxDelay or non-finite matrices.
LoopMargins computeLoopMargins(const Eigen::VectorXd& gain, int delay, const LoopController& controller);

/// True when the loop of `controller` around y = diag(gain) z^-delay u is stable (closed-loop
/// eigenvalues inside the unit circle); the delay may exceed the one the controller was designed for.
/// Throws like computeLoopMargins (delay up to 2 kMaxDelay).
bool closedLoopStable(const Eigen::VectorXd& gain, int delay, const LoopController& controller);

/// Margins of an LQG design, computed block by block (points not coupled by the design do not
/// interact, so each block's loop is small).
LoopMargins lqgMargins(const RunToRunPlant& plant, const LqgDesign& design);

/// The LQG controller of one design block in loop form: Ac = (A - BK)(I - LC), Bc = (A - BK)L,
/// Cc = -K(I - LC), Dc = -KL.
LoopController lqgBlockController(const LqgBlock& block);

/// The EWMA controller (weight lambda at every point, u = -offset / k_i) in loop form around y = diag(gain)
/// z^-delay u: xi = [offset; u(k-1) .. u(k-delay)], offset(k) = (1 - lambda) offset(k-1) + lambda (y(k) - k_i
/// u(k-delay)). Throws std::invalid_argument for a weight outside (0, 1], a delay outside 1 .. 2 kMaxDelay or a gain
/// that is not positive.
LoopController ewmaLoopController(const Eigen::VectorXd& gain, int delay, double weight);

/// Sensitivity |S(e^jw)| of channel `channel` at the frequencies `wRadPerPart` (for plots).
std::vector<double> sensitivityMagnitude(const Eigen::VectorXd& gain, int delay, const LoopController& controller,
                                         int channel, const std::vector<double>& wRadPerPart);

/// Sensitivity |S(e^jw)| of control point `point` of an LQG design (its block's loop).
std::vector<double> lqgSensitivityMagnitude(const RunToRunPlant& plant, const LqgDesign& design, int point,
                                            const std::vector<double>& wRadPerPart);

}  // namespace tt::core
