#pragma once

#include <QObject>
#include <QThread>
#include <QVector>
#include <memory>
#include <vector>

#include "core/run/boring_run.h"
#include "runtime/boring/compensation_worker.h"

namespace tt::runtime {

/// The GUI thread's handle on the in-process compensation: the thread with its worker
/// (CompensationWorker), the operator's commands passed on as queued calls (never waiting), the
/// cycles passed back as signals. A stopped run's late cycles are dropped, so after stop() nothing
/// of it arrives. Destroying the session stops the run and waits for the thread.
class CompensationSession : public QObject {
    Q_OBJECT
public:
    explicit CompensationSession(QObject* parent = nullptr);
    ~CompensationSession() override;

    /// Hands `run`, built on `station`, to the compensation thread: from now on only that thread
    /// touches them. `speed`: PLC cycles per period on a simulated pass.
    void start(std::shared_ptr<core::BoringStation> station, std::unique_ptr<core::BoringRun> run, int speed);
    void setSpeed(int speed);
    void setSegment(core::SegmentKind kind);
    /// Stops the run; its cycles still on the way are dropped.
    void stop();
    bool running() const { return m_running; }

    /// The compensation's thread (never the GUI thread).
    QThread* compensationThread() { return &m_thread; }
    /// When the PLC periods of the current or last run started (steady clock, measured in the
    /// compensation's thread), oldest first.
    std::vector<std::chrono::steady_clock::time_point> cycleStarts() const { return m_schedule->starts(); }

signals:
    /// The cycles of one PLC period, oldest first.
    void cycles(const QVector<tt::core::BoringRunCycle>& batch);
    /// The simulated pass is over; the run has stopped.
    void passFinished();

private:
    QThread m_thread;
    std::shared_ptr<CycleSchedule> m_schedule;
    CompensationWorker* m_worker = nullptr;
    quint64 m_runId = 0;
    bool m_running = false;
};

}  // namespace tt::runtime
