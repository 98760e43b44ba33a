#pragma once

#include <QObject>
#include <QThread>
#include <QVector>
#include <memory>

#include "core/loop/loop_events.h"
#include "runtime/run/loop_snapshot.h"
#include "runtime/run/loop_worker.h"

namespace tt::runtime {

/// The GUI thread's handle on the closed loop: starts the loop thread with its worker, forwards the
/// operator's commands to it (queued, never blocking) and its reports back as signals. Destroying the
/// session stops the run and waits for the thread (the device thread never waits for either).
class RunSession : public QObject {
    Q_OBJECT
public:
    explicit RunSession(QObject* parent = nullptr);
    ~RunSession() override;

    /// Starts a run (LoopWorker::start; the machine is made in the loop's thread).
    void start(const RunStart& run);
    /// Continues the stored run `runId` (LoopWorker::resume).
    void resume(const RunStart& run, qint64 runId);
    void pause();
    void continueRun();
    void stop();
    void setSpeed(double speed);
    void setManualEntry(bool manual);
    void submitDiameters(qint64 partNumber, const QVector<double>& diametersMm);
    void skipMeasurement();
    void silenceGauge(double seconds);
    /// The operator confirms the part on the machine is finished (LoopWorker::confirmPartFinished).
    void confirmPartFinished();
    /// Hands a newly applied controller tuning to the running loop (LoopWorker::applyTuning).
    void applyTuning(const core::RunToRunSetup& tuning);

    /// The thread the loop runs in (never the GUI thread).
    QThread* loopThread() { return &m_thread; }
    /// The latest snapshot received (Idle before the first run).
    const LoopSnapshot& snapshot() const { return m_snapshot; }

signals:
    void started(const tt::runtime::RunLayout& layout);
    void startFailed(const QString& reason);
    void snapshotChanged(const tt::runtime::LoopSnapshot& snapshot);
    void loopEvent(const tt::core::LoopEvent& event);
    void partProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm);
    void notice(const QString& text);
    /// The running loop's controller was replaced by the applied tuning from part `partNumber` on.
    void tuningTaken(qint64 partNumber);
    /// The plant database's forwarder changed state (runs stored in a plant database through this terminal's
    /// journal): online or offline since when, and the parts kept on this terminal.
    void plantStatus(const tt::storage::ForwarderStatus& status);
    /// The machine reported a problem, stored as an alarm of the run (LoopWorker::machineIncident).
    void machineIncident(const QString& text);

private:
    QThread m_thread;
    LoopWorker* m_worker = nullptr;
    LoopSnapshot m_snapshot;
};

}  // namespace tt::runtime
