#pragma once

#include <QObject>
#include <QVector>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "core/run/boring_run.h"

Q_DECLARE_METATYPE(tt::core::BoringRunCycle)

class QTimer;

namespace tt::runtime {

/// When the PLC cycles of the compensation thread started (steady clock), for the operator's
/// figures and the tests that prove a busy window does not delay them. Thread-safe.
class CycleSchedule {
public:
    /// Keeps at most `capacity` (> 0) start times, the latest.
    explicit CycleSchedule(std::size_t capacity = 20000);
    /// Forgets every start (a new run).
    void clear();
    /// A cycle starts now.
    void record(std::chrono::steady_clock::time_point start);
    /// The recorded starts, oldest first.
    std::vector<std::chrono::steady_clock::time_point> starts() const;

private:
    const std::size_t m_capacity;
    mutable std::mutex m_mutex;
    std::vector<std::chrono::steady_clock::time_point> m_starts;
};

/// The in-process compensation in its own thread (paper 001; issue 11): owns the run and the
/// station it runs on, and every PLC cycle (a precise timer of this thread, one period of the run's
/// PLC cycle) runs the run's cycle: a machine once per period (its devices are reached through
/// thread-safe relays, so a busy window does not delay the offset), a simulated pass `speed`
/// times per period in lock-step with it. Commands come as queued calls; the cycles go out in
/// batches, one per period, through a queued signal.
class CompensationWorker : public QObject {
    Q_OBJECT
public:
    explicit CompensationWorker(std::shared_ptr<CycleSchedule> schedule);
    ~CompensationWorker() override;

    /// Starts `run` on `station` (the run was built on it); `runId` marks its batches.
    void start(std::shared_ptr<core::BoringStation> station, std::shared_ptr<core::BoringRun> run, int speed,
               quint64 runId);
    /// PLC cycles per period on a simulated pass (1 .. 100); a machine always runs one.
    void setSpeed(int speed);
    /// What the part program cuts.
    void setSegment(core::SegmentKind kind);
    /// Stops the timer and drops the run and the station.
    void stop();

signals:
    /// The cycles of one period of run `runId`, oldest first.
    void cycles(quint64 runId, const QVector<tt::core::BoringRunCycle>& batch);
    /// The simulated pass of run `runId` is over (the tool left the bore); the worker stopped.
    void passFinished(quint64 runId);

private:
    void tick();

    std::shared_ptr<CycleSchedule> m_schedule;
    QTimer* m_timer;
    std::shared_ptr<core::BoringStation> m_station;
    std::shared_ptr<core::BoringRun> m_run;
    int m_speed = 1;
    quint64 m_runId = 0;
    bool m_preferred = false;  ///< the thread's priority was raised (preferThisThread)
};

}  // namespace tt::runtime
