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

bool FeedStudyWorker::start(FeedStudyResult::Job job, const core::FeedScenario& scenario) {
    if (m_thread) return false;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    const std::shared_ptr<std::atomic<bool>> cancel = m_cancel;
    m_thread = QThread::create([this, job, scenario, cancel] {
        const core::FeedProgress progress = [this](int done, int total) {
            QMetaObject::invokeMethod(
                this, [this, done, total] { emit this->progress(done, total); }, Qt::QueuedConnection);
        };
        auto result =
            std::make_shared<FeedStudyResult>(compute(job, scenario, progress, [cancel] { return cancel->load(); }));
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

FeedStudyResult FeedStudyWorker::compute(FeedStudyResult::Job job, const core::FeedScenario& scenario,
                                         const core::FeedProgress& progress, const core::FeedCancelled& cancelled) {
    FeedStudyResult r;
    r.job = job;
    r.scenario = scenario;
    try {
        if (job == FeedStudyResult::Job::Simulate) {
            const double load = scenario.finalLoadN();
            const int total = load > 0.0 ? 3 : 2;
            r.with = core::runFeedScenario(scenario, true, cancelled);
            progress(1, total);
            r.without = core::runFeedScenario(scenario, false, cancelled);
            progress(2, total);
            if (load > 0.0) {
                try {
                    r.stability = core::analyseStability(scenario.params, load);
                } catch (const std::invalid_argument& e) {
                    r.stabilityProblem = QString::fromStdString(e.what());
                }
                if (r.stability && r.stability->gainLimit)
                    r.check = core::crossCheckGainLimit(scenario, *r.stability->gainLimit, cancelled);
                progress(3, total);
            }
        } else {
            const core::FeedSweepKind kind = job == FeedStudyResult::Job::SweepXi ? core::FeedSweepKind::DampingRatio
                                                                                  : core::FeedSweepKind::AmplifierGain;
            r.sweep = core::sweepFeed(scenario, kind, core::defaultSweepValues(kind, scenario), progress, cancelled);
        }
    } catch (const core::FeedSimulationCancelled&) {
        r.cancelled = true;
    } catch (const std::exception& e) {
        r.problem = QString::fromStdString(e.what());
    }
    return r;
}

}  // namespace tt::ui
