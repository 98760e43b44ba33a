#pragma once

#include <QObject>
#include <QString>
#include <atomic>
#include <functional>

#include "core/sim/feed_drives/corner_training.h"

class QThread;

namespace tt::ui {

/// Runs one piece of the Corner tool's long work (training, a run of corners, a retraining) in its own
/// thread, so the window never waits for it. The work gets a progress callback that reports to the GUI
/// thread (at most about 20 times a second) and stops the work (core::OperationCancelled) once cancel()
/// was called. One job at a time; destroying the runner cancels a running job and waits for it.
class CornerJob : public QObject {
    Q_OBJECT
public:
    /// The work; runs in the job's thread and must not touch widgets.
    using Work = std::function<void(const core::CornerProgress& progress)>;

    explicit CornerJob(QObject* parent = nullptr);
    ~CornerJob() override;

    /// Starts `work`; false when a job is still running.
    bool start(Work work);
    /// Asks the running job to stop at its next progress report.
    void cancel();
    /// Whether a job runs.
    bool running() const { return m_thread != nullptr; }

signals:
    /// Progress of the running job: its stage ("targets", "network", "work", "retraining"), done of total.
    void progress(const QString& stage, int done, int total);
    /// The job ended: cancelled, or failed with `error` (empty when it succeeded).
    void finished(bool cancelled, const QString& error);

private:
    QThread* m_thread = nullptr;
    std::atomic<bool> m_cancel{false};
    bool m_cancelled = false;
    QString m_error;
};

}  // namespace tt::ui
