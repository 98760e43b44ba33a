#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// A shaft between centres as an Euler–Bernoulli beam on two elastic supports (the headstock centre
/// at x = 0, the tailstock centre at x = L; radial springs, rotation free), discretised into equal
/// finite elements with cubic Hermite shape functions. For point loads at the nodes this is exact:
/// for a uniform shaft the deflection under the load equals the closed form
/// P [ (1-ξ)²/k_A + ξ²/k_B + x²(L-x)²/(3 E I L) ], ξ = x / L (Timoshenko & Gere, simply supported beam,
/// plus the rigid-body motion on the springs).
class LatheShaftBeam {
public:
    /// Throws std::invalid_argument unless every value is finite and positive and elements >= 2.
    LatheShaftBeam(double lengthMm, double youngModulusNPerMm2, double headstockNPerMm, double tailstockNPerMm,
                   int elements);

    /// Number of beam elements.
    int elementCount() const { return m_elements; }
    /// Number of nodes (elements + 1).
    int nodeCount() const { return m_elements + 1; }
    /// Length of one element, mm.
    double elementLengthMm() const { return m_lengthMm / m_elements; }
    /// x of node i, mm.
    double nodeXMm(int node) const { return elementLengthMm() * node; }

    /// Radial deflection at every node under a radial force `forceN` at node `loadNode`, mm,
    /// for the element diameters `elementDiameterMm` (one per element, solid round section I = π d⁴ / 64).
    Eigen::VectorXd deflectionMm(int loadNode, double forceN, const std::vector<double>& elementDiameterMm) const;

    /// The compliance under the cutter while it cuts at each node, mm/N: the shaft is stepped, the blank
    /// diameter ahead of the cutter and the finished diameter behind it (`feedTowardsHeadstock`: the
    /// cut runs from x = L to x = 0, so the finished part is at x > cutter).
    std::vector<double> cuttingComplianceMmPerN(double finishDiameterMm, double blankDiameterMm,
                                                bool feedTowardsHeadstock) const;

private:
    double m_lengthMm;
    double m_youngModulus;
    double m_headstock;
    double m_tailstock;
    int m_elements;
};

/// The compliance under the cutter at the nodes of a lathe set-up's shaft model.
struct CutterCompliance {
    std::vector<double> zMm;               ///< node positions from the headstock centre, mm
    std::vector<double> complianceMmPerN;  ///< stepped shaft on its centres plus the cutter (1 / k_tool), mm/N
};

/// The compliance under the cutter of `setup` (shaft, centres, cutter, element length, direction of the
/// cut) for a radial depth of cut `depthMm` (the blank ahead of the cutter is finish + 2a in diameter).
/// Throws std::invalid_argument on a bad set-up or a depth that is not positive and below the radius.
CutterCompliance cutterCompliance(const LatheSetup& setup, double depthMm);

}  // namespace tt::core
