#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/control/profile_interpolation.h"
#include "core/sim/shaft/lathe_cutting_force.h"
#include "core/sim/shaft/lathe_disturbance.h"
#include "core/sim/shaft/lathe_part_process.h"
#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// The physical lathe: a shaft turned between centres (paper 000's set-up). The finished radius at x
/// follows from the cut being in equilibrium with the elastic system at the cutter:
///   r = r_cmd + C(x) F_p(R_blank - r),  F_p = K a  (Kienzle, proportional to the depth a)
///   => r = (r_cmd + C K R_blank) / (1 + C K),
/// where r_cmd is the commanded radius (nominal + tool setting + warm-up + wear + the CNC's correction
/// y_set(x)), C(x) the compliance under the cutter (stepped shaft on elastic centres, finite elements,
/// plus the cutter's own compliance). The part-to-part random variation f(k) of the disturbance model
/// is added at the control points and drawn along the shaft through them by PCHIP (paper 000: the
/// random error is largest at the five control places, and the shaft between follows them).
class LatheSimulator final : public LathePartProcess {
public:
    /// `controlPointZMm`: where the disturbance model's N points lie (strictly increasing, on the part);
    /// `disturbance`: its N-point model. Throws std::invalid_argument on a bad set-up.
    LatheSimulator(const LatheSetup& setup, std::vector<double> controlPointZMm, LatheDisturbanceModel disturbance);

    TurnedPart machine(const PartCorrection& correction) override;
    double nominalDiameterMm() const override { return m_setup.workpiece.finishDiameterMm; }
    double partLengthMm() const override { return m_setup.workpiece.lengthMm; }

    /// The lathe's set-up.
    const LatheSetup& setup() const { return m_setup; }
    /// The control points along the part, mm.
    const std::vector<double>& controlPointZMm() const { return m_pointZ; }
    /// Positions of the simulator's profile grid (the shaft model's nodes), mm.
    const std::vector<double>& gridZMm() const { return m_gridZ; }
    /// Compliance under the cutter at each grid position: shaft on its centres plus the cutter, mm/N.
    const std::vector<double>& complianceMmPerN() const { return m_compliance; }
    /// Radial force at the nominal depth of cut, N.
    double nominalRadialForceN() const { return m_force.radialForceN(m_setup.cutting.depthOfCutMm); }

    /// Diameter change of the machine warm-up at part k (linear ramp), mm.
    double warmUpShiftMm(std::int64_t partNumber) const;
    /// Diameter change from flank wear at part k (zero on a fresh edge, growing over the tool life), mm.
    double toolWearMm(std::int64_t partNumber) const;
    /// Diameter step of the cutting edge in use at part k (tool-change repeatability), mm.
    double toolChangeOffsetMm(std::int64_t partNumber) const;
    /// Diameter error along the grid at part k without disturbance and correction: the systematic
    /// (barrel) error plus warm-up, wear and tool setting, mm.
    std::vector<double> deterministicErrorMm(std::int64_t partNumber) const;
    /// How much the diameter at grid node i changes per mm of radial correction: 2 / (1 + C K)
    /// (the deeper cut pushes back harder, so less than the rigid 2).
    double correctionGainAt(std::size_t gridIndex) const;

private:
    double finishedDiameterMm(std::size_t gridIndex, double commandedRadialMm) const;

    LatheSetup m_setup;
    std::vector<double> m_pointZ;
    LatheCuttingForce m_force;
    LatheDisturbance m_disturbance;
    std::vector<double> m_gridZ;
    std::vector<double> m_compliance;
};

}  // namespace tt::core
