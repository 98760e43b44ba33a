#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <optional>

#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "core/sim/shaft/feed_schedule_check.h"

namespace tt::ui {

/// What a task of the Feed schedule tool produced: a model, a check on the simulator, or why not.
struct FeedTaskResult {
    std::optional<config::DeformationModelFile> model;
    std::optional<core::FeedScheduleCheck> check;
    QString error;  ///< the engine's message when it failed
};

/// The long work of the Feed schedule tool, one task at a time in a worker thread (QtConcurrent) with
/// progress and cancel, so the window never waits: the experiments on the simulator and the fit, a fit
/// of a measured CSV, the scheduled pass machined on the simulator.
class FeedModelTask : public QObject {
    Q_OBJECT
public:
    /// Idle until a task is started.
    explicit FeedModelTask(QObject* parent = nullptr);
    /// Cancels a running task and waits for it.
    ~FeedModelTask() override;

    /// Whether a task is running.
    bool busy() const;
    /// Runs the experiments of `setup` on the simulator (progress bar by bar) and fits the model.
    /// `presetName` is recorded as the model's set-up. Ignored while busy.
    void simulateAndFit(const config::FeedSchedulingSetup& setup, const QString& presetName,
                        core::DeformationTermSet terms, bool stepwise);
    /// Reads the experiment CSV `path` and fits the model (the set-up from its '# preset:' line).
    void fitCsv(const QString& path, core::DeformationTermSet terms, bool stepwise);
    /// Machines the schedule on the simulated lathe `lathe` at the request's depth.
    void check(const core::LatheSetup& lathe, const core::FeedSchedule& schedule,
               const core::FeedScheduleRequest& request);
    /// Asks the running task to stop; `finished` then reports it as cancelled.
    void cancel();

signals:
    /// Progress of the running task, 0 .. 100 %.
    void progress(int percent);
    /// The task ended: its result, or `cancelled`.
    void finished(const tt::ui::FeedTaskResult& result, bool cancelled);

private:
    template <typename Work>
    void run(Work work);

    QFutureWatcher<FeedTaskResult> m_watcher;
};

}  // namespace tt::ui
