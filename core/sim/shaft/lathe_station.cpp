#include "core/sim/shaft/lathe_station.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {
constexpr double kNever = std::numeric_limits<double>::infinity();
}

LatheStation::LatheStation(LathePartProcess& process, const LatheMicrometer& micrometer, std::uint64_t seed,
                           const Clock& clock, std::vector<double> measurePointZMm, LatheStationTiming timing)
    : LatheStation(process, LatheMicrometerModel(micrometer, seed), clock, std::move(measurePointZMm), timing) {}

LatheStation::LatheStation(LathePartProcess& process, LatheMicrometerModel gauge, const Clock& clock,
                           std::vector<double> measurePointZMm, LatheStationTiming timing)
    : m_process(process),
      m_micrometer(std::move(gauge)),
      m_clock(clock),
      m_points(std::move(measurePointZMm)),
      m_timing(timing) {
    if (m_points.empty()) throw std::invalid_argument("the measuring station needs at least one point to measure");
    if (!(m_timing.partTimeS > 0.0) || !(m_timing.measureStartS >= 0.0) || !(m_timing.perPointS >= 0.0) ||
        !std::isfinite(m_timing.partTimeS + m_timing.measureStartS + m_timing.perPointS))
        throw std::invalid_argument("the station times must be finite, the part time positive");
}

// ---- faults ---------------------------------------------------------------------------------------------

void LatheStation::silenceGauge(double fromS, double untilS) {
    if (!(untilS > fromS)) throw std::invalid_argument("a gauge silence must end after it starts");
    m_silences.emplace_back(fromS, untilS);
}

void LatheStation::injectReading(std::int64_t partNumber, int pointIndex, double valueMm) {
    m_injected[{partNumber, pointIndex}] = valueMm;
}

bool LatheStation::gaugeSilentAt(double t) const {
    return std::any_of(m_silences.begin(), m_silences.end(),
                       [t](const auto& w) { return t >= w.first && t < w.second; });
}

double LatheStation::afterSilence(double t) const {
    bool moved = true;
    while (moved) {
        moved = false;
        for (const auto& [from, until] : m_silences)
            if (t >= from && t < until) {
                t = until;
                moved = true;
            }
    }
    return t;
}

// ---- machining ------------------------------------------------------------------------------------------

void LatheStation::finishMachining() {
    if (!m_machining || m_clock.nowS() < m_machining->finishS) return;
    TurnedPart part = m_process.machine(m_machining->correction);
    const double finishS = m_machining->finishS;
    m_finished.push_back({part.partNumber, finishS});
    m_machined.push_back(part);
    while (m_machined.size() > m_keep)
        m_machined.pop_front();
    m_queue.push_back({std::move(part), finishS, 0});
    m_machining.reset();
}

void LatheStation::forgetPart(std::int64_t partNumber) {
    for (auto it = m_queue.begin(); it != m_queue.end(); ++it)
        if (it->part.partNumber == partNumber) {
            m_queue.erase(it);
            return;
        }
}

void LatheStation::acceptMachinedPart(TurnedPart part) {
    m_machined.push_back(part);
    while (m_machined.size() > m_keep)
        m_machined.pop_front();
    m_queue.push_back({std::move(part), m_clock.nowS(), 0});
}

void LatheStation::restoreMachinedPart(const PartCorrection& applied) {
    TurnedPart part = m_process.machine(applied);
    m_queue.push_back({std::move(part), m_clock.nowS(), 0});
}

DeviceHealth LatheStation::Output::health() const {
    if (!m_s.m_outputFault.empty()) return {DeviceState::Error, m_s.m_outputFault};
    return {DeviceState::Ready, "simulated CNC ready"};
}

OutputResult LatheStation::Output::sendPartCorrection(const PartCorrection& correction) {
    if (!m_s.m_outputFault.empty()) return {false, m_s.m_outputFault};
    if (correction.path.zMm.size() != correction.path.xCorrectionMm.size())
        return {false, "the correction path has different numbers of positions and corrections"};
    for (double v : correction.path.xCorrectionMm)
        if (!std::isfinite(v)) return {false, "the correction path contains a value that is not a number"};
    m_s.m_active = correction;
    m_s.m_sent.push_back(correction);
    ++m_s.m_sentCount;
    while (m_s.m_sent.size() > m_s.m_keep)
        m_s.m_sent.pop_front();
    return {true, {}};
}

OutputResult LatheStation::Output::sendDynamicOffset(double) {
    return {false, "the simulated lathe for shafts between centres takes part corrections, not dynamic offsets"};
}

DeviceHealth LatheStation::Cycle::health() const {
    return {DeviceState::Ready, m_s.m_machining ? "machining" : "waiting for the next part"};
}

OutputResult LatheStation::Cycle::startPart(std::int64_t partNumber) {
    m_s.finishMachining();
    if (m_s.m_machining)
        return {false, "the lathe is still machining part " + std::to_string(m_s.m_machining->correction.partNumber)};
    if (partNumber < 1) return {false, "part numbers start at 1"};
    PartCorrection c = m_s.m_active.value_or(PartCorrection{});
    c.partNumber = partNumber;
    m_s.m_machining = Machining{std::move(c), m_s.m_clock.nowS() + m_s.m_timing.partTimeS};
    return {true, {}};
}

std::optional<FinishedPart> LatheStation::Cycle::takeFinishedPart() {
    m_s.finishMachining();
    if (m_s.m_finished.empty()) return std::nullopt;
    FinishedPart f = m_s.m_finished.front();
    m_s.m_finished.pop_front();
    return f;
}

// ---- measuring ------------------------------------------------------------------------------------------

std::optional<double> LatheStation::nextReadingTimeS() const {
    if (!m_automatic || m_queue.empty()) return std::nullopt;
    const ToMeasure& front = m_queue.front();
    double t = m_lastReadingS + m_timing.perPointS;
    if (front.nextPoint == 0) t = std::max(t, front.readyS + m_timing.measureStartS);
    return afterSilence(t);
}

DeviceHealth LatheStation::Gauge::health() const {
    if (m_s.gaugeSilentAt(m_s.m_clock.nowS()))
        return {DeviceState::Disconnected, "the simulated gauge does not answer"};
    if (!m_s.m_automatic) return {DeviceState::Ready, "automatic measuring is off: diameters are entered by hand"};
    return {DeviceState::Ready, "simulated micrometer ready"};
}

std::optional<GaugeReading> LatheStation::Gauge::takeReading() {
    m_s.finishMachining();
    const double now = m_s.m_clock.nowS();
    if (m_s.gaugeSilentAt(now)) return std::nullopt;
    const auto due = m_s.nextReadingTimeS();
    if (!due || *due > now) return std::nullopt;
    ToMeasure& front = m_s.m_queue.front();
    const int point = front.nextPoint;
    const std::int64_t partNumber = front.part.partNumber;
    const auto injected = m_s.m_injected.find({partNumber, point});
    double value = 0.0;
    if (injected != m_s.m_injected.end()) {
        value = injected->second;
        m_s.m_injected.erase(injected);
    } else {
        value = m_s.m_micrometer.readMm(front.part.diameterAtMm(m_s.m_points[static_cast<std::size_t>(point)]),
                                        partNumber, point);
    }
    m_s.m_lastReadingS = *due;
    if (++front.nextPoint >= static_cast<int>(m_s.m_points.size())) m_s.m_queue.pop_front();
    return GaugeReading{value, *due};
}

double LatheStation::nextEventTimeS() const {
    double next = kNever;
    if (m_machining) next = std::min(next, m_machining->finishS);
    if (const auto reading = nextReadingTimeS()) next = std::min(next, *reading);
    const double now = m_clock.nowS();
    for (const auto& [from, until] : m_silences) {
        if (from > now) next = std::min(next, from);
        if (until > now) next = std::min(next, until);
    }
    return next;
}

}  // namespace tt::core
