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

const char* toString(BoringMethod method) {
    switch (method) {
        case BoringMethod::None:
            return "none";
        case BoringMethod::Current:
            return "current";
        case BoringMethod::Probe:
            return "probe";
    }
    return "none";
}

BoringMethod boringMethodFromString(const std::string& text) {
    if (text == "none") return BoringMethod::None;
    if (text == "current") return BoringMethod::Current;
    if (text == "probe") return BoringMethod::Probe;
    throw std::invalid_argument("method '" + text + "' must be current, probe or none");
}

const char* toString(ReadingProblem problem) {
    switch (problem) {
        case ReadingProblem::None:
            return "none";
        case ReadingProblem::SourceNotReady:
            return "source not ready";
        case ReadingProblem::NoRecentSample:
            return "no recent sample";
        case ReadingProblem::NoTable:
            return "no linearisation table";
        case ReadingProblem::NotCylindrical:
            return "not cylindrical";
        case ReadingProblem::SlideNotMoving:
            return "slide not moving";
        case ReadingProblem::WindowTooShort:
            return "window too short";
        case ReadingProblem::WaitingForStrokes:
            return "waiting for strokes";
    }
    return "none";
}

const char* toString(OutputProblem problem) {
    switch (problem) {
        case OutputProblem::None:
            return "none";
        case OutputProblem::NotReady:
            return "not ready";
        case OutputProblem::Refused:
            return "refused";
    }
    return "none";
}

CurrentDeflectionSource::CurrentDeflectionSource(DriveCurrentReadout& readout, const DitherEstimatorConfig& config)
    : m_readout(readout), m_estimator(config) {}

DeflectionReading CurrentDeflectionSource::poll(double /*nowS*/) {
    DeflectionReading r;
    const DeviceHealth health = m_readout.health();
    if (!health.ready()) {
        r.problem = ReadingProblem::SourceNotReady;
        r.sourceHealth = health;
        return r;
    }
    while (const std::optional<DriveSample> sample = m_readout.takeSample())
        r.fresh = m_estimator.update(*sample, m_nextOffsetVelocity).newEstimate || r.fresh;
    const DitherUpdate& state = m_estimator.state();
    if (!state.estimate) {
        r.fresh = false;
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
        r.problem = ReadingProblem::SourceNotReady;
        r.sourceHealth = health;
        return r;
    }
    double sum = 0.0;
    int count = 0;
    bool rawWithoutTable = false;
    while (const std::optional<ProbeSample> sample = m_probe.takeSample()) {
        const std::size_t plane = static_cast<std::size_t>(m_plane);
        double mm = 0.0;
        if (sample->linearised) {
            mm = sample->deflectionMm[plane];
        } else if (m_hostTable) {
            mm = m_hostTable->interpolatedUm(sample->adcCode[plane]) / 1000.0;
        } else {
            rawWithoutTable = true;
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
        r.problem = rawWithoutTable ? ReadingProblem::NoTable : ReadingProblem::NoRecentSample;
        r.silenceLimitS = m_maxSilenceS;
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
        c.step = m_compensator.step(m_cycleS, std::nullopt);
        c.outputProblem = OutputProblem::NotReady;
        c.outputHealth = outputHealth;
        m_source.offsetMoving(0.0);
        return c;
    }
    c.step = m_compensator.step(m_cycleS, c.reading.deflectionMm);
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
        c.outputProblem = OutputProblem::Refused;
        c.outputMessage = result.message;
        m_source.offsetMoving(0.0);
        m_compensator.restoreOffset(m_lastSentMm);
        c.step.offsetMm = m_lastSentMm;
        c.step.holding = true;
    }
    return c;
}

}  // namespace tt::core
