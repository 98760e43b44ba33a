#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/model/disturbance_model.h"

namespace tt::core {

/// One control point along the part (paper 000: the five places where the random error is largest).
struct ControlPointSpec {
    double xMm = 0.0;                          ///< axial position from the left end, mm
    double gain = 2.0;                         ///< k_i: diameter change per radial cutter move (2 = mm/mm)
    DisturbanceModel disturbance;              ///< random diameter error at this point, mm
    double measurementNoiseVarianceMm2 = 0.0;  ///< gauge noise variance, mm^2 (> 0)
};

/// What the plant builder needs: the control points and the transport delay.
struct RunToRunPlantSpec {
    std::vector<ControlPointSpec> points;  ///< 1 .. 16 points
    int delay = 4;                         ///< z: parts between machining a part and using its measurement, 1 .. 8
};

/// Limits of the plant builder.
inline constexpr int kMaxControlPoints = 16;
/// Largest transport delay z, parts.
inline constexpr int kMaxDelay = 8;

/// The run-to-run plant in state-space form (paper 000, eq. (2) and the extended plant):
/// `x(k+1) = A x(k) + B u(k) + G w(k)`, `y(k) = C x(k) + D u(k) + v(k)`, cov(w) = W, cov(v) = V.
/// Step k is the measurement of part k; u(k) is the radial correction (mm) that part k + z receives;
/// y(k) is the measured diameter deviation (mm). State order: the delay chains of all points
/// (z states each: u(k-1) .. u(k-z)), then the disturbance states of all points.
struct RunToRunPlant {
    Eigen::MatrixXd A, B, C, D, G, W, V;
    int delay = 1;
    std::vector<double> xMm;  ///< control point positions
    Eigen::VectorXd gain;     ///< k_i per point
    /// Per point: first index and count of its delay states and of its disturbance states, and first
    /// index and count of its noise inputs (columns of G).
    struct PointLayout {
        Eigen::Index delayStart = 0, delayCount = 0;
        Eigen::Index disturbanceStart = 0, disturbanceCount = 0;
        Eigen::Index noiseStart = 0, noiseCount = 0;
    };
    std::vector<PointLayout> layout;
    std::vector<DisturbanceModel> disturbances;  ///< per point, as specified

    /// Number of control points N.
    int pointCount() const { return static_cast<int>(xMm.size()); }
    /// Number of states n (delay chains + disturbance states).
    Eigen::Index stateCount() const { return A.rows(); }
};

/// Builds the state-space plant. Throws std::invalid_argument naming the point and the field for
/// out-of-range input (1..16 points, delay 1..8, gain in (0, 100], gauge noise variance > 0).
RunToRunPlant buildRunToRunPlant(const RunToRunPlantSpec& spec);

/// The paper's five control points on a shaft of `lengthMm` (325 mm in the paper): both ends, the
/// left inflection point 27.5 mm from the left end (paper: 25-30 mm), the middle, and the right
/// inflection point 62.5 mm from the right end (paper: 50-75 mm). Sorted by position.
std::vector<double> paperControlPointsMm(double lengthMm = 325.0);

}  // namespace tt::core
