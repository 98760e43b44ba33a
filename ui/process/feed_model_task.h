#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <cstdint>
#include <optional>

#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "core/sim/shaft/feed_refinement.h"
#include "core/sim/shaft/feed_schedule_check.h"

namespace tt::ui {

/// What a task of the Feed schedule tool produced: a model (with the measurements it was fitted on), a
/// check on the simulator, a refinement of the model, or why not.
struct FeedTaskResult {
    std::optional<config::DeformationModelFile> model;
    std::optional<core::DeformationSamples> samples;  ///< the measurements of `model`
    std::optional<core::FeedScheduleCheck> check;
    std::optional<core::FeedRefinement> refinement;
    std::optional<config::DeformationModelFile> refinedModel;  ///< the refinement's local model, if it has one
    QString error;                                             ///< the engine's message when it failed
};

/// What a refinement starts from: the model, its measurements (may be empty) and the request.
struct FeedRefineJob {
    core::LatheSetup lathe;
    config::DeformationModelFile model;
    core::DeformationSamples measured;
    core::FeedScheduleRequest request;
    core::FeedRefinementOptions options;
    std::uint64_t seed = 1;
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
    /// Closes the loop on the model (refineFeedSchedule): targeted bars on the simulator, the local model
    /// refitted, the pass rescheduled and machined, round after round; progress bar by bar.
    void refine(const FeedRefineJob& job);
    /// Asks the running task to stop; `finished` then reports it as cancelled.
    void cancel();

signals:
    /// Progress of the running task, 0 .. 100 %.
    void progress(int percent);
    /// Where a refinement is: round, bars done in it and bars planned in it (in the GUI thread).
    void refineProgress(int round, int barsDone, int bars);
    /// The task ended: its result, or `cancelled`.
    void finished(const tt::ui::FeedTaskResult& result, bool cancelled);

private:
    template <typename Work>
    void run(Work work);

    QFutureWatcher<FeedTaskResult> m_watcher;
};

}  // namespace tt::ui
