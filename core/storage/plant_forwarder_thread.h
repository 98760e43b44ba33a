#pragma once

#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QMutex>
#include <QThread>
#include <QWaitCondition>
#include <functional>

#include "core/storage/plant_forwarder.h"

namespace tt::storage {

/// What a forwarder thread sends where.
struct ForwarderOptions {
    QString journalPath;   ///< the terminal's journal (HistoryJournal made it)
    DatabaseConfig plant;  ///< the plant database
    QString machine;       ///< the journal's machine (reported with its backlog)
    std::int64_t journalLimitBytes = kDefaultJournalLimitBytes;
    ForwarderSettings settings;
};

/// The forwarder of a terminal in its own thread: sends the journal to the plant database in order and in
/// batches (PlantForwarder), and when the server cannot be reached retries with a back-off from 0.5 s doubling
/// to 30 s, while the loop goes on writing the journal. Its state is a thread-safe snapshot (status()), a
/// signal (statusChanged, queued to the receiver's thread) and a callback (called in the forwarder's thread).
/// Starts with start(); stops on requestStop() or drainAndStop(); the destructor stops it and waits.
class PlantForwarderThread : public QThread {
    Q_OBJECT
public:
    explicit PlantForwarderThread(ForwarderOptions options, QObject* parent = nullptr);
    ~PlantForwarderThread() override;

    /// The newest status (any thread).
    ForwarderStatus status() const;
    /// Called in the forwarder's thread at every change of the link and at most every 0.25 s otherwise. Set
    /// before start().
    void setStatusCallback(std::function<void(const ForwarderStatus&)> callback);
    /// New entries are in the journal: send them now instead of at the next poll (any thread, cheap).
    void wake();
    /// Asks the thread to stop after its current attempt (any thread).
    void requestStop();
    /// Sends what is left, waiting at most `timeoutS` (retrying as usual), then stops the thread. Returns
    /// whether everything was sent. Call from the thread that started it.
    bool drainAndStop(double timeoutS);

    /// The deadline `seconds` from now: expired at once for 0, a negative time or NaN (a wait computed as "what is
    /// left" can come out below zero on a busy computer), never one that does not expire.
    static QDeadlineTimer deadlineAfter(double seconds);

signals:
    /// The status changed (emitted from the forwarder's thread).
    void statusChanged(const tt::storage::ForwarderStatus& status);

protected:
    void run() override;

private:
    void publish(ForwarderStatus status, bool linkChanged);
    /// Waits `seconds` or until woken (`wakeable`) or stopped; returns false when stopping.
    bool pause(double seconds, bool wakeable);
    bool stopping() const;
    void sendRound(PlantForwarder& forwarder, ForwarderStatus& s, double& retryS);

    ForwarderOptions m_options;
    mutable QMutex m_mutex;
    QWaitCondition m_wakeUp;
    bool m_woken = false;
    bool m_stop = false;
    bool m_finishing = false;  ///< drainAndStop: stop once drained
    ForwarderStatus m_status;
    std::function<void(const ForwarderStatus&)> m_callback;
    qint64 m_lastPublishMs = -1;
    QElapsedTimer m_sinceReport;  ///< since the last heartbeat (the forwarder's thread only)
};

}  // namespace tt::storage
