#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/drive_current.h"

namespace tt::core {

/// Tuning of the force-from-current estimator (paper 001, way 1). Velocities are those of the
/// cross slide (linear scale), mm/s; X positive away from the spindle axis.
struct DitherEstimatorConfig {
    double currentToForceNPerA = 0.0;     ///< k_p, N/A (from the k_p calibration)
    double stiffnessNPerMm = 0.0;         ///< k_st of the tool, N/mm (tool table)
    double movingVelocityMmPerS = 0.005;  ///< |v| above this counts as moving
    double plateauTolerance = 0.15;       ///< constant velocity: |v| within this fraction of the plateau speed
    int minPlateauSamples = 3;            ///< fewer samples at constant velocity: window too short
    double minStrokeMm = 0.003;           ///< a stroke shorter than this: the slide did not really move
    double maxSpeedAsymmetry = 0.2;       ///< |V_fwd − V_rev| / mean above this: not a cylinder
    double maxStrokeS = 2.5;              ///< moving one way longer than this: feed motion, not dither
    double maxQuietS = 3.0;               ///< no usable stroke for this long: refuse with the reason last seen
    double maxPairAgeS = 3.0;             ///< the forward and reverse strokes used must be this recent
    int strokesAveraged = 4;              ///< the last n usable strokes of each direction are averaged (1: one pair)
};

/// Kind of the segment being machined, as the part program says (the PLC knows the block type).
enum class SegmentKind { Cylinder, Taper, Contour };

/// Why no force can be estimated now.
enum class DitherRefusal { None, NotCylindrical, SlideNotMoving, WindowTooShort, WaitingForStrokes };

/// Plain English name of a refusal ("slide not moving").
const char* toString(DitherRefusal refusal);

/// One force estimate from a forward and a reverse stroke.
struct ForceEstimate {
    double timeS = 0.0;            ///< end of the later of the two strokes, s
    double forceN = 0.0;           ///< P = k_p (I_fwd − I_rev) / 2: radial force pushing the tool towards the axis, N
    double deflectionMm = 0.0;     ///< tool tip deflection along X, −P / k_st, mm (negative: towards the axis)
    double correctionMm = 0.0;     ///< ΔX = P / k_st, mm: the X offset that cancels the deflection
    double forwardCurrentA = 0.0;  ///< mean current at constant velocity, moving +X, A
    double reverseCurrentA = 0.0;  ///< mean current magnitude at constant velocity, moving −X, A
    double forwardSpeedMmPerS = 0.0;
    double reverseSpeedMmPerS = 0.0;
    int forwardSamples = 0;
    int reverseSamples = 0;
    int strokesUsed = 0;  ///< forward plus reverse strokes averaged
};

/// What the estimator says after a sample.
struct DitherUpdate {
    bool newEstimate = false;               ///< a stroke pair completed with this sample
    std::optional<ForceEstimate> estimate;  ///< the latest valid estimate, if still valid
    DitherRefusal refusal = DitherRefusal::None;
    std::string reason;  ///< why there is no valid estimate, in the user's terms
};

/// Force from the cross-feed motor current with dither (paper 001, way 1, fig. 1). While a
/// cylinder is bored the stopped cross feed oscillates; in the constant-velocity part of each
/// stroke the current is averaged per direction. Friction changes sign with the direction and
/// the cutting force does not, so with I_fwd = mean current moving +X (into the bore wall) and
/// I_rev = mean current magnitude moving −X, P = k_p (I_fwd − I_rev) / 2 and ΔX = P / k_st
/// (the paper's ΔX = −P / k with P taken along X). Signed currents are used internally,
/// P = k_p (I₊ + I₋) / 2, which is the same when friction exceeds the cutting force and stays
/// right when it does not. The stroke means of the last `strokesAveraged` strokes per direction
/// are averaged (1 = the paper's single pair) to tame current noise. Refuses on tapers and
/// contours (forward and reverse plateau speeds differ, or the slide moves one way too long),
/// when the slide does not really move, and when the constant-velocity window holds too few
/// samples; a single bad stroke (the jerk of a reversal) is tolerated for maxQuietS. Call
/// update() once per PLC cycle (10–100 ms) with the newest drive sample; O(samples per stroke)
/// at a stroke's end.
class DitherForceEstimator {
public:
    /// Throws std::invalid_argument for a non-positive k_p, k_st or thresholds.
    explicit DitherForceEstimator(const DitherEstimatorConfig& config);

    /// Sets the kind of the segment being machined; anything but a cylinder refuses at once.
    void setSegment(SegmentKind kind);
    /// Feeds one drive sample (in time order); returns the state after it. A sample with a
    /// non-finite value is ignored. Direction and strokes are judged on the slide's absolute velocity
    /// and position, on which friction acts (issue 13); `offsetVelocityMmPerS`, the speed at which the
    /// PLC was moving the dynamic offset, is taken off only to find the dither's constant-velocity part
    /// and to compare forward with reverse speeds. A dither too slow for the offset is refused before
    /// the run (core/run/dither_check.h).
    DitherUpdate update(const DriveSample& sample, double offsetVelocityMmPerS = 0.0);
    /// The state after the last update.
    const DitherUpdate& state() const { return m_state; }
    /// Forgets every stroke and estimate (new tool, new bore).
    void reset();

    const DitherEstimatorConfig& config() const { return m_config; }

private:
    struct Stroke {
        int direction = 0;
        std::vector<DriveSample> samples;
        std::vector<double> ditherSpeeds;  ///< per sample: |slide velocity - offset velocity|, mm/s
        bool tooLong = false;              ///< lasted longer than maxStrokeS: refused, never evaluated
    };
    struct StrokeMean {
        double endS = 0.0;
        double currentA = 0.0;  ///< signed mean current at constant velocity
        double speedMmPerS = 0.0;
        int samples = 0;
    };

    void refuse(DitherRefusal refusal, const std::string& reason);
    void finishStroke();
    void combine(const StrokeMean& newer, int direction);

    DitherEstimatorConfig m_config;
    SegmentKind m_segment = SegmentKind::Cylinder;
    Stroke m_stroke;
    std::deque<StrokeMean> m_forward;  ///< the last usable strokes moving +X, newest last
    std::deque<StrokeMean> m_reverse;
    std::optional<double> m_lastMotionS;
    std::optional<double> m_lastUsableStrokeS;          ///< end of the last stroke with a constant-velocity window
    DitherRefusal m_lastProblem = DitherRefusal::None;  ///< why the last unusable stroke was not used
    std::string m_lastProblemReason;
    std::optional<double> m_firstSampleS;
    DitherUpdate m_state;
};

}  // namespace tt::core
