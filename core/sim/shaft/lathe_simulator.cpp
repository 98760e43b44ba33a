#include "core/sim/shaft/lathe_simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sim/shaft/lathe_random.h"
#include "core/sim/shaft/lathe_shaft_beam.h"

namespace tt::core {

namespace {

/// The CNC follows the polyline of the path samples; outside them it holds the end values.
double pathCorrectionAt(const CorrectionPath& path, double z) {
    const auto& zs = path.zMm;
    if (zs.empty()) return 0.0;
    if (z <= zs.front()) return path.xCorrectionMm.front();
    if (z >= zs.back()) return path.xCorrectionMm.back();
    const auto upper = std::upper_bound(zs.begin(), zs.end(), z);
    const auto i = static_cast<std::size_t>(upper - zs.begin());
    const double t = (z - zs[i - 1]) / (zs[i] - zs[i - 1]);
    return path.xCorrectionMm[i - 1] + t * (path.xCorrectionMm[i] - path.xCorrectionMm[i - 1]);
}

}  // namespace

LatheSimulator::LatheSimulator(const LatheSetup& setup, std::vector<double> controlPointZMm,
                               LatheDisturbanceModel disturbance)
    : m_setup(setup),
      m_pointZ(std::move(controlPointZMm)),
      m_force(setup.force, setup.cutting),
      m_disturbance(std::move(disturbance), setup.seed) {
    validateLatheSetup(setup);
    if (m_pointZ.empty()) throw std::invalid_argument("the lathe simulator needs at least one control point");
    if (static_cast<int>(m_pointZ.size()) != m_disturbance.pointCount())
        throw std::invalid_argument("the disturbance model has " + std::to_string(m_disturbance.pointCount()) +
                                    " points but " + std::to_string(m_pointZ.size()) + " control points are given");
    for (std::size_t i = 0; i < m_pointZ.size(); ++i) {
        if (!std::isfinite(m_pointZ[i]) || m_pointZ[i] < 0.0 || m_pointZ[i] > setup.workpiece.lengthMm)
            throw std::invalid_argument("control point " + std::to_string(i + 1) + " lies outside the part");
        if (i > 0 && m_pointZ[i] <= m_pointZ[i - 1])
            throw std::invalid_argument("the control points must be strictly increasing along the part");
    }
    CutterCompliance compliance = cutterCompliance(setup, setup.cutting.depthOfCutMm);
    m_compliance = std::move(compliance.complianceMmPerN);
    m_gridZ = std::move(compliance.zMm);
}

double LatheSimulator::warmUpShiftMm(std::int64_t partNumber) const {
    const double progress = (static_cast<double>(partNumber) - 0.5) / m_setup.warmUp.durationParts;
    return m_setup.warmUp.diameterShiftMm * std::clamp(progress, 0.0, 1.0);
}

double LatheSimulator::toolWearMm(std::int64_t partNumber) const {
    const auto life = static_cast<std::int64_t>(m_setup.wear.toolLifeParts);
    const auto onEdge = (partNumber - 1) % life;  // parts already cut with this edge
    return m_setup.wear.diameterGrowthMm * static_cast<double>(onEdge) / static_cast<double>(life);
}

double LatheSimulator::toolChangeOffsetMm(std::int64_t partNumber) const {
    if (m_setup.wear.changeRepeatabilityMm <= 0.0) return 0.0;
    const auto edge = static_cast<std::uint64_t>((partNumber - 1) / m_setup.wear.toolLifeParts);
    return m_setup.wear.changeRepeatabilityMm * latheNormals(m_setup.seed, LatheStream::ToolChange, edge).next();
}

double LatheSimulator::finishedDiameterMm(std::size_t gridIndex, double commandedRadialMm) const {
    const double nominalRadius = 0.5 * m_setup.workpiece.finishDiameterMm;
    const double blankRadius = nominalRadius + m_setup.cutting.depthOfCutMm;
    const double commanded = nominalRadius + commandedRadialMm;
    if (commanded >= blankRadius) return 2.0 * blankRadius;  // the cutter does not reach the blank
    const double ck = m_compliance[gridIndex] * m_force.forcePerDepthNPerMm();
    return 2.0 * (commanded + ck * blankRadius) / (1.0 + ck);
}

double LatheSimulator::correctionGainAt(std::size_t gridIndex) const {
    return 2.0 / (1.0 + m_compliance.at(gridIndex) * m_force.forcePerDepthNPerMm());
}

std::vector<double> LatheSimulator::deterministicErrorMm(std::int64_t partNumber) const {
    if (partNumber < 1) throw std::invalid_argument("part numbers start at 1");
    const double offset = 0.5 * (m_setup.toolSettingOffsetMm + warmUpShiftMm(partNumber) + toolWearMm(partNumber) +
                                 toolChangeOffsetMm(partNumber));
    std::vector<double> error(m_gridZ.size());
    for (std::size_t i = 0; i < m_gridZ.size(); ++i)
        error[i] = finishedDiameterMm(i, offset) - m_setup.workpiece.finishDiameterMm;
    return error;
}

TurnedPart LatheSimulator::machine(const PartCorrection& correction) {
    const std::int64_t k = correction.partNumber;
    if (k < 1) throw std::invalid_argument("part numbers start at 1 (got " + std::to_string(k) + ")");
    if (correction.path.zMm.size() != correction.path.xCorrectionMm.size())
        throw std::invalid_argument("the correction path has different numbers of positions and corrections");
    const double offset =
        0.5 * (m_setup.toolSettingOffsetMm + warmUpShiftMm(k) + toolWearMm(k) + toolChangeOffsetMm(k));
    const Eigen::VectorXd f = m_disturbance.diameterMm(k);
    const std::vector<double> fPoints(f.data(), f.data() + f.size());
    const PiecewiseCubic variation = PiecewiseCubic::pchip(m_pointZ, fPoints);

    TurnedPart part;
    part.partNumber = k;
    part.zMm = m_gridZ;
    part.diameterMm.resize(m_gridZ.size());
    for (std::size_t i = 0; i < m_gridZ.size(); ++i) {
        const double z = m_gridZ[i];
        part.diameterMm[i] = finishedDiameterMm(i, offset + pathCorrectionAt(correction.path, z)) + variation.value(z);
    }
    return part;
}

}  // namespace tt::core
