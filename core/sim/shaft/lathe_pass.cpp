#include "core/sim/shaft/lathe_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sim/shaft/lathe_cutting_force.h"
#include "core/sim/shaft/lathe_shaft_beam.h"

namespace tt::core {

LathePass::LathePass(const LatheSetup& setup, double depthMm) : m_setup(setup), m_depthMm(depthMm) {
    CutterCompliance c = cutterCompliance(setup, depthMm);
    m_gridZ = std::move(c.zMm);
    m_compliance = std::move(c.complianceMmPerN);
}

double LathePass::complianceMmPerN(double zMm) const {
    if (!std::isfinite(zMm) || zMm < m_gridZ.front() || zMm > m_gridZ.back())
        throw std::invalid_argument("the position " + std::to_string(zMm) + " mm is off the shaft (0 .. " +
                                    std::to_string(m_gridZ.back()) + " mm)");
    const auto upper = std::upper_bound(m_gridZ.begin(), m_gridZ.end(), zMm);
    if (upper == m_gridZ.end()) return m_compliance.back();
    const auto i = static_cast<std::size_t>(upper - m_gridZ.begin());
    const double t = (zMm - m_gridZ[i - 1]) / (m_gridZ[i] - m_gridZ[i - 1]);
    return m_compliance[i - 1] + t * (m_compliance[i] - m_compliance[i - 1]);
}

double LathePass::deformationMm(double zMm, double feedMmPerRev) const {
    if (!std::isfinite(feedMmPerRev) || feedMmPerRev <= 0.0 || feedMmPerRev > 5.0)
        throw std::invalid_argument("the feed " + std::to_string(feedMmPerRev) + " mm/rev is outside (0, 5] mm/rev");
    LatheCutting cutting = m_setup.cutting;
    cutting.feedMmPerRev = feedMmPerRev;
    const double ck = complianceMmPerN(zMm) * LatheCuttingForce(m_setup.force, cutting).forcePerDepthNPerMm();
    return ck * m_depthMm / (1.0 + ck);
}

}  // namespace tt::core
