#pragma once

#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include "core/sim/hydraulic/feed_study.h"

class QThread;

namespace tt::ui {

/// What the Hydraulic feed tool asked for and what came back.
struct FeedStudyResult {
    enum class Job { Simulate, SweepXi, SweepGain };
    Job job = Job::Simulate;
    core::FeedScenario scenario;
    core::FeedRegulator regulator = core::FeedRegulator::Feedback;  ///< the regulator of `with` and of the sweeps
    core::FeedRun with;                                             ///< Simulate: with the regulator
    core::FeedRun without;                                          ///< Simulate: regulator off
    std::optional<core::FeedStability> stability;                   ///< Simulate, feed-forward, with a load at the end
    std::optional<core::FeedFeedbackDesign> feedback;               ///< Simulate, feedback: its design and margins
    std::optional<core::FeedBoundaryCheck> check;                   ///< Simulate, when there is a gain limit
    std::vector<core::FeedSweepPoint> sweep;                        ///< SweepXi, SweepGain
    QString problem;           ///< the engine refused (a parameter or the load), in its words
    QString stabilityProblem;  ///< Simulate: why there is no stability analysis (no design point for the load)
    bool cancelled = false;
};

/// Runs the feed stabiliser's simulations and sweeps in a worker thread (never on the GUI thread),
/// reports progress and can be cancelled. One job at a time.
class FeedStudyWorker : public QObject {
    Q_OBJECT
public:
    explicit FeedStudyWorker(QObject* parent = nullptr);
    /// Cancels a running job and waits for its thread.
    ~FeedStudyWorker() override;

    /// Starts `job` on `scenario` with `regulator` (feed-forward or feedback); false when a job is still running.
    bool start(FeedStudyResult::Job job, const core::FeedScenario& scenario, core::FeedRegulator regulator);
    /// Asks the running job to stop at its next sample.
    void cancel();
    bool busy() const { return m_thread != nullptr; }

signals:
    /// (done, total) runs; in the GUI thread.
    void progress(int done, int total);
    /// The job's result (also when cancelled or refused); in the GUI thread.
    void finished(std::shared_ptr<const tt::ui::FeedStudyResult> result);

private:
    static FeedStudyResult compute(FeedStudyResult::Job job, const core::FeedScenario& scenario,
                                   core::FeedRegulator regulator, const core::FeedProgress& progress,
                                   const core::FeedCancelled& cancelled);
    static void simulate(FeedStudyResult& r, const core::FeedProgress& progress, const core::FeedCancelled& cancelled);

    QThread* m_thread = nullptr;
    std::shared_ptr<std::atomic<bool>> m_cancel;
};

}  // namespace tt::ui
