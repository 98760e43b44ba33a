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

LoopEvent makeEvent(LoopEvent::Kind kind, std::int64_t part, Notice notice) {
    LoopEvent e;
    e.kind = kind;
    e.partNumber = part;
    e.message = describe(notice);
    e.notice = std::move(notice);
    return e;
}

/// A notice of `kind` about part `part` (and `other`).
Notice notice(NoticeKind kind, std::int64_t part = 0, std::int64_t other = 0) {
    return Notice(kind, part, other);
}

/// A notice of `kind` about part `part` with the words of a device or the storage.
Notice because(NoticeKind kind, std::int64_t part, std::string cause) {
    Notice n{kind, part};
    n.cause = std::move(cause);
    return n;
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
      m_limiter(m_config.limits, m_config.pointZMm),
      m_monitor(m_config.mismatch) {
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
    if (m_adaptive) m_adaptive->reset();
    resetRun(m_config.firstPartNumber);
    setState(LoopState::Running, notice(NoticeKind::Starting, m_nextPart));
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
    m_monitor.reset();
    m_holding = false;
}

void LoopEngine::resumeFrom(const ResumePoint& point) {
    if (m_state != LoopState::Idle) throw std::logic_error("a run is already going; stop it first");
    if (m_adaptive) {
        m_adaptive->reset();
        if (m_ports.history) {
            // The controller the recorded adaptations left in place, and the recent parts for priming and
            // identification.
            const std::vector<AdaptationRecord> records = m_ports.history->adaptations(point.run.runId);
            std::unique_ptr<RunToRunController> adapted =
                m_adaptive->restore(records, m_ports.history->parts(point.run.runId));
            if (adapted) m_controller = std::move(adapted);
        }
    }
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
    setState(LoopState::Running, notice(NoticeKind::ContinuingRun, m_nextPart, *m_runId));
}

void LoopEngine::pause() {
    if (m_state != LoopState::Running && m_state != LoopState::Paused) return;
    m_pauseCause = PauseCause::Operator;
    setState(LoopState::Paused, notice(NoticeKind::PausedByOperator));
}

void LoopEngine::continueRun() {
    if (m_state != LoopState::Paused) return;
    m_pauseCause = PauseCause::None;
    m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
    setState(LoopState::Running,
             m_inProgress ? notice(NoticeKind::Machining, m_inProgress->partNumber) : notice(NoticeKind::Continuing));
}

void LoopEngine::stop() {
    if (m_state == LoopState::Idle) return;
    if (m_inProgress)
        alarm("part-abandoned", notice(NoticeKind::PartAbandoned, m_inProgress->partNumber), m_inProgress->partNumber);
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->finishRun(*m_runId, "stopped");
        } catch (const std::exception& e) {
            LoopEvent event = makeEvent(LoopEvent::Kind::Alarm, 0, because(NoticeKind::HistoryEndFailed, 0, e.what()));
            event.alarmKind = "history";
            notify(std::move(event));
        }
    }
    m_inProgress.reset();
    m_pauseCause = PauseCause::None;
    setState(LoopState::Idle, notice(NoticeKind::Stopped));
}

void LoopEngine::replaceController(std::unique_ptr<RunToRunController> next, int transferParts,
                                   std::optional<RunToRunSetup> tuning) {
    if (!next) throw std::invalid_argument("the loop needs a controller");
    if (next->pointCount() != m_controller->pointCount())
        throw std::invalid_argument("the new controller has " + std::to_string(next->pointCount()) +
                                    " control points, the loop " + std::to_string(m_controller->pointCount()));
    if (transferParts < 1 || transferParts > 1000)
        throw std::invalid_argument("the controller transfer must last 1 .. 1000 parts, not " +
                                    std::to_string(transferParts));
    m_nextController = std::move(next);
    m_transferParts = transferParts;
    m_nextTuning = std::move(tuning);
}

void LoopEngine::setAdaptation(RunToRunSetup setup) {
    if (static_cast<int>(setup.plant.points.size()) != m_controller->pointCount())
        throw std::invalid_argument("the adaptation's setup has " + std::to_string(setup.plant.points.size()) +
                                    " control points, the loop " + std::to_string(m_controller->pointCount()));
    m_adaptive = std::make_unique<AdaptiveLoop>(std::move(setup), m_config.adaptation, m_config.mismatch.action,
                                                m_config.delayParts, m_config.tolerances);
}

bool LoopEngine::acceptProposal() {
    if (!m_adaptive || !m_adaptive->hasProposal()) return false;
    m_acceptPending = true;
    return true;
}

std::string LoopEngine::controllerDescription() const {
    if (m_holding) return "holding the last correction (model mismatch)";
    if (m_adaptive) return m_adaptive->controllerDescription();
    return m_controller->name();
}

void LoopEngine::takeOver(std::unique_ptr<RunToRunController> next, std::int64_t part, int transferParts) {
    if (m_adaptive) m_adaptive->prime(*next, part);
    m_controller = std::move(next);
    m_transferParts = transferParts;
    m_transferPending = true;
    m_monitor.reset();
}

Eigen::VectorXd LoopEngine::correctionWithTransfer(std::int64_t part, const std::vector<double>& previous) {
    Eigen::VectorXd u = m_controller->nextCorrection(part);
    if (m_transferPending) {
        // The controller took over at this part: its first correction is offset to the one applied last.
        m_transferPending = false;
        m_transferOffsetMm =
            Eigen::Map<const Eigen::VectorXd>(previous.data(), static_cast<Eigen::Index>(previous.size())) - u;
        m_transferLeft = m_transferParts;
        return u + m_transferOffsetMm;
    }
    if (m_transferLeft > 0) {
        --m_transferLeft;
        u += m_transferOffsetMm * (static_cast<double>(m_transferLeft) / m_transferParts);
    }
    return u;
}

LimiterOutcome LoopEngine::correctionsFor(std::int64_t n, const std::vector<double>& previous,
                                          Eigen::VectorXd& computed) {
    const Eigen::Map<const Eigen::VectorXd> last(previous.data(), static_cast<Eigen::Index>(previous.size()));
    computed = correctionWithTransfer(n, previous);
    if (m_adaptive) computed += m_adaptive->dither(n);
    if (m_holding) computed = last;
    LimiterOutcome limited = m_limiter.apply(computed);
    // The controller learns what the part really receives (limits, transfer, dither, hold).
    m_controller->correctionApplied(
        n, Eigen::Map<const Eigen::VectorXd>(limited.appliedMm.data(),
                                             static_cast<Eigen::Index>(limited.appliedMm.size())));
    return limited;
}

void LoopEngine::skipMeasurement() {
    if (m_awaiting.empty()) return;
    const std::int64_t part = m_awaiting.front();
    PartMeasurementRecord record;
    record.partNumber = part;
    record.timeS = m_ports.clock.nowS();
    for (std::size_t i = 0; i < m_config.pointZMm.size(); ++i)
        record.points.push_back(rejectedPoint(i, std::nullopt, Notice{NoticeKind::SkippedByOperator, part}));
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
    if (m_state == LoopState::Paused &&
        (m_pauseCause == PauseCause::Gauge || m_pauseCause == PauseCause::GaugeSilent)) {
        const std::int64_t due = m_nextPart - m_config.delayParts;
        const bool back =
            m_pauseCause == PauseCause::Gauge ? m_ports.gauge.health().ready() : m_ports.gauge.handEntry();
        if (m_measured.count(due) || back) {
            m_pauseCause = PauseCause::None;
            m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
            setState(LoopState::Running, notice(NoticeKind::GaugeBack));
        }
    }
    if (m_state == LoopState::Paused && m_pauseCause == PauseCause::History && !m_ports.history->refusesNextPart()) {
        m_pauseCause = PauseCause::None;
        setState(LoopState::Running, notice(NoticeKind::Continuing));
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
        LoopEvent event = makeEvent(LoopEvent::Kind::DeviceChanged, 0, Notice{});
        event.message = health.message;
        event.device = name;
        event.health = health;
        notify(std::move(event));
    }
}

void LoopEngine::collectFinishedParts() {
    while (auto finished = m_ports.machine.takeFinishedPart()) {
        if (!m_inProgress || finished->partNumber != m_inProgress->partNumber) {
            alarm("machine", notice(NoticeKind::UnexpectedPartFinished, finished->partNumber));
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
                fault(because(NoticeKind::HistoryPartFailed, record.partNumber, e.what()));
                return;
            }
        }
        m_inProgress.reset();
        ++m_partsFinished;
        m_awaiting.push_back(record.partNumber);
        if (!m_session) openSession();
        LoopEvent event = makeEvent(LoopEvent::Kind::PartFinished, record.partNumber,
                                    notice(NoticeKind::PartFinished, record.partNumber));
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
            Notice unexpected = notice(NoticeKind::ReadingUnexpected);
            unexpected.value = reading->diameterMm;
            alarm("reading-unexpected", unexpected);
            continue;
        }
        if (!m_session) openSession();
        const SessionAccept accepted = m_session->accept(*reading);
        if (!accepted.accepted) {
            Notice refusal = accepted.refusal;
            refusal.part = m_awaiting.front();
            alarm("reading-refused", refusal, m_awaiting.front());
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
        if (!diameters[i]) {
            record.points.push_back(rejectedPoint(i, std::nullopt, Notice{NoticeKind::NotMeasured, partNumber}));
            continue;
        }
        // The measurement session's own plausibility rule, for one point.
        MeasurementSession check({m_config.pointZMm[i]}, m_config.nominalDiameterMm, m_config.plausibleRangeMm);
        SessionAccept verdict = check.accept({*diameters[i], timeS});
        verdict.refusal.part = partNumber;
        verdict.refusal.point = static_cast<int>(i) + 1;
        record.points.push_back(verdict.accepted ? acceptedPoint(i, *diameters[i])
                                                 : rejectedPoint(i, diameters[i], verdict.refusal));
        // The tolerance verdict is on the part, not on the reading: every plausible reading gets one.
        if (verdict.accepted && !m_config.tolerances.empty()) {
            record.points.back().tolerance = m_config.tolerances[i];
            record.points.back().verdict = outerDiameterVerdict(m_config.tolerances[i], *diameters[i]);
        }
    }
    return record;
}

void LoopEngine::judgeTolerances(const PartMeasurementRecord& record) {
    bool scrap = false;
    for (const PointMeasurementRecord& p : record.points) {
        if (!p.verdict || *p.verdict == ToleranceVerdict::Good || !p.tolerance || !p.measuredMm) continue;
        const bool rework = *p.verdict == ToleranceVerdict::Rework;
        Notice out(rework ? NoticeKind::OutOfToleranceRework : NoticeKind::OutOfToleranceScrap, record.partNumber);
        out.point = p.pointIndex + 1;
        out.zMm = p.zMm;
        out.value = *p.measuredMm;
        out.reference = p.tolerance->nominalMm;
        out.limit = rework ? p.tolerance->upperLimitMm() : p.tolerance->lowerLimitMm();
        alarm("out-of-tolerance", out, record.partNumber);
        scrap = scrap || !rework;
    }
    if (scrap && m_config.pauseOnScrap && m_state == LoopState::Running) {
        m_pauseCause = PauseCause::Operator;
        setState(LoopState::Paused, notice(NoticeKind::PausedOnScrap, record.partNumber));
    }
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
            fault(because(NoticeKind::HistoryMeasurementFailed, record.partNumber, e.what()));
            return;
        }
    }
    for (const PointMeasurementRecord& p : record.points)
        if (!p.accepted && p.measuredMm) alarm("measurement-rejected", p.rejection, record.partNumber);
    judgeTolerances(record);
    const bool willBeUsed =
        !m_config.lastPartNumber || record.partNumber + m_config.delayParts <= *m_config.lastPartNumber;
    LoopEvent event = makeEvent(LoopEvent::Kind::PartMeasured, record.partNumber,
                                notice(NoticeKind::PartMeasured, record.partNumber));
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
        verdict.reasons.assign(record.points.size(),
                               because(NoticeKind::ControllerFailed, record.partNumber, e.what()));
    }
    if (m_adaptive) m_adaptive->partMeasured(record.partNumber, measurement.deviationMm, verdict.accepted);
    watchModel(record.partNumber);
    for (std::size_t i = 0; i < record.points.size(); ++i) {
        PointMeasurementRecord& p = record.points[i];
        if (!p.accepted) continue;
        const bool ok = i < verdict.accepted.size() && verdict.accepted[i];
        if (ok) continue;
        Notice why = i < verdict.reasons.size() && verdict.reasons[i] ? verdict.reasons[i]
                                                                      : Notice{NoticeKind::ControllerRejected};
        why.part = record.partNumber;
        why.point = p.pointIndex + 1;
        why.zMm = p.zMm;
        const auto tolerance = p.tolerance;
        const auto toleranceVerdict = p.verdict;
        p = rejectedPoint(i, p.measuredMm, why);
        p.tolerance = tolerance;
        p.verdict = toleranceVerdict;
        alarm("measurement-rejected", p.rejection, record.partNumber);
    }
}

void LoopEngine::watchModel(std::int64_t partNumber) {
    const std::optional<Innovation> innovation = m_controller->lastInnovation();
    if (!innovation || innovation->partNumber != partNumber) return;
    const std::optional<MismatchFinding> found = m_monitor.add(*innovation);
    if (!found) return;
    const MismatchAction action = m_config.mismatch.action;
    const bool adapts = m_adaptive && (action == MismatchAction::Adapt || action == MismatchAction::Propose);
    m_holding = action == MismatchAction::Hold || (!m_adaptive && action != MismatchAction::AlarmOnly);
    Notice what(NoticeKind::ModelMismatch, found->partNumber, found->windowParts);
    what.point = found->point;
    what.value = found->statistic;
    what.limit = found->threshold;
    what.reference = found->test == MismatchTest::Correlation    ? 1.0
                     : found->test == MismatchTest::Independence ? 2.0
                                                                 : 0.0;
    if (m_holding) what.cause = "hold";
    if (adapts) what.cause = mismatchActionName(action);
    alarm(kModelMismatchAlarm, what, found->partNumber);
    if (adapts) applyAdaptation(m_adaptive->onMismatch(what, m_nextPart, m_ports.clock.nowS()), m_nextPart);
}

void LoopEngine::applyAdaptation(AdaptationStep step, std::int64_t part) {
    if (step.controller) takeOver(std::move(step.controller), part, m_config.adaptation.transferParts);
    if (step.record && m_ports.history && m_runId) {
        try {
            m_ports.history->recordAdaptation(*m_runId, *step.record);
        } catch (const std::exception& e) {
            alarm("history", because(NoticeKind::HistoryPartFailed, part, e.what()), part);
        }
    }
    if (!step.notice) return;
    const double now = m_ports.clock.nowS();
    const std::string message = describe(step.notice);
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->recordAlarm(*m_runId, {part, now, kAdaptationAlarm, message});
        } catch (const std::exception&) {
            // Shown anyway; a history that cannot be written faults the loop at the next part.
        }
    }
    LoopEvent event = makeEvent(LoopEvent::Kind::Alarm, part, step.notice);
    event.alarmKind = kAdaptationAlarm;
    event.adaptation = std::move(step.record);
    notify(std::move(event));
}

void LoopEngine::startNextPart() {
    if (m_config.lastPartNumber && m_nextPart > *m_config.lastPartNumber) {
        if (!m_awaiting.empty())
            setState(LoopState::Running, notice(NoticeKind::MeasuringLastParts, m_awaiting.front()));
        return;
    }
    if (historyRefusesPart()) return;
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
                Notice silent = because(NoticeKind::GaugeNotReady, n, gauge.message);
                silent.otherPart = due;
                setState(LoopState::Paused, silent);
                alarm("gauge-silent", silent, due);
            } else if (!m_ports.gauge.handEntry() && now - m_waitingSinceS >= m_config.gaugeTimeoutS) {
                m_pauseCause = PauseCause::GaugeSilent;
                Notice late = notice(NoticeKind::NoDiameters, n, due);
                late.value = (now - m_waitingSinceS) / 60.0;
                setState(LoopState::Paused, late);
                alarm("gauge-silent", late, due);
            } else {
                setState(LoopState::Running, notice(NoticeKind::WaitingForDiameters, n, due));
            }
            return;
        }
        used = std::move(it->second);
        m_measured.erase(it);
    }
    // A controller applied from outside takes over before it gets the measurement due (it is primed up to here).
    if (m_nextController) {
        if (m_adaptive) m_adaptive->controllerReplaced(std::move(m_nextTuning), n);
        m_nextTuning.reset();
        takeOver(std::move(m_nextController), n, m_transferParts);
    }
    if (used) offerMeasurement(*used);
    if (m_adaptive && m_acceptPending) {
        m_acceptPending = false;
        applyAdaptation(m_adaptive->acceptProposal(n, now), n);
    }
    if (m_adaptive) applyAdaptation(m_adaptive->beforePart(n, now), n);
    m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();

    const std::vector<double> previous = m_limiter.lastAppliedMm();
    Eigen::VectorXd computed;
    LimiterOutcome limited;
    PartCorrection correction;
    try {
        limited = correctionsFor(n, previous, computed);
        correction = partCorrectionFor(m_config, n, limited.appliedMm);
    } catch (const std::exception& e) {
        m_limiter.setLastApplied(previous);
        fault(because(NoticeKind::CorrectionsFailed, n, e.what()));
        return;
    }
    for (Notice note : limited.notes) {
        note.part = n;
        alarm("correction-limited", note, n);
    }

    m_monitor.partStarted(n, limited.appliedMm);
    if (m_adaptive) m_adaptive->partStarted(n, limited.appliedMm);
    OutputResult sent = m_ports.output.sendPartCorrection(correction);
    if (!sent.ok) {
        m_limiter.setLastApplied(previous);
        fault(because(NoticeKind::CncRefused, n, sent.message));
        return;
    }
    OutputResult started = m_ports.machine.startPart(n);
    if (!started.ok) {
        fault(because(NoticeKind::MachineRefused, n, started.message));
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
    setState(LoopState::Running, notice(NoticeKind::Machining, n));
    LoopEvent event = makeEvent(LoopEvent::Kind::PartStarted, n, notice(NoticeKind::Machining, n));
    event.corrections = m_inProgress->corrections;
    event.path = std::move(correction.path);
    notify(std::move(event));
}

bool LoopEngine::historyRefusesPart() {
    if (!m_ports.history || !m_runId) return false;
    Notice refusal = m_ports.history->refusesNextPart();
    if (!refusal) return false;
    refusal.part = m_nextPart;
    m_pauseCause = PauseCause::History;
    setState(LoopState::Paused, refusal);
    alarm("history-full", refusal);
    return true;
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
            alarm("history", because(NoticeKind::HistoryEndFailed, 0, e.what()));
        }
    }
    setState(LoopState::Idle, notice(NoticeKind::RunComplete, *m_config.lastPartNumber));
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

PointMeasurementRecord LoopEngine::acceptedPoint(std::size_t i, double measuredMm) const {
    return {static_cast<int>(i), m_config.pointZMm[i], measuredMm, m_config.nominalDiameterMm, true, {}, {}};
}

PointMeasurementRecord LoopEngine::rejectedPoint(std::size_t i, std::optional<double> measuredMm,
                                                 const Notice& why) const {
    Notice rejection = why;
    rejection.point = static_cast<int>(i) + 1;
    rejection.zMm = m_config.pointZMm[i];
    // The stored reason keeps its words: "not measured", "rejected: ...", "rejected by the controller: ...".
    const std::string text = describe(rejection);
    const std::string reason = why.kind == NoticeKind::NotMeasured || why.kind == NoticeKind::SkippedByOperator ? text
                               : isControllerRejection(why.kind) ? "rejected by the controller: " + text
                                                                 : "rejected: " + text;
    return {
        static_cast<int>(i), m_config.pointZMm[i], measuredMm, m_config.nominalDiameterMm, false, reason, rejection};
}

void LoopEngine::setState(LoopState state, const Notice& status) {
    const std::string detail = describe(status);
    if (state == m_state && detail == m_detail) return;
    m_state = state;
    m_detail = detail;
    m_status = status;
    notify(makeEvent(LoopEvent::Kind::StateChanged, 0, status));
}

void LoopEngine::alarm(const std::string& kind, const Notice& what, std::optional<std::int64_t> part) {
    const double now = m_ports.clock.nowS();
    // A rejected measurement is stored and shown with its part and point.
    const std::string message = isRejection(what.kind) ? "part " + std::to_string(what.part) + ", point " +
                                                             std::to_string(what.point) + ": " + describe(what)
                                                       : describe(what);
    if (m_ports.history && m_runId) {
        try {
            m_ports.history->recordAlarm(*m_runId, {part, now, kind, message});
        } catch (const std::exception&) {
            // The alarm is still shown; a history that cannot be written faults the loop at the next part.
        }
    }
    LoopEvent event = makeEvent(LoopEvent::Kind::Alarm, part.value_or(0), what);
    event.message = message;
    event.alarmKind = kind;
    notify(std::move(event));
}

void LoopEngine::fault(const Notice& what) {
    setState(LoopState::Fault, what);
    alarm("fault", what);
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
