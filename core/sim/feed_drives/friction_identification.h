#pragma once

#include <vector>

#include "core/sim/feed_drives/corner_simulation.h"

namespace tt::core {

/// A corner as the controller recorded it on the machine: the move, the pulse it applied and the
/// encoder positions over time (CornerTrace::encoderXMm / encoderZMm, sampled as the simulator's trace).
struct RecordedCorner {
    CornerMove move;
    double amplitudeV = 0.0;
    CornerTrace trace;
};

/// The friction factors that make the controller's model reproduce the recorded corners.
struct FrictionEstimate {
    double xFactor = 1.0;  ///< multiply the model's X friction by this
    double zFactor = 1.0;  ///< multiply the model's Z friction by this
    double xRmsUm = 0.0;   ///< RMS difference of the X encoder positions left, µm
    double zRmsUm = 0.0;   ///< the same for Z
    int simulations = 0;
};

/// Re-identifies the friction of each drive from recorded corners: for each axis, the factor in
/// [factorMin, factorMax] on the model's viscous, Coulomb and static friction that minimises the
/// squared difference between the recorded and the simulated encoder positions of that axis (the axes
/// are independent in the model), by Brent's method on the bracket. Throws std::invalid_argument when
/// no corner is given or the bracket is empty.
FrictionEstimate identifyFriction(const FeedDrivesConfig& model, const CornerCostSettings& cost,
                                  const PulseSettings& pulse, const std::vector<RecordedCorner>& corners,
                                  double factorMin, double factorMax, int traceEvery);

}  // namespace tt::core
