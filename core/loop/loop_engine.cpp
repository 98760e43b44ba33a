#include "core/loop/loop_engine.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/common/text_format.h"
#include "core/control/correction_path_builder.h"

namespace tt::core {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

std::string partText(std::int64_t n) {
    return "part " + std::to_string(n);
}

LoopEvent makeEvent(LoopEvent::Kind kind, std::int64_t part, std::string message) {
    LoopEvent e;
    e.kind = kind;
    e.partNumber = part;
    e.message = std::move(message);
    return e;
}

std::string minutesText(double seconds) {
    return formatFixed(seconds / 60.0, 1) + " min";
}

}  // namespace

PartCorrection partCorrectionFor(const LoopConfig& config, std::int64_t partNumber,
                                 const std::vector<double>& appliedMm) {
    CorrectionPathRequest request;
    request.pointZMm = config.pointZMm;
    request.pointCorrectionMm = appliedMm;
    request.method = config.interpolation;
    request.diameterErrorModel = config.systematicModel;
    request.partLengthMm = config.partLengthMm;
    request.stepMm = config.pathStepMm;
    return PartCorrection{partNumber, config.pointZMm, appliedMm, buildCorrectionPath(request)};
}

PartCorrection partCorrectionFor(const LoopConfig& config, const StoredPart& part) {
    std::vector<double> applied;
    for (const PointCorrectionRecord& c : part.corrections)
        applied.push_back(c.appliedMm);
    if (applied.size() != config.pointZMm.size())
        throw std::invalid_argument("stored part " + std::to_string(part.partNumber) + " has " +
                                    std::to_string(applied.size()) + " corrections for " +
                                    std::to_string(config.pointZMm.size()) + " control points");
    return partCorrectionFor(config, part.partNumber, applied);
}

LoopEngine::LoopEngine(LoopConfig config, LoopPorts ports, std::unique_ptr<RunToRunController> controller)
    : m_config(std::move(config)),
      m_ports(ports),
      m_controller(std::move(controller)),
      m_limiter(m_config.limits, m_config.pointZMm) {
    validateLoopConfig(m_config);
    if (!m_controller) throw std::invalid_argument("the loop needs a controller");
    if (m_controller->pointCount() != static_cast<int>(m_config.pointZMm.size()))
        throw std::invalid_argument("the controller has " + std::to_string(m_controller->pointCount()) +
                                    " control points, the loop " + std::to_string(m_config.pointZMm.size()));
    m_nextPart = m_config.firstPartNumber;
}

// ---- commands -------------------------------------------------------------------------------------------

void LoopEngine::start(const RunDescription& run) {
    if (m_state != LoopState::Idle) throw std::logic_error("a run is already going; stop it first");
    m_runId.reset();
    if (m_ports.history) m_runId = m_ports.history->beginRun(run);
    resetRun(m_config.firstPartNumber);
    setState(LoopState::Running, "starting " + partText(m_nextPart));
}

void LoopEngine::resetRun(std::int64_t nextPart) {
    m_nextPart = nextPart;
    m_partsFinished = 0;
    m_complete = false;
    m_inProgress.reset();
    m_awaiting.clear();
    m_session.reset();
    m_measured.clear();
    m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
    m_pauseCause = PauseCause::None;
}

void LoopEngine::resumeFrom(const ResumePoint& point) {
    if (m_state != LoopState::Idle) throw std::logic_error("a run is already going; stop it first");
    m_controller->restoreState(point.controllerState);
    m_runId = point.run.runId;
    resetRun(point.lastPartNumber + 1);
    for (const StoredPart& part : point.pendingParts) {
        if (part.measurement)
            m_measured[part.partNumber] = *part.measurement;
        else
            m_awaiting.push_back(part.partNumber);
        if (part.partNumber == point.lastPartNumber && !part.corrections.empty()) {
            std::vector<double> applied;
            for (const PointCorrectionRecord& c : part.corrections)
                applied.push_back(c.appliedMm);
            m_limiter.setLastApplied(std::move(applied));
        }
    }
    if (!m_awaiting.empty()) openSession();
    setState(LoopState::Running, "continuing run " + std::to_string(*m_runId) + " with " + partText(m_nextPart));
}

void LoopEngine::pause() {
    if (m_state != LoopState::Running && m_state != LoopState::Paused) return;
    m_pauseCause = PauseCause::Operator;
    setState(LoopState::Paused, "paused by the operator; the CNC keeps the last correction");
}

void LoopEngine::continueRun() {
    if (m_state != LoopState::Paused) return;
    m_pauseCause = PauseCause::None;
    m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
    setState(LoopState::Running, m_inProgress ? "machining " + partText(m_inProgress->partNumber) : "continuing");
}

void LoopEngine::stop() {
    if (m_state == LoopState::Idle) return;
    if (m_inProgress)
        alarm("part-abandoned",
              partText(m_inProgress->partNumber) + " was on the machine when the run was stopped; it is not recorded",
              m_inProgress->partNumber);
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->finishRun(*m_runId, "stopped");
        } catch (const std::exception& e) {
            LoopEvent event = makeEvent(LoopEvent::Kind::Alarm, 0,
                                        std::string("the end of the run could not be stored: ") + e.what());
            event.alarmKind = "history";
            notify(std::move(event));
        }
    }
    m_inProgress.reset();
    m_pauseCause = PauseCause::None;
    setState(LoopState::Idle, "stopped");
}

void LoopEngine::skipMeasurement() {
    if (m_awaiting.empty()) return;
    const std::int64_t part = m_awaiting.front();
    PartMeasurementRecord record;
    record.partNumber = part;
    record.timeS = m_ports.clock.nowS();
    for (std::size_t i = 0; i < m_config.pointZMm.size(); ++i)
        record.points.push_back({static_cast<int>(i), m_config.pointZMm[i], std::nullopt, m_config.nominalDiameterMm,
                                 false, "not measured: skipped by the operator"});
    completeMeasurement(std::move(record));
}

// ---- the step -------------------------------------------------------------------------------------------

void LoopEngine::step() {
    if (m_state == LoopState::Idle || m_state == LoopState::Fault) return;
    watchDevices();
    collectFinishedParts();
    if (m_state == LoopState::Fault) return;
    collectReadings();
    if (m_state == LoopState::Fault) return;
    if (m_state == LoopState::Paused && m_pauseCause == PauseCause::Gauge) {
        const std::int64_t due = m_nextPart - m_config.delayParts;
        if (m_measured.count(due) || m_ports.gauge.health().ready()) {
            m_pauseCause = PauseCause::None;
            m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
            setState(LoopState::Running, "the gauge answers again; continuing");
        }
    }
    if (m_state == LoopState::Running && !m_inProgress) startNextPart();
    maybeComplete();
}

double LoopEngine::nextWakeS() const {
    if (m_state == LoopState::Running && !m_inProgress && !std::isnan(m_waitingSinceS))
        return m_waitingSinceS + m_config.gaugeTimeoutS;
    return kNever;
}

void LoopEngine::watchDevices() {
    const std::pair<const char*, DeviceHealth> devices[] = {
        {"gauge", m_ports.gauge.health()}, {"cnc", m_ports.output.health()}, {"machine", m_ports.machine.health()}};
    for (const auto& [name, health] : devices) {
        auto it = m_deviceStates.find(name);
        if (it != m_deviceStates.end() && it->second == health.state) continue;
        m_deviceStates[name] = health.state;
        LoopEvent event = makeEvent(LoopEvent::Kind::DeviceChanged, 0, health.message);
        event.device = name;
        event.health = health;
        notify(std::move(event));
    }
}

void LoopEngine::collectFinishedParts() {
    while (auto finished = m_ports.machine.takeFinishedPart()) {
        if (!m_inProgress || finished->partNumber != m_inProgress->partNumber) {
            alarm("machine", "the machine reported " + partText(finished->partNumber) +
                                 " finished, which the loop did not start; ignored");
            continue;
        }
        PartCompletionRecord record;
        record.partNumber = m_inProgress->partNumber;
        record.startedS = m_inProgress->startedS;
        record.finishedS = finished->timeS;
        record.corrections = m_inProgress->corrections;
        record.usedMeasurement = m_inProgress->usedMeasurement;
        record.controllerState = m_inProgress->controllerState;
        if (m_ports.history && m_runId) {
            try {
                m_ports.history->recordPart(*m_runId, record);
            } catch (const std::exception& e) {
                fault("the history could not be written, " + partText(record.partNumber) + " is not stored (" +
                      e.what() + "); the CNC keeps the last correction");
                return;
            }
        }
        m_inProgress.reset();
        ++m_partsFinished;
        m_awaiting.push_back(record.partNumber);
        if (!m_session) openSession();
        LoopEvent event =
            makeEvent(LoopEvent::Kind::PartFinished, record.partNumber, partText(record.partNumber) + " finished");
        event.corrections = record.corrections;
        notify(std::move(event));
    }
}

void LoopEngine::openSession() {
    m_session.emplace(m_config.pointZMm, m_config.nominalDiameterMm, std::numeric_limits<double>::max());
}

void LoopEngine::collectReadings() {
    while (auto reading = m_ports.gauge.takeReading()) {
        if (m_awaiting.empty()) {
            alarm("reading-unexpected", "a reading of " + formatFixed(reading->diameterMm, 3) +
                                            " mm arrived but no part is waiting to be measured; it was ignored");
            continue;
        }
        if (!m_session) openSession();
        const SessionAccept accepted = m_session->accept(*reading);
        if (!accepted.accepted) {
            alarm("reading-refused", accepted.message, m_awaiting.front());
            continue;
        }
        if (!m_session->complete()) continue;
        std::vector<std::optional<double>> diameters;
        for (double d : m_session->diametersMm())
            diameters.emplace_back(d);
        completeMeasurement(judge(m_awaiting.front(), diameters, reading->timeS));
        if (m_state == LoopState::Fault) return;
    }
}

PartMeasurementRecord LoopEngine::judge(std::int64_t partNumber, const std::vector<std::optional<double>>& diameters,
                                        double timeS) const {
    PartMeasurementRecord record;
    record.partNumber = partNumber;
    record.timeS = timeS;
    for (std::size_t i = 0; i < m_config.pointZMm.size(); ++i) {
        PointMeasurementRecord p{
            static_cast<int>(i), m_config.pointZMm[i], diameters[i], m_config.nominalDiameterMm, false, {}};
        if (!p.measuredMm) {
            p.reason = "not measured";
        } else {
            // The measurement session's own plausibility rule and wording, for one point.
            MeasurementSession check({p.zMm}, m_config.nominalDiameterMm, m_config.plausibleRangeMm);
            const SessionAccept verdict = check.accept({*p.measuredMm, timeS});
            p.accepted = verdict.accepted;
            if (!verdict.accepted) p.reason = "rejected: " + verdict.message;
        }
        record.points.push_back(std::move(p));
    }
    return record;
}

void LoopEngine::completeMeasurement(PartMeasurementRecord record) {
    if (m_awaiting.empty() || m_awaiting.front() != record.partNumber) return;
    m_awaiting.pop_front();
    m_session.reset();
    if (!m_awaiting.empty()) openSession();
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->recordMeasurement(*m_runId, record);
        } catch (const std::exception& e) {
            fault("the diameters of " + partText(record.partNumber) + " could not be stored (" + e.what() +
                  "); the CNC keeps the last correction");
            return;
        }
    }
    for (const PointMeasurementRecord& p : record.points)
        if (!p.accepted && p.measuredMm)
            alarm("measurement-rejected",
                  partText(record.partNumber) + ", point " + std::to_string(p.pointIndex + 1) + ": " + p.reason,
                  record.partNumber);
    const bool willBeUsed =
        !m_config.lastPartNumber || record.partNumber + m_config.delayParts <= *m_config.lastPartNumber;
    LoopEvent event =
        makeEvent(LoopEvent::Kind::PartMeasured, record.partNumber, partText(record.partNumber) + " measured");
    event.measurement = record;
    notify(std::move(event));
    if (willBeUsed && record.partNumber + m_config.delayParts >= m_nextPart)
        m_measured[record.partNumber] = std::move(record);
}

void LoopEngine::offerMeasurement(PartMeasurementRecord& record) {
    PartMeasurement measurement;
    measurement.partNumber = record.partNumber;
    measurement.deviationMm.resize(static_cast<Eigen::Index>(record.points.size()));
    for (std::size_t i = 0; i < record.points.size(); ++i) {
        const PointMeasurementRecord& p = record.points[i];
        measurement.deviationMm(static_cast<Eigen::Index>(i)) =
            p.accepted && p.measuredMm ? *p.measuredMm - p.nominalMm : std::numeric_limits<double>::quiet_NaN();
    }
    MeasurementVerdict verdict;
    try {
        verdict = m_controller->addMeasurement(measurement);
    } catch (const std::exception& e) {
        verdict.accepted.assign(record.points.size(), false);
        verdict.reasons.assign(record.points.size(), std::string("the controller could not use it: ") + e.what());
    }
    for (std::size_t i = 0; i < record.points.size(); ++i) {
        PointMeasurementRecord& p = record.points[i];
        if (!p.accepted) continue;
        const bool ok = i < verdict.accepted.size() && verdict.accepted[i];
        if (ok) continue;
        p.accepted = false;
        p.reason = "rejected by the controller: " + (i < verdict.reasons.size() && !verdict.reasons[i].empty()
                                                         ? verdict.reasons[i]
                                                         : std::string("no reason given"));
        alarm("measurement-rejected",
              partText(record.partNumber) + ", point " + std::to_string(p.pointIndex + 1) + ": " + p.reason,
              record.partNumber);
    }
}

void LoopEngine::startNextPart() {
    if (m_config.lastPartNumber && m_nextPart > *m_config.lastPartNumber) {
        if (!m_awaiting.empty())
            setState(LoopState::Running, "measuring the last parts (" + partText(m_awaiting.front()) + " next)");
        return;
    }
    const std::int64_t n = m_nextPart;
    const std::int64_t due = n - m_config.delayParts;
    const double now = m_ports.clock.nowS();
    std::optional<PartMeasurementRecord> used;
    if (due >= m_config.firstPartNumber) {
        auto it = m_measured.find(due);
        if (it == m_measured.end()) {
            if (std::isnan(m_waitingSinceS)) m_waitingSinceS = now;
            const DeviceHealth gauge = m_ports.gauge.health();
            if (!gauge.ready()) {
                m_pauseCause = PauseCause::Gauge;
                const std::string text = "the gauge is not ready (" + gauge.message + "); " + partText(n) +
                                         " needs the diameters of " + partText(due) +
                                         ". Paused, the CNC keeps the last correction";
                setState(LoopState::Paused, text);
                alarm("gauge-silent", text, due);
            } else if (now - m_waitingSinceS >= m_config.gaugeTimeoutS) {
                m_pauseCause = PauseCause::Gauge;
                const std::string text = "no diameters of " + partText(due) + " for " +
                                         minutesText(now - m_waitingSinceS) +
                                         ". Paused, the CNC keeps the last correction";
                setState(LoopState::Paused, text);
                alarm("gauge-silent", text, due);
            } else {
                setState(LoopState::Running, "waiting for the diameters of " + partText(due));
            }
            return;
        }
        used = std::move(it->second);
        m_measured.erase(it);
        offerMeasurement(*used);
    }
    m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();

    const std::vector<double> previous = m_limiter.lastAppliedMm();
    Eigen::VectorXd computed;
    LimiterOutcome limited;
    PartCorrection correction;
    try {
        computed = m_controller->nextCorrection(n);
        limited = m_limiter.apply(computed);
        correction = partCorrectionFor(m_config, n, limited.appliedMm);
    } catch (const std::exception& e) {
        m_limiter.setLastApplied(previous);
        fault("the corrections for " + partText(n) + " could not be computed (" + e.what() +
              "); the CNC keeps the last correction");
        return;
    }
    for (const std::string& note : limited.notes)
        alarm("correction-limited", partText(n) + ": " + note, n);

    OutputResult sent = m_ports.output.sendPartCorrection(correction);
    if (!sent.ok) {
        m_limiter.setLastApplied(previous);
        fault("the CNC refused the corrections for " + partText(n) + ": " + sent.message +
              "; it keeps the last correction");
        return;
    }
    OutputResult started = m_ports.machine.startPart(n);
    if (!started.ok) {
        fault("the machine did not start " + partText(n) + ": " + started.message);
        return;
    }
    InProgress progress;
    progress.partNumber = n;
    progress.startedS = now;
    for (std::size_t i = 0; i < m_config.pointZMm.size(); ++i)
        progress.corrections.push_back(
            {static_cast<int>(i), m_config.pointZMm[i], computed(static_cast<Eigen::Index>(i)), limited.appliedMm[i]});
    progress.usedMeasurement = std::move(used);
    progress.controllerState = m_controller->saveState();
    m_inProgress = std::move(progress);
    ++m_nextPart;
    setState(LoopState::Running, "machining " + partText(n));
    LoopEvent event = makeEvent(LoopEvent::Kind::PartStarted, n, "machining " + partText(n));
    event.corrections = m_inProgress->corrections;
    event.path = std::move(correction.path);
    notify(std::move(event));
}

void LoopEngine::maybeComplete() {
    if (m_complete || !m_config.lastPartNumber || m_nextPart <= *m_config.lastPartNumber || m_inProgress ||
        !m_awaiting.empty() || m_state == LoopState::Fault || m_state == LoopState::Idle)
        return;
    m_complete = true;
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->finishRun(*m_runId, "complete");
        } catch (const std::exception& e) {
            alarm("history", std::string("the end of the run could not be stored: ") + e.what());
        }
    }
    setState(LoopState::Idle, "run complete: " + partText(*m_config.lastPartNumber) + " was the last");
}

std::optional<std::int64_t> LoopEngine::partAwaitingMeasurement() const {
    if (m_awaiting.empty()) return std::nullopt;
    return m_awaiting.front();
}

std::optional<std::size_t> LoopEngine::nextMeasuredPoint() const {
    if (!m_session) return std::nullopt;
    return m_session->currentPoint();
}

// ---- reporting ------------------------------------------------------------------------------------------

void LoopEngine::setState(LoopState state, const std::string& detail) {
    if (state == m_state && detail == m_detail) return;
    m_state = state;
    m_detail = detail;
    notify(makeEvent(LoopEvent::Kind::StateChanged, 0, detail));
}

void LoopEngine::alarm(const std::string& kind, const std::string& message, std::optional<std::int64_t> part) {
    const double now = m_ports.clock.nowS();
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->recordAlarm(*m_runId, {part, now, kind, message});
        } catch (const std::exception&) {
            // The alarm is still shown; a history that cannot be written faults the loop at the next part.
        }
    }
    LoopEvent event = makeEvent(LoopEvent::Kind::Alarm, part.value_or(0), message);
    event.alarmKind = kind;
    notify(std::move(event));
}

void LoopEngine::fault(const std::string& message) {
    setState(LoopState::Fault, message);
    alarm("fault", message);
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->finishRun(*m_runId, "fault");
        } catch (const std::exception&) {
            // Already reported: the fault itself may be the history.
        }
    }
}

void LoopEngine::notify(LoopEvent event) {
    if (!m_listener) return;
    event.state = m_state;
    event.timeS = m_ports.clock.nowS();
    m_listener->onLoopEvent(event);
}

}  // namespace tt::core
