#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QVector>
#include <memory>
#include <optional>

#include "core/control/run_to_run_setup.h"
#include "core/loop/loop_events.h"
#include "core/loop/shaft_run_stepper.h"
#include "runtime/history/terminal_history.h"
#include "runtime/run/loop_snapshot.h"
#include "runtime/run/machine_catalog.h"
#include "runtime/run/run_request.h"

Q_DECLARE_METATYPE(tt::core::LoopEvent)

namespace tt::storage {
class Database;
class SqlHistoryStore;
}  // namespace tt::storage

namespace tt::runtime {

struct AssembledRun;

/// A run to start (or continue): its request, the machine as the page named it, what the machine can do, and
/// what makes it in the loop's thread.
struct RunStart {
    RunRequest request;
    QString machineName;
    QString outputName;  ///< the CNC output as the Devices page names it (machines assembled from devices)
    MachineCapabilities can;
    MachineMaker make;
};

/// The closed loop in its own thread: owns the assembled run (runtime/run/shaft_run_assembly.h: its machine,
/// the engine and the stepper) and the history connection (QtSql: used only from this thread), and drives the
/// engine from a timer through the run's one stepper (core::ShaftRunStepper), pacing a machine in simulated
/// time by the wall clock at the chosen speed, so the window never waits for it and a paced run machines the
/// same parts as a headless one. Every call comes through queued slots; everything it learns goes out through
/// signals (queued to the GUI thread).
class LoopWorker : public QObject {
    Q_OBJECT
public:
    LoopWorker();
    ~LoopWorker() override;

    /// Steps per timer tick at most (a fast pace catches up with everything due).
    static constexpr int kMaxStepsPerTick = 200;
    /// The timer's period, ms.
    static constexpr int kTickMs = 20;

public slots:
    /// Assembles and starts a run; failures (bad request, history that cannot be opened, a CNC output set up
    /// for another diameter) are reported through startFailed and nothing starts.
    void start(const tt::runtime::RunStart& run);
    /// Continues the stored run `runId` of the request's history with the request (its stored one): its
    /// controller state, its parts still waiting for the gauge; failures through startFailed.
    void resume(const tt::runtime::RunStart& run, qint64 runId);
    void pause();
    void continueRun();
    void stop();
    /// Machine s per wall s for a machine in simulated time (0: as fast as possible).
    void setSpeed(double speed);
    /// Diameters come by hand (true) or from the gauge (false).
    void setManualEntry(bool manual);
    /// The diameters of part `partNumber` at the control points, typed in by the operator (mm).
    void submitDiameters(qint64 partNumber, const QVector<double>& diametersMm);
    /// The oldest part waiting for its diameters is recorded as not measured.
    void skipMeasurement();
    /// The gauge stops answering for `seconds` of the machine's time (a machine with that fault switch).
    void silenceGauge(double seconds);
    /// The operator confirms the part on the machine is finished (machines whose cycle the operator runs).
    void confirmPartFinished();
    /// A new controller tuning (the Controller page's Apply): the running loop takes it over at its next part,
    /// bumplessly (LoopEngine::replaceController over kTuningTransferParts parts); with no run going nothing
    /// happens. A tuning that does not fit the run is refused through notice.
    void applyTuning(const tt::core::RunToRunSetup& tuning);
    /// Stops the timer and drops the run (before the thread ends).
    void shutdown();

signals:
    void started(const tt::runtime::RunLayout& layout);
    void startFailed(const QString& reason);
    void snapshot(const tt::runtime::LoopSnapshot& snapshot);
    void loopEvent(const tt::core::LoopEvent& event);
    /// The true profile of a part as it came off the machine (diameter error, mm; machines that know it).
    void partProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm);
    /// The controller of the running loop was replaced by the applied tuning from part `partNumber` on.
    void tuningTaken(qint64 partNumber);
    /// A command was not taken (wrong part, no run), in plain words.
    void notice(const QString& text);
    /// The plant database's forwarder changed state (only with a plant database): online, offline since,
    /// the parts kept on this terminal.
    void plantStatus(const tt::storage::ForwarderStatus& status);
    /// The machine reported a problem (a real CNC unreachable, a write refused), stored as an alarm of the run.
    void machineIncident(const QString& text);

private:
    class Relay;

    void begin(const RunStart& start, std::optional<qint64> resumeRunId);
    void launch(const RunStart& start, std::optional<qint64> resumeRunId);
    void tick();
    /// Stores the machine's incidents as alarms of the run and reports them (machineIncident).
    void recordIncidents();
    double wallS() const;
    void publish();
    LoopSnapshot snapshotNow() const;
    void onEvent(const core::LoopEvent& event);
    /// Opens the history `path` (an SQLite file, or a plant database through this terminal's journal and its
    /// forwarder) unless it is open; throws TerminalHistoryError.
    void openHistory(const QString& path);
    core::HistoryStore* history() const;
    RunLayout layoutOf(const RunStart& start) const;

    QTimer* m_timer = nullptr;
    QElapsedTimer m_wall;
    std::unique_ptr<AssembledRun> m_run;
    std::unique_ptr<Relay> m_relay;
    std::optional<core::WallPace> m_pace;
    LoopSnapshot m_last;
    std::string m_lastDetail;      ///< the engine's status as last published
    bool m_tuningPending = false;  ///< a replaced controller waits for the next part
    std::unique_ptr<TerminalHistory> m_history;
};

}  // namespace tt::runtime

Q_DECLARE_METATYPE(tt::runtime::RunStart)
