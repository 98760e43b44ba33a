#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <QVector>
#include <memory>

#include "core/loop/loop_events.h"
#include "ui/run/run_settings.h"

Q_DECLARE_METATYPE(tt::core::LoopEvent)

namespace tt::storage {
class Database;
class SqlHistoryStore;
}  // namespace tt::storage

namespace tt::ui {

/// The closed loop in its own thread: owns the run's machine (core::ShaftMachine: whatever the page chose,
/// made in this thread by the MachineMaker), the engine the run builder assembled on it
/// (core/run/shaft_run_builder.h) and the history connection (QtSql: used only from this thread), and steps
/// the engine from a timer so the window never waits for it. Every call comes through queued slots;
/// everything it learns goes out through signals (queued to the GUI thread).
class LoopWorker : public QObject {
    Q_OBJECT
public:
    LoopWorker();
    ~LoopWorker() override;

public slots:
    /// Sets up and starts a run on the machine `makeMachine` makes for the scenario; failures (bad preset,
    /// history that cannot be opened, a CNC output set up for another diameter) are reported through
    /// startFailed and nothing starts.
    void start(const tt::ui::RunSettings& settings, tt::ui::MachineMaker makeMachine);
    /// Continues the stored run `runId` of the history `settings.databasePath` on the machine `makeMachine`
    /// makes, set up with the run's stored settings (core::resumeShaftRun: its controller state, its parts
    /// still waiting for the gauge); failures through startFailed.
    void resume(const tt::ui::RunSettings& settings, qint64 runId, tt::ui::MachineMaker makeMachine);
    void pause();
    void continueRun();
    void stop();
    void setSpeed(double speed);
    /// Diameters come by hand (true) or from the gauge (false).
    void setManualEntry(bool manual);
    /// The diameters of part `partNumber` at the control points, typed in by the operator (mm).
    void submitDiameters(qint64 partNumber, const QVector<double>& diametersMm);
    /// The oldest part waiting for its diameters is recorded as not measured.
    void skipMeasurement();
    /// The gauge stops answering for `seconds` of the machine's time (a machine with that fault switch).
    void silenceGauge(double seconds);
    /// A new controller tuning (the Controller page's Apply): the running loop takes it over at its next part,
    /// bumplessly (LoopEngine::replaceController over kTuningTransferParts parts); with no run going nothing
    /// happens (the page passes the tuning with the next start). A tuning that does not fit the run is
    /// refused through notice.
    void applyTuning(const tt::core::RunToRunSetup& tuning);
    /// Stops the timer and drops the run (before the thread ends).
    void shutdown();

signals:
    void started(const tt::ui::RunLayout& layout);
    void startFailed(const QString& reason);
    void snapshot(const tt::ui::LoopSnapshot& snapshot);
    void loopEvent(const tt::core::LoopEvent& event);
    /// The true profile of a part as it came off the machine (diameter error, mm; machines that know it).
    void partProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm);
    /// The controller of the running loop was replaced by the applied tuning from part `partNumber` on.
    void tuningTaken(qint64 partNumber);
    /// A manual entry was not taken (wrong part, no run), in plain words.
    void notice(const QString& text);

private:
    struct Run;
    class Relay;

    void begin(const RunSettings& settings, const MachineMaker& makeMachine, std::optional<qint64> resumeRunId);
    void tick();
    void publish();
    void onEvent(const core::LoopEvent& event);
    void openHistory(const QString& path);
    std::unique_ptr<Run> build(const RunSettings& settings, const MachineMaker& makeMachine);
    RunLayout layoutOf(const Run& run, const RunSettings& settings) const;

    QTimer* m_timer = nullptr;
    std::unique_ptr<Run> m_run;
    LoopSnapshot m_last;
    std::string m_lastDetail;  ///< the engine's status as last published
    QString m_openDatabasePath;
    bool m_tuningPending = false;  ///< a replaced controller waits for the next part
    std::unique_ptr<storage::Database> m_database;
    std::unique_ptr<storage::SqlHistoryStore> m_history;
};

}  // namespace tt::ui
