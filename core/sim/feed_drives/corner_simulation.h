#pragma once

#include <optional>
#include <vector>

#include "core/sim/feed_drives/corner_cost.h"
#include "core/sim/feed_drives/corner_move.h"
#include "core/sim/feed_drives/corrective_pulse.h"

namespace tt::core {

/// A load torque on one motor for a while (a hard spot, a chip): what makes a corner an outlier.
struct LoadTorquePulse {
    FeedAxis axis = FeedAxis::Z;
    double startS = 0.0;     ///< relative to the velocity change, s
    double durationS = 0.0;  ///< s
    double torqueNm = 0.0;   ///< against the motion when positive, N·m
};

/// What to simulate besides the drives and the move.
struct CornerSimulationOptions {
    bool keepTrace = false;                      ///< record the trajectory (plots, identification)
    int traceEvery = 5;                          ///< one trace sample every this many steps
    std::optional<LoadTorquePulse> disturbance;  ///< an outlier's load, none normally
};

/// The trajectory of a simulated corner, sampled every `traceEvery` steps.
struct CornerTrace {
    std::vector<double> timeS;  ///< 0 = the programmed velocity change
    std::vector<double> programmedXMm;
    std::vector<double> programmedZMm;
    std::vector<double> xMm;  ///< true slide positions
    std::vector<double> zMm;
    std::vector<double> encoderXMm;  ///< what the encoders report
    std::vector<double> encoderZMm;
    std::vector<double> errorMm;  ///< contour error (distance from the programmed path)
    std::vector<double> pulseV;   ///< corrective pulse on the pulsed axis
};

/// A simulated corner: its cost over the control interval and, when asked, the trajectory. Times are
/// relative to the programmed velocity change.
struct CornerRun {
    CornerCost cost;
    CornerTrace trace;
    double pulseStartS = 0.0;        ///< when the tool reached Zm0 and the pulse fired, s
    double intervalStartS = 0.0;     ///< when the tool reached Zn, s
    double intervalEndS = 0.0;       ///< when the tool passed Zk, s
    double pulseCurrentPeakA = 0.0;  ///< largest |armature current| of the pulsed drive while the pulse is on, A
};

/// Longest simulated time after the programmed velocity change, s (the tool must pass Zk before).
inline constexpr double kMaxCornerRunS = 5.0;

/// Simulates the two drives through the corner `move` with a pulse of `amplitudeV` (0: no pulse) on
/// `pulse.axis`. Both drives start in the steady state of the first move 20 ms (of programmed time)
/// before the earlier of Zm0 and Zn; the pulse fires when the Z encoder reaches Zm0 = Z1 − Vz1·p_m
/// (paper 002, eq. 4); the cost counts the samples with the tool between Zn and Zk; the run ends when
/// the tool passes Zk. The contour error is the distance of the true tool position from the programmed
/// path. Throws std::invalid_argument on invalid drives, move, pulse, cost settings or an amplitude
/// beyond the pulse's limit, std::runtime_error when the tool does not reach Zk in kMaxCornerRunS.
CornerRun simulateCorner(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const CornerMove& move,
                         const PulseSettings& pulse, double amplitudeV, const CornerSimulationOptions& options = {});

}  // namespace tt::core
