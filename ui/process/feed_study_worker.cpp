#include "ui/process/feed_study_worker.h"

#include <QThread>
#include <stdexcept>

namespace tt::ui {

FeedStudyWorker::FeedStudyWorker(QObject* parent) : QObject(parent) {}

FeedStudyWorker::~FeedStudyWorker() {
    if (m_thread) {
        m_cancel->store(true);
        m_thread->wait();
        delete m_thread;
    }
}

bool FeedStudyWorker::start(FeedStudyResult::Job job, const core::FeedScenario& scenario,
                            core::FeedRegulator regulator) {
    if (m_thread) return false;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    const std::shared_ptr<std::atomic<bool>> cancel = m_cancel;
    m_thread = QThread::create([this, job, scenario, regulator, cancel] {
        const core::FeedProgress progress = [this](int done, int total) {
            QMetaObject::invokeMethod(
                this, [this, done, total] { emit this->progress(done, total); }, Qt::QueuedConnection);
        };
        auto result = std::make_shared<FeedStudyResult>(
            compute(job, scenario, regulator, progress, [cancel] { return cancel->load(); }));
        QMetaObject::invokeMethod(
            this,
            [this, result] {
                m_thread->wait();
                delete m_thread;
                m_thread = nullptr;
                emit finished(result);
            },
            Qt::QueuedConnection);
    });
    m_thread->start();
    return true;
}

void FeedStudyWorker::cancel() {
    if (m_cancel) m_cancel->store(true);
}

void FeedStudyWorker::simulate(FeedStudyResult& r, const core::FeedProgress& progress,
                               const core::FeedCancelled& cancelled) {
    const double load = r.scenario.finalLoadN();
    const bool feedForward = r.regulator == core::FeedRegulator::FeedForward;
    const int total = feedForward && load > 0.0 ? 3 : 2;
    if (r.regulator == core::FeedRegulator::Feedback) r.feedback = core::designFeedFeedback(r.scenario.params);
    r.with = core::runFeedScenario(r.scenario, r.regulator, cancelled);
    progress(1, total);
    r.without = core::runFeedScenario(r.scenario, core::FeedRegulator::Off, cancelled);
    progress(2, total);
    if (total < 3) return;
    try {
        r.stability = core::analyseStability(r.scenario.params, load);
    } catch (const std::invalid_argument& e) {
        r.stabilityProblem = QString::fromStdString(e.what());
    }
    if (r.stability && r.stability->gainLimit)
        r.check = core::crossCheckGainLimit(r.scenario, *r.stability->gainLimit, cancelled);
    progress(3, total);
}

FeedStudyResult FeedStudyWorker::compute(FeedStudyResult::Job job, const core::FeedScenario& scenario,
                                         core::FeedRegulator regulator, const core::FeedProgress& progress,
                                         const core::FeedCancelled& cancelled) {
    FeedStudyResult r;
    r.job = job;
    r.scenario = scenario;
    r.regulator = regulator;
    try {
        if (job == FeedStudyResult::Job::Simulate) {
            simulate(r, progress, cancelled);
        } else {
            const core::FeedSweepKind kind = job == FeedStudyResult::Job::SweepXi ? core::FeedSweepKind::DampingRatio
                                                                                  : core::FeedSweepKind::AmplifierGain;
            r.sweep = core::sweepFeed(scenario, kind, core::defaultSweepValues(kind, scenario, regulator), regulator,
                                      progress, cancelled);
        }
    } catch (const core::FeedSimulationCancelled&) {
        r.cancelled = true;
    } catch (const std::exception& e) {
        r.problem = QString::fromStdString(e.what());
    }
    return r;
}

}  // namespace tt::ui
