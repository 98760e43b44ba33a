#include "ui/run/loop_worker.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <stdexcept>

#include "config/loop_scenario.h"
#include "core/control/run_to_run_plant.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_clock.h"
#include "core/loop/loop_engine.h"
#include "core/loop/manual_gauge.h"
#include "core/sim/shaft/lathe_shop.h"
#include "core/sim/statistics/run_to_run_analysis.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "ui/run/lathe_link.h"
#include "ui/tools/database_connection.h"

namespace tt::ui {

namespace {
constexpr int kTickMs = 20;
constexpr int kMaxStepsPerTick = 200;
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
    core::ScaledClock simulatedClock;
    const core::Clock* clock = &simulatedClock;  ///< the loop's time: simulated, or the real lathe's wall clock
    std::unique_ptr<core::LatheShop> shop;       ///< the built-in simulated lathe
    std::shared_ptr<const LathePorts> lathe;     ///< the real lathe's ports
    core::ManualGauge manual;
    std::unique_ptr<core::SelectableGauge> gauge;
    std::unique_ptr<Relay> relay;
    std::unique_ptr<core::LoopEngine> engine;

    core::MachineCycle& machine() {
        return lathe ? static_cast<core::MachineCycle&>(*lathe->machine) : shop->station().machine();
    }
    core::CorrectionOutput& output() {
        return lathe ? static_cast<core::CorrectionOutput&>(*lathe->output) : shop->station().output();
    }
    core::DiameterGauge& automaticGauge() {
        return lathe ? static_cast<core::DiameterGauge&>(*lathe->gauge) : shop->station().gauge();
    }
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
    m_database = openContextDatabase(path);
    m_history = std::make_unique<storage::SqlHistoryStore>(*m_database);
    m_openDatabasePath = path;
}

void LoopWorker::build(Run& run, const RunSettings& settings, std::shared_ptr<const LathePorts> lathe) {
    run.scenario = config::loadLoopScenario(settings.preset, settings.delay);
    if (settings.machine == Machine::RealLathe) {
        if (!lathe) throw std::invalid_argument(tr("the real lathe's devices are not connected").toStdString());
        if (lathe->outputNominalDiameterMm &&
            std::fabs(*lathe->outputNominalDiameterMm - run.scenario.nominalDiameterMm) > 0.0005)
            throw std::invalid_argument(tr("the CNC output “%1” writes programs for a diameter of %2 mm, the set-up "
                                           "%3 turns %4 mm; correct the nominal diameter on the Devices page or "
                                           "choose another set-up")
                                            .arg(lathe->outputName)
                                            .arg(*lathe->outputNominalDiameterMm, 0, 'f', 3)
                                            .arg(settings.preset)
                                            .arg(run.scenario.nominalDiameterMm, 0, 'f', 3)
                                            .toStdString());
        run.lathe = std::move(lathe);
        run.clock = run.lathe->clock.get();
    } else {
        run.simulatedClock.setSpeed(settings.speed);
        run.shop = std::make_unique<core::LatheShop>(run.scenario.shopSpec(settings.seed), run.simulatedClock);
        run.shop->station().setKeptParts(4);
        run.shop->station().setAutomaticGauge(!settings.manualEntry);
    }
    run.gauge = std::make_unique<core::SelectableGauge>(run.automaticGauge(), run.manual);
    run.gauge->setManual(settings.manualEntry);
}

void LoopWorker::start(const RunSettings& settings, std::shared_ptr<const LathePorts> lathe) {
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
        auto run = std::make_unique<Run>();
        build(*run, settings, std::move(lathe));

        const core::ControllerKind kind = core::controllerKindFromName(settings.controller.toStdString());
        const core::RunToRunPlant plant = core::buildRunToRunPlant(run->scenario.control.plant);
        const double ewmaWeight = kind == core::ControllerKind::Ewma && run->scenario.control.ewmaWeightAuto
                                      ? core::bestEwmaWeight(plant, core::defaultEwmaWeightGrid()).weight
                                      : run->scenario.control.ewma.weight;
        const core::LoopConfig loop = run->scenario.loopConfig(kind != core::ControllerKind::Open, std::nullopt);
        run->engine = std::make_unique<core::LoopEngine>(
            loop, core::LoopPorts{run->machine(), run->output(), *run->gauge, *run->clock, m_history.get()},
            core::makeRunToRunController(run->scenario.control, plant, kind, ewmaWeight));
        run->relay = std::make_unique<Relay>(*this);
        run->engine->setListener(run->relay.get());

        QJsonObject settingsJson{
            {QStringLiteral("source"), QStringLiteral("gui")},        {QStringLiteral("preset"), settings.preset},
            {QStringLiteral("controller"), settings.controller},      {QStringLiteral("delay"), run->scenario.delay()},
            {QStringLiteral("seed"), QString::number(settings.seed)}, {QStringLiteral("ewma_weight"), ewmaWeight}};
        if (run->lathe) {
            settingsJson.insert(QStringLiteral("machine"), QStringLiteral("real-lathe"));
            settingsJson.insert(QStringLiteral("cnc_output"), run->lathe->outputName);
            settingsJson.insert(QStringLiteral("gauge"),
                                run->lathe->gaugeName.isEmpty() ? QStringLiteral("by hand") : run->lathe->gaugeName);
        }
        core::RunDescription description{settings.preset.toStdString(),
                                         settings.controller.toStdString(),
                                         run->scenario.delay(),
                                         loop.nominalDiameterMm,
                                         loop.partLengthMm,
                                         loop.pointZMm,
                                         QJsonDocument(settingsJson).toJson(QJsonDocument::Compact).toStdString()};

        RunLayout layout;
        for (double z : loop.pointZMm)
            layout.pointZMm.push_back(z);
        layout.partLengthMm = loop.partLengthMm;
        layout.nominalDiameterMm = loop.nominalDiameterMm;
        layout.plausibleRangeMm = loop.plausibleRangeMm;
        layout.toleranceMm = run->scenario.toleranceMm;
        layout.delay = loop.delayParts;
        layout.controller = settings.controller;
        layout.preset = settings.preset;
        layout.machine = settings.machine;
        if (run->scenario.systematicModel)
            for (double z = 0.0; z <= loop.partLengthMm + 1e-9; z += loop.partLengthMm / 130.0) {
                layout.systematicZMm.push_back(z);
                layout.systematicErrorMm.push_back(run->scenario.systematicModel->value(z));
            }
        m_run = std::move(run);
        emit started(layout);
        m_run->engine->start(description);
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
    if (!m_run || m_run->lathe || !std::isfinite(speed) || speed < 0.0) return;  // the real lathe keeps real time
    m_run->simulatedClock.setSpeed(speed);
}

void LoopWorker::setManualEntry(bool manual) {
    if (!m_run) return;
    if (m_run->lathe && !manual && m_run->gauge->manual()) {
        // Readings the gauge sent while the diameters were typed by hand belong to no point.
        if (const std::size_t dropped = m_run->lathe->gauge->discardPending())
            emit notice(tr("%n gauge reading(s) taken while the diameters were typed by hand were not used.", nullptr,
                           static_cast<int>(dropped)));
    }
    m_run->gauge->setManual(manual);
    if (m_run->shop) m_run->shop->station().setAutomaticGauge(!manual);
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
    const double now = m_run->clock->nowS();
    for (double d : diametersMm)
        m_run->manual.push({d, now});
    tick();
}

void LoopWorker::skipMeasurement() {
    if (m_run) m_run->engine->skipMeasurement();
    tick();
}

void LoopWorker::silenceGauge(double seconds) {
    if (!m_run || !m_run->shop) return;
    const double now = m_run->clock->nowS();
    m_run->shop->station().silenceGauge(now, now + seconds);
    tick();
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
    // Catch up with everything already due (a fast clock can pass several events per tick).
    for (int i = 0; i < kMaxStepsPerTick; ++i) {
        engine.step();
        if (engine.state() == core::LoopState::Idle || engine.state() == core::LoopState::Fault) break;
        if (!m_run->shop || m_run->shop->station().nextEventTimeS() > m_run->clock->nowS()) break;
    }
    publish();
    if (engine.state() == core::LoopState::Idle) m_timer->stop();
}

void LoopWorker::publish() {
    if (!m_run) return;
    const core::LoopEngine& engine = *m_run->engine;
    LoopSnapshot s;
    s.state = engine.state();
    s.detail = QString::fromStdString(engine.detail());
    s.nextPart = engine.nextPartNumber();
    s.partsFinished = engine.partsFinished();
    if (const auto part = engine.partAwaitingMeasurement()) s.awaitingPart = *part;
    s.nextPoint = static_cast<int>(engine.nextMeasuredPoint().value_or(0));
    s.manualEntry = m_run->gauge->manual();
    s.realLathe = m_run->lathe != nullptr;
    s.simulatedS = m_run->clock->nowS();
    s.gauge = m_run->gauge->health();
    s.cnc = m_run->output().health();
    if (const auto id = engine.runId()) s.runId = *id;
    const bool changed = s.state != m_last.state || s.detail != m_last.detail || s.nextPart != m_last.nextPart ||
                         s.partsFinished != m_last.partsFinished || s.awaitingPart != m_last.awaitingPart ||
                         s.nextPoint != m_last.nextPoint || s.manualEntry != m_last.manualEntry ||
                         s.gauge.state != m_last.gauge.state || s.cnc.state != m_last.cnc.state ||
                         s.gauge.message != m_last.gauge.message || s.cnc.message != m_last.cnc.message ||
                         std::floor(s.simulatedS / 60.0) != std::floor(m_last.simulatedS / 60.0);
    m_last = s;
    if (changed) emit snapshot(s);
}

void LoopWorker::onEvent(const core::LoopEvent& event) {
    emit loopEvent(event);
    if (event.kind == core::LoopEvent::Kind::PartFinished && m_run && m_run->shop) {
        const auto& parts = m_run->shop->station().machinedParts();
        if (!parts.empty() && parts.back().partNumber == event.partNumber) {
            const core::TurnedPart& part = parts.back();
            QVector<double> z, error;
            for (std::size_t i = 0; i < part.zMm.size(); ++i) {
                z.push_back(part.zMm[i]);
                error.push_back(part.diameterMm[i] - m_run->shop->process().nominalDiameterMm());
            }
            emit partProfile(event.partNumber, z, error);
        }
    }
    if (event.kind == core::LoopEvent::Kind::PartMeasured && m_run && m_run->shop)
        m_run->shop->station().forgetPart(event.partNumber);
}

}  // namespace tt::ui
