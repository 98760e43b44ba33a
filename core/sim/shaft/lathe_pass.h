#pragma once

#include <functional>
#include <vector>

#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// One longitudinal pass at a constant depth of cut along the shaft of a lathe set-up (between elastic
/// centres, the cutter's own stiffness, the blank ahead of the cutter and the finished part behind it),
/// with a feed that may change along z: the elastic deformation Y under the Kienzle radial force
/// (LatheCuttingForce) at every position, from the same equilibrium as LatheSimulator:
///   Y = C(z) F_p(a - Y, f),  F_p = K(f) (a - Y)  =>  Y = C K a / (1 + C K),
/// the radial distance the cutter and the shaft are pushed apart (the finished radius is larger by Y
/// than commanded). C(z) is interpolated linearly between the nodes of the shaft model. The cutting
/// speed of the set-up sets the speed factor of the force; warm-up, wear and random variation of the
/// part-to-part simulator are not part of one pass.
class LathePass {
public:
    /// Throws std::invalid_argument on a bad set-up or a depth outside (0, finished radius).
    LathePass(const LatheSetup& setup, double depthMm);

    /// Y at z with the feed f, mm. Throws std::invalid_argument when z is off the shaft or f is not in
    /// (0, 5] mm/rev.
    double deformationMm(double zMm, double feedMmPerRev) const;
    /// The nodes of the shaft model (mm from the headstock centre), increasing.
    const std::vector<double>& gridZMm() const { return m_gridZ; }
    /// Compliance under the cutter at z (shaft on its centres plus the cutter), mm/N.
    double complianceMmPerN(double zMm) const;
    /// The depth of cut a, mm.
    double depthMm() const { return m_depthMm; }
    /// The set-up the pass is cut on.
    const LatheSetup& setup() const { return m_setup; }

private:
    LatheSetup m_setup;
    double m_depthMm;
    std::vector<double> m_gridZ;
    std::vector<double> m_compliance;
};

}  // namespace tt::core
