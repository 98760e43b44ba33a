#include "core/run/boring_run.h"

#include <cmath>
#include <string>

#include "core/model/tool_stiffness.h"

namespace tt::core {

namespace {

// The ranges a preset may set (config/boring_config.cpp) and paper 001's PLC cycle.
constexpr double kMinOffsetMm = 1e-3;
constexpr double kMaxOffsetMm = 10.0;
constexpr double kMinRateMmPerS = 1e-4;
constexpr double kMaxRateMmPerS = 100.0;
constexpr double kMinPlcCycleS = 0.01;
constexpr double kMaxPlcCycleS = 0.1;

std::string number(double v) {
    std::string s = std::to_string(v);
    while (s.size() > 1 && s.back() == '0')
        s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

std::string sentence(BoringRunRefusal kind, double value, double min, double max) {
    const std::string range = " is outside " + number(min) + " .. " + number(max);
    switch (kind) {
        case BoringRunRefusal::NoStiffness:
            return "the tool has no stiffness k_st above 0 N/mm (" + number(value) + ")";
        case BoringRunRefusal::NoCurrentGain:
            return "the tool has no current-to-force gain k_p above 0 N/A (" + number(value) + ")";
        case BoringRunRefusal::NoDriveReadout:
            return "the station has no drive current read-out";
        case BoringRunRefusal::NoProbe:
            return "the station has no probe mandrel";
        case BoringRunRefusal::BadPlane:
            return "probe plane " + number(value) + " must be 0 (X) or 1 (Y)";
        case BoringRunRefusal::OffsetLimitOutOfRange:
            return "offset limit " + number(value) + " mm" + range + " mm";
        case BoringRunRefusal::RateLimitOutOfRange:
            return "rate limit " + number(value) + " mm/s" + range + " mm/s";
        case BoringRunRefusal::PlcCycleOutOfRange:
            return "PLC cycle " + number(value * 1000.0) + " ms" + " is outside " + number(min * 1000.0) + " .. " +
                   number(max * 1000.0) + " ms";
        case BoringRunRefusal::PlcCycleNotTheStations:
            return "PLC cycle " + number(value * 1000.0) + " ms is not the simulated pass's " + number(max * 1000.0) +
                   " ms";
        case BoringRunRefusal::EstimatorSettings:
            return "the dither estimator refuses its thresholds";
        case BoringRunRefusal::HeldOffsetBeyondLimit:
            return "the CNC holds an offset of " + number(value) + " mm, more than the limit of " + number(max) + " mm";
    }
    return "the run is refused";
}

bool within(double v, double lo, double hi) {
    return std::isfinite(v) && v >= lo && v <= hi;
}

void checkChoices(const BoringRunChoices& c, BoringStation& station) {
    using R = BoringRunRefusal;
    if (!within(c.limits.maxOffsetMm, kMinOffsetMm, kMaxOffsetMm))
        throw BoringRunRefused(R::OffsetLimitOutOfRange, c.limits.maxOffsetMm, kMinOffsetMm, kMaxOffsetMm);
    if (!within(c.limits.maxRateMmPerS, kMinRateMmPerS, kMaxRateMmPerS))
        throw BoringRunRefused(R::RateLimitOutOfRange, c.limits.maxRateMmPerS, kMinRateMmPerS, kMaxRateMmPerS);
    if (!within(c.plcCycleS, kMinPlcCycleS - 1e-12, kMaxPlcCycleS + 1e-12))
        throw BoringRunRefused(R::PlcCycleOutOfRange, c.plcCycleS, kMinPlcCycleS, kMaxPlcCycleS);
    if (const std::optional<double> own = station.plcCycleS(); own && std::abs(*own - c.plcCycleS) > 1e-9)
        throw BoringRunRefused(R::PlcCycleNotTheStations, c.plcCycleS, *own, *own);
    if (!std::isfinite(c.heldOffsetMm) || std::abs(c.heldOffsetMm) > c.limits.maxOffsetMm)
        throw BoringRunRefused(R::HeldOffsetBeyondLimit, c.heldOffsetMm, -c.limits.maxOffsetMm, c.limits.maxOffsetMm);
    if (c.method == BoringMethod::None) return;
    if (!(c.stiffnessNPerMm > 0.0) || !std::isfinite(c.stiffnessNPerMm))
        throw BoringRunRefused(R::NoStiffness, std::isfinite(c.stiffnessNPerMm) ? c.stiffnessNPerMm : 0.0);
    if (c.method == BoringMethod::Current) {
        if (!station.driveReadout()) throw BoringRunRefused(R::NoDriveReadout);
        if (!(c.currentToForceNPerA > 0.0) || !std::isfinite(c.currentToForceNPerA))
            throw BoringRunRefused(R::NoCurrentGain,
                                   std::isfinite(c.currentToForceNPerA) ? c.currentToForceNPerA : 0.0);
    } else {
        if (!station.probe()) throw BoringRunRefused(R::NoProbe);
        if (c.plane != 0 && c.plane != 1) throw BoringRunRefused(R::BadPlane, c.plane, 0.0, 1.0);
    }
}

}  // namespace

BoringRunRefused::BoringRunRefused(BoringRunRefusal kind, double value, double min, double max)
    : std::invalid_argument(sentence(kind, value, min, max)), m_kind(kind), m_value(value), m_min(min), m_max(max) {}

BoringRunChoices boringChoices(const BoringScenario& scenario, BoringMethod method) {
    BoringRunChoices c;
    c.method = method;
    c.plane = 0;
    c.stiffnessNPerMm = effectiveStiffnessNPerMm(scenario.tool);
    c.currentToForceNPerA = scenario.tool.currentToForceGainNPerA;
    c.limits = scenario.limits;
    c.plcCycleS = scenario.plcCycleS;
    c.estimator = scenario.estimator;
    return c;
}

BoringRun::BoringRun(const BoringRunChoices& choices, BoringStation& station) : m_choices(choices), m_station(station) {
    checkChoices(choices, station);
    if (choices.method == BoringMethod::None) return;
    if (choices.method == BoringMethod::Current) {
        DitherEstimatorConfig config = choices.estimator;
        config.currentToForceNPerA = choices.currentToForceNPerA;
        config.stiffnessNPerMm = choices.stiffnessNPerMm;
        try {
            auto current = std::make_unique<CurrentDeflectionSource>(*station.driveReadout(), config);
            m_current = current.get();
            m_source = std::move(current);
        } catch (const std::invalid_argument&) {
            throw BoringRunRefused(BoringRunRefusal::EstimatorSettings);
        }
    } else {
        m_source = std::make_unique<ProbeDeflectionSource>(*station.probe(), choices.plane, std::nullopt,
                                                           choices.stiffnessNPerMm);
    }
    m_compensator =
        std::make_unique<InProcessCompensator>(*m_source, station.output(), choices.limits, choices.plcCycleS);
    m_compensator->resumeFrom(choices.heldOffsetMm);
}

BoringRun::~BoringRun() = default;

BoringRunCycle BoringRun::cycle() {
    m_station.advanceCycle();
    BoringRunCycle out;
    if (m_compensator) {
        CompensationCycle c = m_compensator->cycle(m_station.clock().nowS());
        if (c.outputProblem == OutputProblem::Refused)
            if (const std::optional<double> confirmed = m_station.confirmedOffsetMm()) {
                m_compensator->resumeFrom(*confirmed);
                c.step.offsetMm = m_compensator->offsetMm();
            }
        out.compensation = std::move(c);
    }
    out.truth = m_station.truth();
    return out;
}

void BoringRun::setSegment(SegmentKind kind) {
    if (m_current) m_current->estimator().setSegment(kind);
}

double BoringRun::offsetMm() const {
    return m_compensator ? m_compensator->offsetMm() : m_choices.heldOffsetMm;
}

std::unique_ptr<BoringRun> buildBoringRun(const BoringRunChoices& choices, BoringStation& station) {
    return std::make_unique<BoringRun>(choices, station);
}

}  // namespace tt::core
