#include "core/sim/shaft/lathe_shaft_beam.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

void requirePositive(double v, const char* what) {
    if (!std::isfinite(v) || v <= 0.0)
        throw std::invalid_argument(std::string(what) + " must be a positive number (got " + std::to_string(v) + ")");
}

}  // namespace

LatheShaftBeam::LatheShaftBeam(double lengthMm, double youngModulusNPerMm2, double headstockNPerMm,
                               double tailstockNPerMm, int elements)
    : m_lengthMm(lengthMm),
      m_youngModulus(youngModulusNPerMm2),
      m_headstock(headstockNPerMm),
      m_tailstock(tailstockNPerMm),
      m_elements(elements) {
    requirePositive(lengthMm, "the shaft length");
    requirePositive(youngModulusNPerMm2, "Young's modulus");
    requirePositive(headstockNPerMm, "the headstock stiffness");
    requirePositive(tailstockNPerMm, "the tailstock stiffness");
    if (elements < 2 || elements > 100000)
        throw std::invalid_argument("the shaft model needs 2 .. 100000 elements (got " + std::to_string(elements) +
                                    ")");
}

Eigen::VectorXd LatheShaftBeam::deflectionMm(int loadNode, double forceN,
                                             const std::vector<double>& elementDiameterMm) const {
    if (loadNode < 0 || loadNode > m_elements)
        throw std::invalid_argument("the load node " + std::to_string(loadNode) + " is outside the shaft model");
    if (static_cast<int>(elementDiameterMm.size()) != m_elements)
        throw std::invalid_argument("the shaft model needs one diameter per element");
    const int dofs = 2 * (m_elements + 1);
    const double h = elementLengthMm();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(16 * m_elements + 2));
    for (int e = 0; e < m_elements; ++e) {
        const double d = elementDiameterMm[static_cast<std::size_t>(e)];
        requirePositive(d, "every shaft diameter");
        const double ei = m_youngModulus * std::numbers::pi * std::pow(d, 4) / 64.0;
        const double c = ei / (h * h * h);
        // Element stiffness of the Euler-Bernoulli beam, DOFs (w1, θ1, w2, θ2).
        const double k[4][4] = {{12 * c, 6 * h * c, -12 * c, 6 * h * c},
                                {6 * h * c, 4 * h * h * c, -6 * h * c, 2 * h * h * c},
                                {-12 * c, -6 * h * c, 12 * c, -6 * h * c},
                                {6 * h * c, 2 * h * h * c, -6 * h * c, 4 * h * h * c}};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                entries.emplace_back(2 * e + i, 2 * e + j, k[i][j]);
    }
    entries.emplace_back(0, 0, m_headstock);
    entries.emplace_back(dofs - 2, dofs - 2, m_tailstock);
    Eigen::SparseMatrix<double> stiffness(dofs, dofs);
    stiffness.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(stiffness);
    if (solver.info() != Eigen::Success) throw std::runtime_error("the shaft stiffness matrix is singular");
    Eigen::VectorXd load = Eigen::VectorXd::Zero(dofs);
    load(2 * loadNode) = forceN;
    const Eigen::VectorXd u = solver.solve(load);
    Eigen::VectorXd w(m_elements + 1);
    for (int i = 0; i <= m_elements; ++i)
        w(i) = u(2 * i);
    return w;
}

std::vector<double> LatheShaftBeam::cuttingComplianceMmPerN(double finishDiameterMm, double blankDiameterMm,
                                                            bool feedTowardsHeadstock) const {
    requirePositive(finishDiameterMm, "the finished diameter");
    requirePositive(blankDiameterMm, "the blank diameter");
    std::vector<double> compliance(static_cast<std::size_t>(m_elements + 1));
    std::vector<double> diameters(static_cast<std::size_t>(m_elements));
    for (int node = 0; node <= m_elements; ++node) {
        for (int e = 0; e < m_elements; ++e) {
            // Element e spans nodes e .. e+1; it is finished when the cutter has passed it.
            const bool finished = feedTowardsHeadstock ? e >= node : e + 1 <= node;
            diameters[static_cast<std::size_t>(e)] = finished ? finishDiameterMm : blankDiameterMm;
        }
        compliance[static_cast<std::size_t>(node)] = deflectionMm(node, 1.0, diameters)(node);
    }
    return compliance;
}

CutterCompliance cutterCompliance(const LatheSetup& setup, double depthMm) {
    validateLatheSetup(setup);
    const double finish = setup.workpiece.finishDiameterMm;
    if (!std::isfinite(depthMm) || depthMm <= 0.0 || depthMm >= 0.5 * finish)
        throw std::invalid_argument("the depth of cut must be above 0 and below the finished radius " +
                                    std::to_string(0.5 * finish) + " mm (got " + std::to_string(depthMm) + ")");
    const int elements = std::max(2, static_cast<int>(std::lround(setup.workpiece.lengthMm / setup.beamElementMm)));
    const LatheShaftBeam beam(setup.workpiece.lengthMm, setup.workpiece.youngModulusNPerMm2,
                              setup.stiffness.headstockNPerMm, setup.stiffness.tailstockNPerMm, elements);
    CutterCompliance c;
    c.complianceMmPerN =
        beam.cuttingComplianceMmPerN(finish, finish + 2.0 * depthMm, setup.cutting.feedTowardsHeadstock);
    for (double& v : c.complianceMmPerN)
        v += 1.0 / setup.stiffness.toolNPerMm;
    c.zMm.resize(c.complianceMmPerN.size());
    for (int i = 0; i < beam.nodeCount(); ++i)
        c.zMm[static_cast<std::size_t>(i)] = beam.nodeXMm(i);
    return c;
}

}  // namespace tt::core
