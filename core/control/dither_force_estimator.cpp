#include "core/control/dither_force_estimator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

void requirePositive(double v, const char* what) {
    if (!std::isfinite(v) || v <= 0.0) throw std::invalid_argument(std::string(what) + " must be above 0");
}

bool finite(const DriveSample& s) {
    return std::isfinite(s.timeS) && std::isfinite(s.currentA) && std::isfinite(s.velocityMmPerS) &&
           std::isfinite(s.positionMm);
}

double relativeDifference(double a, double b) {
    const double mean = 0.5 * (std::abs(a) + std::abs(b));
    return mean > 0.0 ? std::abs(std::abs(a) - std::abs(b)) / mean : 0.0;
}

}  // namespace

const char* toString(DitherRefusal refusal) {
    switch (refusal) {
        case DitherRefusal::None:
            return "none";
        case DitherRefusal::NotCylindrical:
            return "not a cylindrical segment";
        case DitherRefusal::SlideNotMoving:
            return "slide not moving";
        case DitherRefusal::WindowTooShort:
            return "velocity window too short";
        case DitherRefusal::WaitingForStrokes:
            return "waiting for strokes";
    }
    return "unknown";
}

DitherForceEstimator::DitherForceEstimator(const DitherEstimatorConfig& config) : m_config(config) {
    requirePositive(config.currentToForceNPerA, "current-to-force gain k_p");
    requirePositive(config.stiffnessNPerMm, "tool stiffness k_st");
    requirePositive(config.movingVelocityMmPerS, "moving velocity threshold");
    requirePositive(config.plateauTolerance, "plateau tolerance");
    requirePositive(config.minStrokeMm, "minimum stroke");
    requirePositive(config.maxSpeedAsymmetry, "speed asymmetry limit");
    requirePositive(config.maxStrokeS, "longest stroke");
    requirePositive(config.maxQuietS, "longest pause");
    requirePositive(config.maxPairAgeS, "stroke pair age");
    if (config.minPlateauSamples < 1) throw std::invalid_argument("at least one constant-velocity sample is needed");
    if (config.strokesAveraged < 1) throw std::invalid_argument("at least one stroke per direction must be averaged");
    reset();
}

void DitherForceEstimator::reset() {
    m_stroke = Stroke{};
    m_forward.clear();
    m_reverse.clear();
    m_lastMotionS.reset();
    m_lastUsableStrokeS.reset();
    m_lastProblem = DitherRefusal::None;
    m_firstSampleS.reset();
    m_state = DitherUpdate{};
    m_state.refusal = DitherRefusal::WaitingForStrokes;
    m_state.reason = "waiting for the first dither strokes";
}

void DitherForceEstimator::setSegment(SegmentKind kind) {
    if (kind == m_segment) return;
    m_segment = kind;
    m_stroke = Stroke{};
    m_forward.clear();
    m_reverse.clear();
    if (kind == SegmentKind::Cylinder) {
        m_lastMotionS.reset();
        m_lastUsableStrokeS.reset();
        m_lastProblem = DitherRefusal::None;
        m_firstSampleS.reset();
        m_state = DitherUpdate{};
        m_state.refusal = DitherRefusal::WaitingForStrokes;
        m_state.reason = "waiting for dither strokes on the cylindrical segment";
    }
}

void DitherForceEstimator::refuse(DitherRefusal refusal, const std::string& reason) {
    m_state.estimate.reset();
    m_state.refusal = refusal;
    m_state.reason = reason;
}

DitherUpdate DitherForceEstimator::update(const DriveSample& sample, double offsetVelocityMmPerS) {
    m_state.newEstimate = false;
    if (!finite(sample) || !std::isfinite(offsetVelocityMmPerS)) return m_state;  // a corrupt reading is never used
    // Friction acts on the slide's absolute velocity: direction and strokes are judged on the measured
    // velocity and position as they are (while the offset moves faster than the dither the slide does not
    // reverse and no stroke pair completes). The dither's own speed, the slide's minus the offset's, picks
    // the constant-velocity part of a stroke and compares forward with reverse (a taper's feed shows there,
    // the offset's motion must not).
    const double ditherSpeed = std::abs(sample.velocityMmPerS - offsetVelocityMmPerS);
    if (m_segment != SegmentKind::Cylinder) {
        refuse(DitherRefusal::NotCylindrical,
               std::string("the segment is a ") + (m_segment == SegmentKind::Taper ? "taper" : "contour") +
                   ": force from current with dither works only on cylindrical bores (viscous friction differs "
                   "by direction)");
        return m_state;
    }
    if (!m_firstSampleS) m_firstSampleS = sample.timeS;
    const double v = sample.velocityMmPerS;
    const int direction = std::abs(v) > m_config.movingVelocityMmPerS ? (v > 0.0 ? 1 : -1) : 0;
    if (direction != 0) m_lastMotionS = sample.timeS;

    if (direction != 0 && direction == m_stroke.direction) {
        m_stroke.samples.push_back(sample);
        m_stroke.ditherSpeeds.push_back(ditherSpeed);
        const double duration = sample.timeS - m_stroke.samples.front().timeS;
        if (duration > m_config.maxStrokeS) {
            m_stroke.tooLong = true;
            refuse(DitherRefusal::NotCylindrical,
                   "the slide moved " + std::string(direction > 0 ? "outwards" : "inwards") + " for " +
                       formatFixed(duration, 1) + " s without reversing: a feed motion (taper or contour), not dither");
            m_forward.clear();
            m_reverse.clear();
            m_stroke.samples.erase(m_stroke.samples.begin());  // keep the buffer bounded
            m_stroke.ditherSpeeds.erase(m_stroke.ditherSpeeds.begin());
        }
    } else {
        if (m_stroke.direction != 0) finishStroke();
        m_stroke = Stroke{direction, {}, {}, false};
        if (direction != 0) {
            m_stroke.samples.push_back(sample);
            m_stroke.ditherSpeeds.push_back(ditherSpeed);
        }
    }

    // Strokes that cannot be used (too short, no constant-velocity window) are tolerated for a
    // while: a reversal often leaves a jerk of a micrometre. Without a usable stroke for
    // maxQuietS the estimate is withdrawn with the reason last seen.
    const double since = m_lastUsableStrokeS ? *m_lastUsableStrokeS : *m_firstSampleS;
    if (sample.timeS - since > m_config.maxQuietS && !m_stroke.tooLong) {
        const double quiet = sample.timeS - (m_lastMotionS ? *m_lastMotionS : *m_firstSampleS);
        if (quiet > m_config.maxQuietS)
            refuse(DitherRefusal::SlideNotMoving,
                   "the slide has not moved for " + formatFixed(quiet, 1) + " s (speed below " +
                       formatFixed(m_config.movingVelocityMmPerS, 3) +
                       " mm/s): the dither does not move it; raise the dither amplitude or check the drive");
        else if (m_lastProblem != DitherRefusal::None)
            refuse(m_lastProblem, m_lastProblemReason);
        else
            refuse(DitherRefusal::SlideNotMoving,
                   "no complete dither stroke for " + formatFixed(sample.timeS - since, 1) + " s");
    }
    return m_state;
}

void DitherForceEstimator::finishStroke() {
    const std::vector<DriveSample>& s = m_stroke.samples;
    const int direction = m_stroke.direction;
    if (m_stroke.tooLong) return;  // already refused while it lasted
    const double length = std::abs(s.back().positionMm - s.front().positionMm);
    if (length < m_config.minStrokeMm) {
        m_lastProblem = DitherRefusal::SlideNotMoving;
        m_lastProblemReason = "the slide moved only " + formatFixed(length * 1000.0, 1) + " µm in a stroke (at least " +
                              formatFixed(m_config.minStrokeMm * 1000.0, 1) + " µm needed): raise the dither amplitude";
        return;
    }
    std::vector<double> speeds = m_stroke.ditherSpeeds;
    std::sort(speeds.begin(), speeds.end());
    // Plateau speed: the (upper) median of the stroke's speeds. Most of a trapezoidal stroke is at constant
    // velocity; the acceleration samples are slower and an overshoot after a reversal faster, so neither
    // end of the sorted speeds is the plateau.
    const double plateau = speeds[speeds.size() / 2];
    double currentSum = 0.0;
    double speedSum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        const double speed = m_stroke.ditherSpeeds[k];
        if (std::abs(speed - plateau) <= m_config.plateauTolerance * plateau) {
            currentSum += s[k].currentA;
            speedSum += speed;
            ++count;
        }
    }
    if (count < m_config.minPlateauSamples) {
        m_lastProblem = DitherRefusal::WindowTooShort;
        m_lastProblemReason = "only " + std::to_string(count) + " sample" + (count == 1 ? "" : "s") +
                              " at constant velocity in a stroke (at least " +
                              std::to_string(m_config.minPlateauSamples) +
                              " needed): lengthen the dither period or shorten the PLC cycle";
        return;
    }
    m_lastUsableStrokeS = s.back().timeS;
    m_lastProblem = DitherRefusal::None;
    StrokeMean mean;
    mean.endS = s.back().timeS;
    mean.currentA = currentSum / count;
    mean.speedMmPerS = speedSum / count;
    mean.samples = count;
    combine(mean, direction);
}

void DitherForceEstimator::combine(const StrokeMean& newer, int direction) {
    const bool newerForward = direction > 0;
    std::deque<StrokeMean>& same = newerForward ? m_forward : m_reverse;
    std::deque<StrokeMean>& other = newerForward ? m_reverse : m_forward;
    same.push_back(newer);
    while (static_cast<int>(same.size()) > m_config.strokesAveraged)
        same.pop_front();
    if (!other.empty() && newer.endS - other.back().endS > m_config.maxPairAgeS) other.clear();
    if (other.empty()) {
        if (!m_state.estimate) {
            m_state.refusal = DitherRefusal::WaitingForStrokes;
            m_state.reason = "waiting for a stroke in the other direction";
        }
        return;
    }
    const StrokeMean& fwd = newerForward ? newer : other.back();
    const StrokeMean& rev = newerForward ? other.back() : newer;
    const double speedAsymmetry = relativeDifference(fwd.speedMmPerS, rev.speedMmPerS);
    if (speedAsymmetry > m_config.maxSpeedAsymmetry) {
        m_forward.clear();
        m_reverse.clear();
        refuse(DitherRefusal::NotCylindrical,
               "forward and reverse speeds differ (" + formatFixed(fwd.speedMmPerS, 4) + " vs " +
                   formatFixed(rev.speedMmPerS, 4) +
                   " mm/s), so viscous friction differs by direction: a taper or contour, not a cylinder");
        return;
    }
    auto mean = [](const std::deque<StrokeMean>& strokes, auto field) {
        double sum = 0.0;
        for (const StrokeMean& m : strokes)
            sum += field(m);
        return sum / static_cast<double>(strokes.size());
    };
    const auto current = [](const StrokeMean& m) { return m.currentA; };
    const auto speed = [](const StrokeMean& m) { return m.speedMmPerS; };
    const auto samples = [](const StrokeMean& m) { return static_cast<double>(m.samples); };
    ForceEstimate e;
    e.timeS = newer.endS;
    e.forwardCurrentA = mean(m_forward, current);
    e.reverseCurrentA = -mean(m_reverse, current);
    e.forceN = m_config.currentToForceNPerA * (e.forwardCurrentA - e.reverseCurrentA) / 2.0;
    e.deflectionMm = -e.forceN / m_config.stiffnessNPerMm;
    e.correctionMm = -e.deflectionMm;
    e.forwardSpeedMmPerS = mean(m_forward, speed);
    e.reverseSpeedMmPerS = mean(m_reverse, speed);
    e.forwardSamples = static_cast<int>(std::lround(mean(m_forward, samples) * static_cast<double>(m_forward.size())));
    e.reverseSamples = static_cast<int>(std::lround(mean(m_reverse, samples) * static_cast<double>(m_reverse.size())));
    e.strokesUsed = static_cast<int>(m_forward.size() + m_reverse.size());
    m_state.newEstimate = true;
    m_state.estimate = e;
    m_state.refusal = DitherRefusal::None;
    m_state.reason.clear();
}

}  // namespace tt::core
