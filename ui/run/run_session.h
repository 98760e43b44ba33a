#pragma once

#include <QObject>
#include <QThread>
#include <QVector>
#include <memory>

#include "core/loop/loop_events.h"
#include "ui/run/loop_worker.h"
#include "ui/run/run_settings.h"

namespace tt::ui {

/// The GUI thread's handle on the closed loop: starts the loop thread with its worker, forwards the
/// operator's commands to it (queued, never blocking) and its reports back as signals. Destroying the
/// session stops the run and waits for the thread; whoever joins the machine to devices in this thread
/// (LatheLink) releases a write that waits for them first, so the two threads never wait for each other.
class RunSession : public QObject {
    Q_OBJECT
public:
    explicit RunSession(QObject* parent = nullptr);
    ~RunSession() override;

    /// Starts a run on the machine `makeMachine` makes (in the loop's thread).
    void start(const RunSettings& settings, MachineMaker makeMachine);
    /// Continues the stored run `runId` (LoopWorker::resume).
    void resume(const RunSettings& settings, qint64 runId, MachineMaker makeMachine);
    void pause();
    void continueRun();
    void stop();
    void setSpeed(double speed);
    void setManualEntry(bool manual);
    void submitDiameters(qint64 partNumber, const QVector<double>& diametersMm);
    void skipMeasurement();
    void silenceGauge(double seconds);
    /// Hands a newly applied controller tuning to the running loop (LoopWorker::applyTuning).
    void applyTuning(const core::RunToRunSetup& tuning);

    /// The thread the loop runs in (never the GUI thread).
    QThread* loopThread() { return &m_thread; }
    /// The latest snapshot received (Idle before the first run).
    const LoopSnapshot& snapshot() const { return m_snapshot; }

signals:
    void started(const tt::ui::RunLayout& layout);
    void startFailed(const QString& reason);
    void snapshotChanged(const tt::ui::LoopSnapshot& snapshot);
    void loopEvent(const tt::core::LoopEvent& event);
    void partProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm);
    void notice(const QString& text);
    /// The running loop's controller was replaced by the applied tuning from part `partNumber` on.
    void tuningTaken(qint64 partNumber);

private:
    QThread m_thread;
    LoopWorker* m_worker = nullptr;
    LoopSnapshot m_snapshot;
};

}  // namespace tt::ui
