#include "core/sim/feed_drives/corner_simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kSettleS = 0.02;

void validateRun(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const PulseSettings& pulse,
                 double amplitudeV, const CornerSimulationOptions& options) {
    validateFeedDrives(drives);
    validateCornerCost(cost);
    validatePulse(pulse);
    if (!std::isfinite(amplitudeV) || std::abs(amplitudeV) > pulse.limitV + 1e-12)
        throw std::invalid_argument("pulse amplitude " + formatSignificant(amplitudeV, 6) + " V is outside ±" +
                                    formatSignificant(pulse.limitV, 6) + " V");
    if (options.traceEvery < 1 || options.traceEvery > 1000)
        throw std::invalid_argument("trace every " + std::to_string(options.traceEvery) +
                                    " steps is outside 1 .. 1000");
}

double loadOn(const std::optional<LoadTorquePulse>& load, FeedAxis axis, double timeS) {
    if (!load || load->axis != axis) return 0.0;
    return timeS >= load->startS && timeS < load->startS + load->durationS ? load->torqueNm : 0.0;
}

void record(CornerTrace& trace, double t, const PlanePointMm& programmed, const FeedDriveAxis& x,
            const FeedDriveAxis& z, double errorMm, double pulseV) {
    trace.timeS.push_back(t);
    trace.programmedXMm.push_back(programmed.xMm);
    trace.programmedZMm.push_back(programmed.zMm);
    trace.xMm.push_back(x.positionMm());
    trace.zMm.push_back(z.positionMm());
    trace.encoderXMm.push_back(x.encoderMm());
    trace.encoderZMm.push_back(z.encoderMm());
    trace.errorMm.push_back(errorMm);
    trace.pulseV.push_back(pulseV);
}

// The pulse: fired once when the Z encoder reaches Zm0, then on for its duration.
class PulseTrigger {
public:
    PulseTrigger(const PulseSettings& pulse, double amplitudeV, double triggerZMm)
        : m_pulse(pulse), m_amplitudeV(amplitudeV), m_triggerZMm(triggerZMm) {}
    double voltage(double timeS, double encoderZMm) {
        if (!m_fired && encoderZMm >= m_triggerZMm) {
            m_fired = true;
            m_startS = timeS;
        }
        return m_fired && timeS < m_startS + m_pulse.durationS - 1e-12 ? m_amplitudeV : 0.0;
    }
    double startS() const { return m_startS; }

private:
    PulseSettings m_pulse;
    double m_amplitudeV;
    double m_triggerZMm;
    bool m_fired = false;
    double m_startS = 0.0;
};

}  // namespace

CornerRun simulateCorner(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const CornerMove& move,
                         const PulseSettings& pulse, double amplitudeV, const CornerSimulationOptions& options) {
    validateRun(drives, cost, pulse, amplitudeV, options);
    const CornerPath path(drives, move);
    const double zStartMm = path.at(-cost.beforeS).zMm;
    const double zEndMm = path.at(cost.afterS).zMm;
    const double startS = -std::max(cost.beforeS, pulse.leadS) - kSettleS;
    const PlanePointMm start = path.at(startS);
    FeedDriveAxis x(drives.x, start.xMm);
    FeedDriveAxis z(drives.z, start.zMm);
    x.settleOnRamp(start.xMm, path.velocity1MmPerS().xMm);
    z.settleOnRamp(start.zMm, path.velocity1MmPerS().zMm);
    CornerCostAccumulator accumulator(cost, zStartMm, zEndMm);
    PulseTrigger trigger(pulse, amplitudeV, path.at(-pulse.leadS).zMm);
    CornerRun run;
    bool inInterval = false;
    const long maxSteps = std::lround((kMaxCornerRunS - startS) / drives.stepS);
    for (long n = 0;; ++n) {
        if (n > maxSteps)
            throw std::runtime_error("the tool did not pass the end of the control interval within " +
                                     formatSignificant(kMaxCornerRunS, 3) + " s");
        const double t = startS + static_cast<double>(n) * drives.stepS;
        const PlanePointMm programmed = path.at(t);
        const double zMm = z.positionMm();
        const double errorMm = path.distanceMm({x.positionMm(), zMm});
        accumulator.add(zMm, errorMm);
        if (!inInterval && zMm >= zStartMm) {
            inInterval = true;
            run.intervalStartS = t;
        }
        const double pulseV = trigger.voltage(t, z.encoderMm());
        if (options.keepTrace && n % options.traceEvery == 0) record(run.trace, t, programmed, x, z, errorMm, pulseV);
        if (zMm > zEndMm) {
            run.intervalEndS = t;
            break;
        }
        // The interpolator's position is held for the step (sample and hold).
        x.step(drives.stepS, programmed.xMm, pulse.axis == FeedAxis::X ? pulseV : 0.0,
               loadOn(options.disturbance, FeedAxis::X, t));
        z.step(drives.stepS, programmed.zMm, pulse.axis == FeedAxis::Z ? pulseV : 0.0,
               loadOn(options.disturbance, FeedAxis::Z, t));
        if (pulseV != 0.0)
            run.pulseCurrentPeakA =
                std::max(run.pulseCurrentPeakA, std::abs((pulse.axis == FeedAxis::X ? x : z).currentA()));
    }
    run.pulseStartS = trigger.startS();
    run.cost = accumulator.result();
    return run;
}

}  // namespace tt::core
