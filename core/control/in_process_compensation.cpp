#include "core/control/in_process_compensation.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {

ReadingProblem problemOf(DitherRefusal refusal) {
    switch (refusal) {
        case DitherRefusal::NotCylindrical:
            return ReadingProblem::NotCylindrical;
        case DitherRefusal::SlideNotMoving:
            return ReadingProblem::SlideNotMoving;
        case DitherRefusal::WindowTooShort:
            return ReadingProblem::WindowTooShort;
        case DitherRefusal::WaitingForStrokes:
        case DitherRefusal::None:
            break;
    }
    return ReadingProblem::WaitingForStrokes;
}

}  // namespace

CurrentDeflectionSource::CurrentDeflectionSource(DriveCurrentReadout& readout, const DitherEstimatorConfig& config)
    : m_readout(readout), m_estimator(config) {}

DeflectionReading CurrentDeflectionSource::poll(double /*nowS*/) {
    DeflectionReading r;
    const DeviceHealth health = m_readout.health();
    if (!health.ready()) {
        r.reason = "drive current readout is " + std::string(toString(health.state)) +
                   (health.message.empty() ? "" : ": " + health.message);
        r.problem = ReadingProblem::SourceNotReady;
        return r;
    }
    while (const std::optional<DriveSample> sample = m_readout.takeSample())
        r.fresh = m_estimator.update(*sample, m_nextOffsetVelocity).newEstimate || r.fresh;
    const DitherUpdate& state = m_estimator.state();
    if (!state.estimate) {
        r.fresh = false;
        r.reason = state.reason;
        r.problem = problemOf(state.refusal);
        return r;
    }
    r.deflectionMm = state.estimate->deflectionMm;
    r.forceN = state.estimate->forceN;
    return r;
}

ProbeDeflectionSource::ProbeDeflectionSource(DeflectionProbe& probe, int plane,
                                             std::optional<LinearisationTable> hostTable, double stiffnessNPerMm,
                                             double maxSilenceS)
    : m_probe(probe),
      m_plane(plane),
      m_hostTable(std::move(hostTable)),
      m_stiffnessNPerMm(stiffnessNPerMm),
      m_maxSilenceS(maxSilenceS) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("probe plane must be 0 (X) or 1 (Y)");
    if (!std::isfinite(maxSilenceS) || maxSilenceS <= 0.0)
        throw std::invalid_argument("the probe silence limit must be above 0 s");
}

DeflectionReading ProbeDeflectionSource::poll(double nowS) {
    DeflectionReading r;
    const DeviceHealth health = m_probe.health();
    if (!health.ready()) {
        m_lastDeflectionMm.reset();
        r.reason = "probe mandrel is " + std::string(toString(health.state)) +
                   (health.message.empty() ? "" : ": " + health.message);
        r.problem = ReadingProblem::SourceNotReady;
        return r;
    }
    double sum = 0.0;
    int count = 0;
    std::string problem;
    while (const std::optional<ProbeSample> sample = m_probe.takeSample()) {
        const std::size_t plane = static_cast<std::size_t>(m_plane);
        double mm = 0.0;
        if (sample->linearised) {
            mm = sample->deflectionMm[plane];
        } else if (m_hostTable) {
            mm = m_hostTable->interpolatedUm(sample->adcCode[plane]) / 1000.0;
        } else {
            problem = "the mandrel sends raw ADC codes and no linearisation table is loaded";
            continue;
        }
        if (!std::isfinite(mm)) continue;
        sum += mm;
        ++count;
        m_lastSampleS = sample->timeS;
    }
    if (count > 0) {
        m_lastDeflectionMm = sum / count;
        r.fresh = true;
    }
    if (!m_lastDeflectionMm || nowS - m_lastSampleS > m_maxSilenceS) {
        r.reason = !problem.empty()
                       ? problem
                       : "no probe sample for more than " + std::to_string(std::lround(m_maxSilenceS * 1000.0)) + " ms";
        r.problem = !problem.empty() ? ReadingProblem::NoTable : ReadingProblem::NoRecentSample;
        return r;
    }
    r.deflectionMm = m_lastDeflectionMm;
    if (m_stiffnessNPerMm > 0.0) r.forceN = -m_stiffnessNPerMm * *m_lastDeflectionMm;
    return r;
}

InProcessCompensator::InProcessCompensator(DeflectionSource& source, CorrectionOutput& output,
                                           const CompensatorLimits& limits, double plcCycleS)
    : m_source(source), m_output(output), m_compensator(limits), m_cycleS(plcCycleS) {
    if (!std::isfinite(plcCycleS) || plcCycleS < 0.01 - 1e-12 || plcCycleS > 0.1 + 1e-12)
        throw std::invalid_argument("the PLC cycle must be within 10 .. 100 ms");
}

void InProcessCompensator::resumeFrom(double offsetMm) {
    m_compensator.restoreOffset(offsetMm);
    m_lastSentMm = m_compensator.offsetMm();
}

CompensationCycle InProcessCompensator::cycle(double nowS) {
    CompensationCycle c;
    c.timeS = nowS;
    c.reading = m_source.poll(nowS);
    const DeviceHealth outputHealth = m_output.health();
    if (!outputHealth.ready()) {
        c.step =
            m_compensator.step(m_cycleS, std::nullopt, "CNC output is " + std::string(toString(outputHealth.state)));
        c.outputError = outputHealth.message.empty() ? c.step.reason : outputHealth.message;
        m_source.offsetMoving(0.0);
        return c;
    }
    c.step = m_compensator.step(m_cycleS, c.reading.deflectionMm, c.reading.reason);
    if (c.step.offsetMm == m_lastSentMm && c.step.holding) {
        m_source.offsetMoving(0.0);
        return c;
    }
    const OutputResult result = m_output.sendDynamicOffset(c.step.offsetMm);
    if (result.ok) {
        c.sent = true;
        m_source.offsetMoving((c.step.offsetMm - m_lastSentMm) / m_cycleS);
        m_lastSentMm = c.step.offsetMm;
    } else {
        c.outputError = result.message;
        m_source.offsetMoving(0.0);
        m_compensator.restoreOffset(m_lastSentMm);
        c.step.offsetMm = m_lastSentMm;
        c.step.holding = true;
        c.step.reason = "CNC refused the offset: " + result.message;
    }
    return c;
}

}  // namespace tt::core
