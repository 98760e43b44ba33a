#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "devices/parsers/linuxcnc_mdi.h"

namespace tt::devices {

/// How the program draws the correction between the control points.
enum class ParametricSlopes {
    Pchip,    ///< shape-preserving PCHIP (Fritsch-Carlson, MATLAB pchip), its slopes computed in the program
    Weights,  ///< slopes as fixed linear combinations of the parameters (natural cubic spline: d = W p)
};

/// A LinuxCNC part program for one finishing pass whose cutter path is drawn through numbered parameters set
/// by TrueTurn between parts (a shop's program reading #500 .. #504, as Fanuc macro B programs read #500..):
/// profile mode. Without parameters (firstParameter 0) the pass is the nominal path plus the feed-forward, and
/// the correction comes from the tool's wear entry applied with G43.2 (wear mode).
struct ParametricProgramJob {
    /// The control points along the part, mm from its left end, strictly increasing, on the part.
    std::vector<double> pointZMm;
    ParametricSlopes slopes = ParametricSlopes::Pchip;
    /// Slopes::Weights: N x N, d_k = sum_j w[k][j] p_j with z in mm and p in any unit (the slope of the
    /// interpolant through the unit vectors, so the same weights serve every unit and X mode).
    std::vector<std::vector<double>> slopeWeights;
    /// The path's samples along the part, mm, strictly increasing (the approximation unit's grid).
    std::vector<double> pathZMm;
    /// The feed-forward at each sample, radial mm (empty: none).
    std::vector<double> feedForwardMm;
    double nominalDiameterMm = 27.0;
    /// The first parameter of the corrections (#first .. #first+N-1, then the part number at #first+N);
    /// 0: no parameters (wear mode: the nominal path, the correction from the wear entry).
    int firstParameter = 500;
    linuxcnc::ProgramConventions conventions;  ///< G20/G21, G7/G8 (parameters are read in these)
    double feed = 0.25;                        ///< feed per revolution (G95) or per minute (G94), program units
    bool feedPerMinute = false;                ///< G94 (units/min) instead of G95 (units/rev)
    int spindleRpm = 546;                      ///< constant spindle speed (G97 S M3); 0: no spindle words
    int toolNumber = 1;                        ///< T<n> M6 G43
    std::optional<int> wearTool;               ///< G43.2 H<n> after G43: the wear entry's offset is added
    double zOriginMm = 0.0;                    ///< machine Z of the part's left end, mm
    int zDirection = -1;                       ///< machine Z = zOrigin + zDirection * z
    double clearanceMm = 2.0;                  ///< radial and axial clearance of approach and retract, mm
    double largestTotalMm = 0.5;               ///< the program refuses to cut with a parameter beyond this (radial mm)
    /// Path blending tolerance (G64 P and Q), mm: the cutter leaves the programmed path by at most this.
    double blendToleranceMm = 0.00002;
    int programNumber = 1001;
    std::vector<std::string> notes;  ///< one comment line each at the top (printable ASCII, upper-cased)
};

/// The program text. Structure: header comments (units, X mode, parameters and their meaning), G18 G40 G90,
/// the units and X mode, G64 P Q, the tool (T M6 G43, G43.2 H), guards (the part-number parameter must be
/// set, every correction within largestTotalMm, else ABORT with the reason), the part number cleared, the
/// slopes, the spindle, the approach a clearance before z = 0 outside the part (a 0.05 s dwell half-way at the
/// path's first X), one G1 per path sample whose
/// X is the nominal plus the feed-forward plus the Hermite cubic through the parameters (held at the end
/// values outside the control points, as the approximation unit does), a dwell of 0.05 s at the end of the cut,
/// the retract, M5, M2. Throws
/// std::invalid_argument, in the user's terms, for a bad job.
std::string writeParametricProgram(const ParametricProgramJob& job);

}  // namespace tt::devices
