#include "ui/run/loop_worker.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <stdexcept>

#include "config/loop_scenario.h"
#include "core/loop/loop_engine.h"
#include "core/loop/manual_gauge.h"
#include "core/run/shaft_run_builder.h"
#include "core/storage/data_stores.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "ui/log_categories.h"
#include "ui/run/interrupted_run.h"

namespace tt::ui {

namespace {
constexpr int kTickMs = 20;
constexpr int kMaxStepsPerTick = 200;
/// Points of the systematic model d(x) the profile plot draws.
constexpr int kModelSamples = 130;
/// Parts over which the difference between the old and the new controller's correction fades out when a new
/// tuning is applied during a run (docs/DECISIONS.md).
constexpr int kTuningTransferParts = 10;
}  // namespace

namespace {
/// The scenario's controller part tuned as the Controller page applied it (core::withControllerTuning).
void tuneScenario(config::LoopScenario& scenario, const core::RunToRunSetup& tuning) {
    static_cast<core::ShaftScenario&>(scenario) = core::withControllerTuning(scenario, tuning);
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

/// Everything one run is made of, in the order it must be built and torn down.
struct LoopWorker::Run {
    config::LoopScenario scenario;
    core::ShaftRunPlan plan;
    std::shared_ptr<core::ShaftMachine> machine;
    core::ManualGauge manual;
    std::unique_ptr<core::SelectableGauge> gauge;
    std::unique_ptr<Relay> relay;
    std::unique_ptr<core::LoopEngine> engine;
};

LoopWorker::LoopWorker() {
    m_timer = new QTimer(this);
    m_timer->setInterval(kTickMs);
    connect(m_timer, &QTimer::timeout, this, &LoopWorker::tick);
}

LoopWorker::~LoopWorker() = default;

void LoopWorker::openHistory(const QString& path) {
    if (path.isEmpty()) {
        m_history.reset();
        m_database.reset();
        m_openDatabasePath.clear();
        return;
    }
    if (m_history && path == m_openDatabasePath) return;
    m_history.reset();
    m_database.reset();
    m_database = std::make_unique<storage::Database>(storage::DataStores(path).config());
    m_history = std::make_unique<storage::SqlHistoryStore>(*m_database);
    m_openDatabasePath = path;
}

std::unique_ptr<LoopWorker::Run> LoopWorker::build(const RunSettings& settings, const MachineMaker& makeMachine) {
    auto run = std::make_unique<Run>();
    run->scenario = config::loadLoopScenario(settings.preset, settings.delay);
    if (settings.tuning) tuneScenario(run->scenario, *settings.tuning);
    run->scenario.pauseOnScrap = run->scenario.pauseOnScrap || settings.pauseOnScrap;
    run->plan = core::planShaftRun(run->scenario, {core::controllerKindFromName(settings.controller.toStdString()),
                                                   settings.ewmaWeight, settings.lastPartNumber});
    run->machine = makeMachine(run->scenario);
    run->machine->setManualEntry(settings.manualEntry);
    run->gauge = std::make_unique<core::SelectableGauge>(run->machine->gauge(), run->manual);
    run->gauge->setManual(settings.manualEntry);
    run->engine = core::buildShaftRun(run->scenario, run->plan, *run->machine, m_history.get(), run->gauge.get());
    run->relay = std::make_unique<Relay>(*this);
    run->engine->setListener(run->relay.get());
    return run;
}

RunLayout LoopWorker::layoutOf(const Run& run, const RunSettings& settings) const {
    const core::LoopConfig& loop = run.plan.loop;
    RunLayout layout;
    for (double z : loop.pointZMm)
        layout.pointZMm.push_back(z);
    layout.partLengthMm = loop.partLengthMm;
    layout.nominalDiameterMm = loop.nominalDiameterMm;
    layout.plausibleRangeMm = loop.plausibleRangeMm;
    layout.toleranceMm = run.scenario.toleranceMm;
    layout.delay = loop.delayParts;
    layout.controller = settings.controller;
    layout.preset = settings.preset;
    layout.machineName = settings.machineName;
    layout.operatorCycle = settings.operatorCycle;
    layout.adjustableSpeed = run.machine->speedAdjustable();
    if (run.scenario.systematicModel)
        for (int i = 0; i <= kModelSamples; ++i) {
            const double z = loop.partLengthMm * i / kModelSamples;
            layout.systematicZMm.push_back(z);
            layout.systematicErrorMm.push_back(run.scenario.systematicModel->value(z));
        }
    return layout;
}

void LoopWorker::start(const RunSettings& settings, MachineMaker makeMachine) {
    begin(settings, makeMachine, std::nullopt);
}

void LoopWorker::resume(const RunSettings& settings, qint64 runId, MachineMaker makeMachine) {
    begin(settings, makeMachine, runId);
}

void LoopWorker::begin(const RunSettings& settings, const MachineMaker& makeMachine,
                       std::optional<qint64> resumeRunId) {
    m_tuningPending = false;
    if (m_run && m_run->engine->state() != core::LoopState::Idle) {
        emit startFailed(tr("A run is already going; stop it first."));
        return;
    }
    try {
        openHistory(settings.databasePath);
    } catch (const std::exception& e) {
        emit startFailed(tr("The run history cannot be opened: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    try {
        std::unique_ptr<Run> run = build(settings, makeMachine);
        const RunLayout layout = layoutOf(*run, settings);
        m_run = std::move(run);
        qCInfo(lcLoop).noquote() << "run started:" << settings.preset << settings.controller << "z =" << layout.delay
                                 << "on" << settings.machineName;
        if (resumeRunId) {
            const std::optional<core::ResumePoint> point =
                m_history ? m_history->resumePoint(*resumeRunId) : std::nullopt;
            if (!point)
                throw std::runtime_error("run " + std::to_string(*resumeRunId) + " has no part to continue from");
            emit started(layout);
            core::resumeShaftRun(*m_run->engine, *m_run->machine, m_run->plan.loop, *point);
            qCInfo(lcLoop).noquote() << "run" << *resumeRunId << "resumed from part" << point->lastPartNumber + 1;
        } else {
            emit started(layout);
            m_run->engine->start(storedRunDescription(settings, m_run->plan));
        }
    } catch (const core::OutputDiameterMismatch& e) {
        m_run.reset();
        emit startFailed(tr("The run cannot start: the CNC output “%1” writes programs for a diameter of %2 mm, the "
                            "set-up %3 turns %4 mm; correct the nominal diameter on the Devices page or choose "
                            "another set-up")
                             .arg(settings.outputName)
                             .arg(e.outputMm, 0, 'f', 3)
                             .arg(settings.preset)
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
    if (m_run && std::isfinite(speed) && speed >= 0.0) m_run->machine->setSpeed(speed);
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

void LoopWorker::applyTuning(const core::RunToRunSetup& tuning) {
    if (!m_run || m_run->engine->state() == core::LoopState::Idle) return;
    try {
        m_run->engine->replaceController(core::retunedShaftController(m_run->scenario, m_run->plan, tuning),
                                         kTuningTransferParts);
        tuneScenario(m_run->scenario, tuning);
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
    m_database.reset();
}

void LoopWorker::tick() {
    if (!m_run) return;
    core::LoopEngine& engine = *m_run->engine;
    const core::ShaftMachine& machine = *m_run->machine;
    // Catch up with everything already due (a fast clock can pass several events per tick).
    for (int i = 0; i < kMaxStepsPerTick; ++i) {
        engine.step();
        if (engine.state() == core::LoopState::Idle || engine.state() == core::LoopState::Fault) break;
        if (!(machine.nextEventTimeS() <= machine.clock().nowS())) break;
    }
    publish();
    if (engine.state() == core::LoopState::Idle) m_timer->stop();
}

void LoopWorker::publish() {
    if (!m_run) return;
    const core::LoopEngine& engine = *m_run->engine;
    LoopSnapshot s;
    s.state = engine.state();
    s.status = engine.status();
    s.nextPart = engine.nextPartNumber();
    s.partsFinished = engine.partsFinished();
    if (const auto part = engine.partAwaitingMeasurement()) s.awaitingPart = *part;
    s.nextPoint = static_cast<int>(engine.nextMeasuredPoint().value_or(0));
    s.manualEntry = m_run->gauge->manual();
    s.machineS = m_run->machine->clock().nowS();
    s.gauge = m_run->gauge->health();
    s.cnc = m_run->machine->output().health();
    if (const auto id = engine.runId()) s.runId = *id;
    const bool changed = s.state != m_last.state || engine.detail() != m_lastDetail || s.nextPart != m_last.nextPart ||
                         s.partsFinished != m_last.partsFinished || s.awaitingPart != m_last.awaitingPart ||
                         s.nextPoint != m_last.nextPoint || s.manualEntry != m_last.manualEntry ||
                         s.gauge.state != m_last.gauge.state || s.cnc.state != m_last.cnc.state ||
                         s.gauge.message != m_last.gauge.message || s.cnc.message != m_last.cnc.message ||
                         std::floor(s.machineS / 60.0) != std::floor(m_last.machineS / 60.0);
    m_last = s;
    m_lastDetail = engine.detail();
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

}  // namespace tt::ui
