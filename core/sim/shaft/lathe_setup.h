#pragma once

#include <cstdint>

namespace tt::core {

/// The shaft turned between centres (paper 000: blanks 325 mm long turned to 27 / 26.5 / 24.8 mm).
struct LatheWorkpiece {
    double lengthMm = 325.0;                ///< distance between the centres, mm
    double finishDiameterMm = 27.0;         ///< nominal finished diameter, mm
    double youngModulusNPerMm2 = 210000.0;  ///< E of the shaft material (steel: 210 GPa), N/mm²
};

/// The cutting conditions of the finishing pass (paper 000: a = 0.6 mm, f = 0.25 mm/rev, v = 46.3 m/min).
struct LatheCutting {
    double depthOfCutMm = 0.6;          ///< radial depth a; the blank diameter is finish + 2a, mm
    double feedMmPerRev = 0.25;         ///< feed f, mm per revolution
    double cuttingSpeedMPerMin = 46.3;  ///< cutting speed v, m/min
    bool feedTowardsHeadstock = true;   ///< the cut runs from the tailstock (x = L) to the headstock (x = 0)
};

/// Kienzle-type specific force of the radial (passive) force component:
/// F_p = k · b · h^(1-m) · (v / v_ref)^(-s), with chip width b = a / sin κ and chip thickness
/// h = f sin κ (Kienzle & Victor 1957; the speed factor as in Degner, Lutze & Smejkal,
/// "Spanende Formung"). F_p is proportional to a, which the simulator uses for the self-consistent cut.
struct LatheForceModel {
    double specificForceNPerMm2 = 1100.0;  ///< k (k_p1.1), N/mm² at h = 1 mm, b = 1 mm
    double exponent = 0.5;                 ///< m (the force grows as h^(1-m))
    double leadAngleDeg = 90.0;            ///< tool cutting-edge angle κ_r, degrees
    double referenceSpeedMPerMin = 100.0;  ///< v_ref of the speed correction, m/min
    double speedExponent = 0.1;            ///< s of the speed correction (force falls slowly with v)
};

/// Stiffness of the machine around the cut: the centres are elastic supports of the shaft, the cutter
/// deflects under the same radial force.
struct LatheStiffness {
    double headstockNPerMm = 30000.0;  ///< radial stiffness of the headstock centre (x = 0), N/mm
    double tailstockNPerMm = 15000.0;  ///< radial stiffness of the tailstock centre (x = L), N/mm
    double toolNPerMm = 30000.0;       ///< radial stiffness of the cutter and its holder, N/mm
};

/// Machine warm-up (paper 000: linear over 60 min = 10 parts, 0.004 mm at most).
struct LatheWarmUp {
    double diameterShiftMm = -0.004;  ///< diameter change once warm, mm (negative: the tool grows towards the axis)
    double durationParts = 10.0;      ///< parts until warm (linear ramp), > 0
};

/// Flank wear of the insert and tool changes (paper 000: 30 min = 5 parts, 0.002 mm radial = 0.004 mm on diameter).
struct LatheToolWear {
    double diameterGrowthMm = 0.004;     ///< diameter growth over one tool life, mm
    int toolLifeParts = 5;               ///< parts per cutting edge; then the edge is changed
    double changeRepeatabilityMm = 0.0;  ///< standard deviation of the diameter step at a change, mm
};

/// The micrometer that measures finished diameters (paper 000: MKTs 50, 0.001 mm; 0.001 mm at 95 %).
struct LatheMicrometer {
    double resolutionMm = 0.001;  ///< display step; 0 = no rounding
    double error95Mm = 0.001;     ///< error at 95 % confidence (σ = error95 / 1.96), mm
};

/// Everything the physical lathe simulator needs.
struct LatheSetup {
    LatheWorkpiece workpiece;
    LatheCutting cutting;
    LatheForceModel force;
    LatheStiffness stiffness;
    LatheWarmUp warmUp;
    LatheToolWear wear;
    LatheMicrometer micrometer;
    double toolSettingOffsetMm = 0.0;  ///< diameter error of the tool setting (trial cut), mm
    /// Share (0 .. 1) of the part-to-part random variance that is common to the whole shaft (see
    /// LatheDisturbanceModel::fromPointModels); the rest is independent from point to point.
    double randomCommonShare = 0.0;
    /// Scale of the part-to-part random variation against the disturbance model (standard deviation
    /// factor, >= 0): a group of parts with less scatter than the model was designed for.
    double randomScale = 1.0;
    double beamElementMm = 2.5;  ///< finite-element length of the shaft model, mm (also the profile grid)
    std::uint64_t seed = 1;      ///< seed of every random source
};

/// Throws std::invalid_argument naming the first value that is not physical (non-positive length,
/// depth of cut not smaller than the radius, lead angle outside (0, 180), ...).
void validateLatheSetup(const LatheSetup& setup);

}  // namespace tt::core
