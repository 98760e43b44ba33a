#include "runtime/run/loop_worker.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/loop/loop_engine.h"
#include "core/storage/data_stores.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "runtime/log_categories.h"
#include "runtime/run/shaft_run_assembly.h"

namespace tt::runtime {

namespace {
/// Points of the systematic model d(x) the profile plot draws.
constexpr int kModelSamples = 130;
/// Parts over which the difference between the old and the new controller's correction fades out when a new
/// tuning is applied during a run (docs/DECISIONS.md).
constexpr int kTuningTransferParts = 10;

/// The part the engine waits longest for, its next point and what the machine has on it, as the page shows.
void addProgress(LoopSnapshot& s, const core::LoopEngine& engine, const core::ShaftMachine& machine) {
    if (const auto part = engine.partAwaitingMeasurement()) s.awaitingPart = *part;
    s.nextPoint = static_cast<int>(engine.nextMeasuredPoint().value_or(0));
    if (const auto onMachine = machine.partOnMachine()) s.partOnMachine = *onMachine;
}

bool sameSnapshot(const LoopSnapshot& a, const LoopSnapshot& b) {
    return a.state == b.state && a.nextPart == b.nextPart && a.partsFinished == b.partsFinished &&
           a.awaitingPart == b.awaitingPart && a.nextPoint == b.nextPoint && a.manualEntry == b.manualEntry &&
           a.partOnMachine == b.partOnMachine && a.gauge.state == b.gauge.state && a.cnc.state == b.cnc.state &&
           a.gauge.message == b.gauge.message && a.cnc.message == b.cnc.message &&
           std::floor(a.machineS / 60.0) == std::floor(b.machineS / 60.0);
}
}  // namespace

/// Passes the engine's events (on this thread) to the worker.
class LoopWorker::Relay final : public core::LoopListener {
public:
    explicit Relay(LoopWorker& worker) : m_worker(worker) {}
    void onLoopEvent(const core::LoopEvent& event) override { m_worker.onEvent(event); }

private:
    LoopWorker& m_worker;
};

LoopWorker::LoopWorker() : m_relay(std::make_unique<Relay>(*this)) {
    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, &LoopWorker::tick);
    m_wall.start();
}

LoopWorker::~LoopWorker() = default;

double LoopWorker::wallS() const {
    return static_cast<double>(m_wall.nsecsElapsed()) * 1e-9;
}

void LoopWorker::openHistory(const QString& path) {
    if (path.isEmpty()) {
        m_history.reset();
        return;
    }
    if (m_history && path == m_history->location()) return;
    m_history.reset();
    TerminalHistoryOptions options;
    options.location = path;
    options.machine = terminalMachineName();
    options.journalLimitBytes = storage::journalLimitFromSettings();
    m_history = std::make_unique<TerminalHistory>(options);
    if (storage::PlantForwarderThread* forwarder = m_history->forwarder())
        connect(forwarder, &storage::PlantForwarderThread::statusChanged, this, &LoopWorker::plantStatus,
                Qt::QueuedConnection);
    m_history->startForwarding();
}

core::HistoryStore* LoopWorker::history() const {
    return m_history ? &m_history->store() : nullptr;
}

RunLayout LoopWorker::layoutOf(const RunStart& start) const {
    const core::LoopConfig& loop = m_run->plan.loop;
    RunLayout layout;
    for (double z : loop.pointZMm)
        layout.pointZMm.push_back(z);
    layout.partLengthMm = loop.partLengthMm;
    layout.nominalDiameterMm = loop.nominalDiameterMm;
    layout.plausibleRangeMm = loop.plausibleRangeMm;
    layout.toleranceMm = m_run->scenario.toleranceMm;
    layout.delay = loop.delayParts;
    layout.controller = QString::fromStdString(core::controllerKindName(start.request.controller));
    layout.preset = start.request.preset;
    layout.machineName = start.machineName;
    layout.partsConfirmedByOperator = start.can.partsConfirmedByOperator;
    layout.adjustableSpeed = m_run->stepper->simulatedTime();
    if (const auto& model = m_run->scenario.systematicModel)
        for (int i = 0; i <= kModelSamples; ++i) {
            const double z = loop.partLengthMm * i / kModelSamples;
            layout.systematicZMm.push_back(z);
            layout.systematicErrorMm.push_back(model->value(z));
        }
    return layout;
}

void LoopWorker::start(const RunStart& run) {
    begin(run, std::nullopt);
}

void LoopWorker::resume(const RunStart& run, qint64 runId) {
    begin(run, runId);
}

void LoopWorker::begin(const RunStart& start, std::optional<qint64> resumeRunId) {
    m_tuningPending = false;
    if (m_run && m_run->engine->state() != core::LoopState::Idle) {
        emit startFailed(tr("A run is already going; stop it first."));
        return;
    }
    try {
        openHistory(start.request.database);
    } catch (const std::exception& e) {
        emit startFailed(tr("The run history cannot be opened: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    try {
        launch(start, resumeRunId);
    } catch (const core::OutputDiameterMismatch& e) {
        m_run.reset();
        emit startFailed(tr("The run cannot start: the CNC output “%1” writes programs for a diameter of %2 mm, the "
                            "set-up %3 turns %4 mm; correct the nominal diameter on the Devices page or choose "
                            "another set-up")
                             .arg(start.outputName)
                             .arg(e.outputMm, 0, 'f', 3)
                             .arg(start.request.preset)
                             .arg(e.scenarioMm, 0, 'f', 3));
        return;
    } catch (const std::exception& e) {
        m_run.reset();
        emit startFailed(tr("The run cannot start: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    m_timer->start();
    tick();
}

void LoopWorker::launch(const RunStart& start, std::optional<qint64> resumeRunId) {
    m_run = assembleRun(start.request, start.make, history());
    m_run->engine->setListener(m_relay.get());
    m_pace.emplace(m_run->machine->clock().nowS(), wallS(), start.request.speed);
    qCInfo(lcLoop).noquote() << "run started:" << start.request.preset
                             << QString::fromStdString(core::controllerKindName(start.request.controller))
                             << "z =" << m_run->plan.loop.delayParts << "on" << start.machineName;
    if (!resumeRunId) {
        emit started(layoutOf(start));
        startRun(*m_run);
        return;
    }
    const std::optional<core::ResumePoint> point = m_history ? history()->resumePoint(*resumeRunId) : std::nullopt;
    if (!point) throw std::runtime_error("run " + std::to_string(*resumeRunId) + " has no part to continue from");
    emit started(layoutOf(start));
    resumeRun(*m_run, *point, history()->parts(*resumeRunId));
    m_pace.emplace(m_run->machine->clock().nowS(), wallS(), start.request.speed);
    qCInfo(lcLoop).noquote() << "run" << *resumeRunId << "resumed from part" << point->lastPartNumber + 1;
}

void LoopWorker::pause() {
    if (m_run) m_run->engine->pause();
    publish();
}

void LoopWorker::continueRun() {
    if (m_run) m_run->engine->continueRun();
    tick();
}

void LoopWorker::stop() {
    if (m_run) m_run->engine->stop();
    publish();
    m_timer->stop();
}

void LoopWorker::setSpeed(double speed) {
    if (m_pace && std::isfinite(speed) && speed >= 0.0) m_pace->setSpeed(speed, wallS());
}

void LoopWorker::setManualEntry(bool manual) {
    if (!m_run) return;
    if (const std::size_t dropped = m_run->machine->setManualEntry(manual))
        emit notice(tr("%n gauge reading(s) taken while the diameters were typed by hand were not used.", nullptr,
                       static_cast<int>(dropped)));
    m_run->gauge->setManual(manual);
    publish();
}

void LoopWorker::submitDiameters(qint64 partNumber, const QVector<double>& diametersMm) {
    if (!m_run) {
        emit notice(tr("No run is going: the diameters were not taken."));
        return;
    }
    const auto awaiting = m_run->engine->partAwaitingMeasurement();
    if (!awaiting || *awaiting != partNumber || m_run->engine->nextMeasuredPoint() != std::optional<std::size_t>(0)) {
        emit notice(tr("Part %1 is not the part waiting for its diameters; nothing was taken.").arg(partNumber));
        return;
    }
    const double now = m_run->machine->clock().nowS();
    for (double d : diametersMm)
        m_run->manual.push({d, now});
    tick();
}

void LoopWorker::skipMeasurement() {
    if (m_run) m_run->engine->skipMeasurement();
    tick();
}

void LoopWorker::silenceGauge(double seconds) {
    if (m_run && m_run->machine->silenceGauge(seconds)) tick();
}

void LoopWorker::confirmPartFinished() {
    if (!m_run) return;
    if (!m_run->machine->confirmPartFinished()) emit notice(tr("No part is on the machine."));
    tick();
}

void LoopWorker::applyTuning(const core::RunToRunSetup& tuning) {
    if (!m_run || m_run->engine->state() == core::LoopState::Idle) return;
    try {
        m_run->engine->replaceController(core::retunedShaftController(m_run->scenario, m_run->plan, tuning),
                                         kTuningTransferParts);
        static_cast<core::ShaftScenario&>(m_run->scenario) = core::withControllerTuning(m_run->scenario, tuning);
        m_tuningPending = true;
    } catch (const std::exception& e) {
        emit notice(tr("The new controller tuning was not taken: %1").arg(QString::fromStdString(e.what())));
    }
}

void LoopWorker::shutdown() {
    m_timer->stop();
    if (m_run && m_run->engine->state() != core::LoopState::Idle) m_run->engine->stop();
    m_run.reset();
    m_history.reset();
}

void LoopWorker::tick() {
    if (!m_run) return;
    // Speed 0: as fast as the timer lets it (kMaxStepsPerTick events a tick).
    const double until =
        m_pace && m_pace->speed() > 0.0 ? m_pace->machineAt(wallS()) : std::numeric_limits<double>::infinity();
    m_run->stepper->advanceTo(until, kMaxStepsPerTick);
    recordIncidents();
    publish();
    if (m_run->engine->state() == core::LoopState::Idle) m_timer->stop();
}

void LoopWorker::recordIncidents() {
    for (const std::string& incident : m_run->machine->takeIncidents()) {
        const core::LoopEngine& engine = *m_run->engine;
        if (core::HistoryStore* store = history(); store && engine.runId())
            store->recordAlarm(*engine.runId(),
                               {engine.partAwaitingMeasurement(), m_run->machine->clock().nowS(), "machine", incident});
        qCWarning(lcLoop).noquote() << "machine:" << QString::fromStdString(incident);
        emit machineIncident(QString::fromStdString(incident));
    }
}

LoopSnapshot LoopWorker::snapshotNow() const {
    const core::LoopEngine& engine = *m_run->engine;
    LoopSnapshot s;
    s.state = engine.state();
    s.status = engine.status();
    s.nextPart = engine.nextPartNumber();
    s.partsFinished = engine.partsFinished();
    addProgress(s, engine, *m_run->machine);
    s.manualEntry = m_run->gauge->manual();
    s.machineS = m_run->machine->clock().nowS();
    s.gauge = m_run->gauge->health();
    s.cnc = m_run->machine->output().health();
    if (const auto id = engine.runId()) s.runId = *id;
    return s;
}

void LoopWorker::publish() {
    if (!m_run) return;
    const LoopSnapshot s = snapshotNow();
    const bool changed = m_run->engine->detail() != m_lastDetail || !sameSnapshot(s, m_last);
    m_last = s;
    m_lastDetail = m_run->engine->detail();
    if (changed) emit snapshot(s);
}

void LoopWorker::onEvent(const core::LoopEvent& event) {
    if (event.kind == core::LoopEvent::Kind::Alarm)
        qCWarning(lcLoop).noquote() << QString::fromStdString(event.alarmKind) << QString::fromStdString(event.message);
    if (event.kind == core::LoopEvent::Kind::StateChanged)
        qCInfo(lcLoop).noquote() << core::toString(event.state).data() << "-" << QString::fromStdString(event.message);
    emit loopEvent(event);
    if (!m_run) return;
    if (event.kind == core::LoopEvent::Kind::PartStarted && m_tuningPending) {
        m_tuningPending = false;
        emit tuningTaken(event.partNumber);
    }
    if (event.kind == core::LoopEvent::Kind::PartFinished)
        if (const auto profile = m_run->machine->trueProfile(event.partNumber))
            emit partProfile(event.partNumber, QVector<double>(profile->zMm.begin(), profile->zMm.end()),
                             QVector<double>(profile->errorMm.begin(), profile->errorMm.end()));
    if (event.kind == core::LoopEvent::Kind::PartMeasured) m_run->machine->partMeasured(event.partNumber);
}

}  // namespace tt::runtime
