#pragma once

#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// Radial (passive) force of the cut, Kienzle type: F_p = k · b · h^(1-m) · (v / v_ref)^(-s),
/// b = a / sin κ, h = f sin κ (Kienzle & Victor 1957). The radial component pushes the cutter and the
/// shaft apart and so sets the diameter error; the tangential component deflects the shaft in the
/// other plane and changes the diameter only to second order (δ_t² / d, below 0.001 mm here), so it is
/// not modelled.
class LatheCuttingForce {
public:
    /// Throws std::invalid_argument on non-physical coefficients.
    LatheCuttingForce(const LatheForceModel& model, const LatheCutting& cutting);

    /// F_p at radial depth `depthMm`, N (0 when the cutter does not cut, depth <= 0).
    double radialForceN(double depthMm) const;
    /// F_p / a, N/mm: the force is proportional to the depth, so this is also dF_p / da.
    double forcePerDepthNPerMm() const { return m_forcePerDepth; }

private:
    double m_forcePerDepth = 0.0;
};

}  // namespace tt::core
