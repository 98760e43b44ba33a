#include "core/sim/boring/boring_machine.h"

#include "core/common/text_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tt::core {

namespace {

void requireWithin(double v, double lo, double hi, const std::string& what) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(what + ": " + std::to_string(v) + " is outside " + std::to_string(lo) + " .. " +
                                    std::to_string(hi));
}

/// Refuses a pass that would take longer than kMaxBoringPassS of simulated time or more than
/// kMaxBoringSteps simulation steps (every value in range can still ask for 3e12 steps).
void requireBoundedPass(const BoringScenario& s) {
    const double feedMmPerS = s.cut.feedMmPerRev * s.cut.spindleRpm / 60.0;
    const double passS = (s.cut.approachMm + s.cut.boreLengthMm) / feedMmPerS;
    if (passS > kMaxBoringPassS)
        throw std::invalid_argument("the pass takes " + formatSignificant(passS, 3) +
                                    " s of simulated time (approach and bore at feed x spindle speed); the limit is " +
                                    formatSignificant(kMaxBoringPassS, 6) + " s");
    const double steps = passS / s.simStepS;
    if (steps > kMaxBoringSteps)
        throw std::invalid_argument("the pass needs " + formatSignificant(steps, 3) +
                                    " simulation steps; the limit is " + formatSignificant(kMaxBoringSteps, 6) +
                                    " (a longer simulation step or a shorter bore)");
}

}  // namespace

void validateScenario(const BoringScenario& s) {
    const std::vector<std::string> toolProblems = validateTool(s.tool);
    if (!toolProblems.empty()) throw std::invalid_argument("tool " + toolProblems.front());
    requireWithin(s.trueStiffnessFactor, 0.5, 1.5, "bar true stiffness factor");
    const BoringCutConfig& c = s.cut;
    requireWithin(c.boreLengthMm, 10.0, 5000.0, "bore length (mm)");
    requireWithin(c.feedMmPerRev, 0.01, 2.0, "feed (mm/rev)");
    requireWithin(c.spindleRpm, 1.0, 5000.0, "spindle speed (rpm)");
    requireWithin(c.radialSpecificForceNPerMm2, 10.0, 10000.0, "radial specific force (N/mm²)");
    requireWithin(c.tangentialToRadialRatio, 0.0, 10.0, "tangential to radial force ratio");
    requireWithin(c.depthStartMm, 0.01, 20.0, "depth at the bore entry (mm)");
    requireWithin(c.depthEndMm, 0.01, 20.0, "depth at the bore end (mm)");
    requireWithin(c.hardnessVariation, 0.0, 0.5, "hardness variation");
    requireWithin(c.hardnessWavelengthMm, 1.0, 1.0e5, "hardness wavelength (mm)");
    requireWithin(c.wearForceIncrease, 0.0, 2.0, "wear force increase");
    requireWithin(c.approachMm, 0.0, 100.0, "approach (mm)");
    requireWithin(c.entryRampMm, 0.0, 50.0, "entry ramp (mm)");
    requireWithin(c.gaugeMarginMm, 0.0, c.boreLengthMm / 2.0 - 1.0, "gauge margin (mm)");
    requireWithin(c.boreToleranceMm, 0.0, 1.0, "bore tolerance (mm)");
    requireWithin(s.plcCycleS, 0.01, 0.1, "PLC cycle (s)");
    requireWithin(s.simStepS, 1.0e-5, 1.0e-3, "simulation step (s)");
    if (s.simStepS > s.plcCycleS / 10.0) throw std::invalid_argument("the simulation step must be ≤ PLC cycle / 10");
    requireBoundedPass(s);
    requireWithin(s.calibration.points, 5, 1000, "calibration points");
    requireWithin(s.calibration.readingsPerPoint, 1, 1000, "readings per calibration point");
    requireWithin(s.calibration.spanFraction, 0.1, 1.0, "calibration span fraction");
    requireWithin(s.calibration.referenceResolutionUm, 0.0, 100.0, "reference resolution (µm)");
    requireWithin(s.calibration.referenceNoiseUm, 0.0, 100.0, "reference noise (µm)");
    DitherProfile check(s.dither);
    CrossFeedDrive driveCheck(s.drive, 0);
    InductiveProbe probeCheck(s.probe, 0);
    DeflectionCompensator limitsCheck(s.limits);
    (void)check;
    (void)driveCheck;
    (void)probeCheck;
    (void)limitsCheck;
}

BoringMachine::BoringMachine(const BoringScenario& scenario, bool dither)
    : m_scenario(scenario),
      m_dither(dither),
      m_ditherProfile((validateScenario(scenario), scenario.dither)),
      m_drive(scenario.drive, scenario.seed * 2654435761ULL + 1),
      m_probe(scenario.probe, scenario.seed * 2654435761ULL + 2),
      m_stiffnessX(computedStiffnessNPerMm(scenario.tool, BendingPlane::Radial) * scenario.trueStiffnessFactor),
      m_stiffnessY(computedStiffnessNPerMm(scenario.tool, BendingPlane::Tangential) * scenario.trueStiffnessFactor),
      m_axialSpeedMmPerS(scenario.cut.feedMmPerRev * scenario.cut.spindleRpm / 60.0) {
    m_state.toolZMm = -scenario.cut.approachMm;
    m_probe.settle(0.0, 0.0);
}

double BoringMachine::radialForce(double zMm, double slideMm) const {
    const BoringCutConfig& c = m_scenario.cut;
    if (zMm < 0.0 || zMm > c.boreLengthMm) return 0.0;
    const double along = zMm / c.boreLengthMm;
    const double depthNominal = c.depthStartMm + (c.depthEndMm - c.depthStartMm) * along;
    const double hardness = 1.0 + c.hardnessVariation * std::sin(2.0 * std::numbers::pi * zMm / c.hardnessWavelengthMm);
    const double wear = 1.0 + c.wearForceIncrease * along;
    const double engaged = c.entryRampMm > 0.0 ? std::min(1.0, zMm / c.entryRampMm) : 1.0;
    // P = C a with a = a_nom + x_tip and x_tip = x_slide − P / k  =>  P = C (a_nom + x_slide) / (1 + C / k).
    const double cutting = c.radialSpecificForceNPerMm2 * c.feedMmPerRev * hardness * wear * engaged;
    return std::max(0.0, cutting * (depthNominal + slideMm) / (1.0 + cutting / m_stiffnessX));
}

void BoringMachine::step(double dtS, double offsetStartMm, double offsetRateMmPerS, double cycleStartS) {
    const double t = m_state.timeS + dtS;
    const double z = -m_scenario.cut.approachMm + m_axialSpeedMmPerS * t;
    const DitherState d = m_dither ? m_ditherProfile.at(t) : DitherState{};
    MotorCommand command;
    command.positionMm = offsetStartMm + offsetRateMmPerS * (t - cycleStartS) + d.positionMm;
    command.velocityMmPerS = offsetRateMmPerS + d.velocityMmPerS;
    command.accelerationMmPerS2 = d.accelerationMmPerS2;
    m_drive.step(dtS, command, -radialForce(z, m_drive.slidePositionMm()));

    const double force = radialForce(z, m_drive.slidePositionMm());
    m_state.timeS = t;
    m_state.toolZMm = z;
    m_state.radialForceN = force;
    m_state.tangentialForceN = force * m_scenario.cut.tangentialToRadialRatio;
    m_state.tipDeflectionXmm = -force / m_stiffnessX;
    m_state.tipDeflectionYmm = -m_state.tangentialForceN / m_stiffnessY;
    m_state.slidePositionMm = m_drive.slidePositionMm();
    m_state.radiusErrorMm = m_state.slidePositionMm + m_state.tipDeflectionXmm;
    m_state.appliedOffsetMm = command.positionMm - d.positionMm;
    m_state.cutting = z >= 0.0 && z <= m_scenario.cut.boreLengthMm;

    m_probe.advance(dtS, m_state.tipDeflectionXmm, m_state.tipDeflectionYmm);
    if (t >= m_nextProbeS) {
        sampleProbe();
        m_nextProbeS += 1.0 / m_scenario.probe.sampleRateHz;
    }
    if (m_state.cutting && m_observer) m_observer(m_state);
}

void BoringMachine::sampleProbe() {
    ProbeSample s;
    s.timeS = m_state.timeS;
    s.adcCode = m_probe.convert(m_state.timeS);
    s.linearised = m_probe.table(0).has_value();
    for (int plane = 0; plane < 2; ++plane) {
        const auto& table = m_probe.table(plane);
        const std::size_t p = static_cast<std::size_t>(plane);
        s.deflectionMm[p] =
            table ? table->deflectionUm(s.adcCode[p]) / 1000.0 : std::numeric_limits<double>::quiet_NaN();
    }
    m_probePort.queue.push_back(s);
    while (m_probePort.queue.size() > 10000)
        m_probePort.queue.pop_front();  // nobody reads: keep memory bounded
}

void BoringMachine::advanceCycle() {
    const double cycle = m_scenario.plcCycleS;
    const int steps = std::max(1, static_cast<int>(std::lround(cycle / m_scenario.simStepS)));
    const double dt = cycle / steps;
    const double start = m_state.timeS;
    const double target = m_outputPort.pendingOffsetMm;
    const double rate = (target - m_appliedOffsetMm) / cycle;
    for (int i = 0; i < steps; ++i)
        step(dt, m_appliedOffsetMm, rate, start);
    m_appliedOffsetMm = target;
    m_drivePort.queue.push_back(m_drive.sample(m_state.timeS));
    while (m_drivePort.queue.size() > 10000)
        m_drivePort.queue.pop_front();
}

bool BoringMachine::finished() const {
    return m_state.toolZMm > m_scenario.cut.boreLengthMm;
}

std::optional<DriveSample> BoringMachine::DrivePort::takeSample() {
    if (queue.empty() || !status.ready()) return std::nullopt;
    DriveSample s = queue.front();
    queue.pop_front();
    return s;
}

std::optional<ProbeSample> BoringMachine::ProbePort::takeSample() {
    if (queue.empty() || !status.ready()) return std::nullopt;
    ProbeSample s = queue.front();
    queue.pop_front();
    return s;
}

OutputResult BoringMachine::OutputPort::sendPartCorrection(const PartCorrection&) {
    return {false, "the boring simulator takes a dynamic X offset, not a part correction"};
}

OutputResult BoringMachine::OutputPort::sendDynamicOffset(double xOffsetMm) {
    if (!std::isfinite(xOffsetMm)) return {false, "the offset is not a number"};
    pendingOffsetMm = xOffsetMm;
    return {true, {}};
}

}  // namespace tt::core
