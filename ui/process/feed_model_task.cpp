#include "ui/process/feed_model_task.h"

#include <QFile>
#include <QFileInfo>
#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "config/deformation_csv.h"
#include "config/feed_refinement_json.h"
#include "config/preset_library.h"
#include "core/sim/shaft/deformation_experiment.h"
#include "core/sim/shaft/lathe_pass.h"

namespace tt::ui {

namespace {

config::DeformationModelFile fitted(const core::DeformationSamples& samples, core::DeformationTermSet terms,
                                    bool stepwise) {
    return config::deformationModelFile(core::fitDeformationModel(samples, terms, stepwise));
}

}  // namespace

FeedModelTask::FeedModelTask(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcher<FeedTaskResult>::progressValueChanged, this, &FeedModelTask::progress);
    connect(&m_watcher, &QFutureWatcher<FeedTaskResult>::finished, this, [this] {
        const QFuture<FeedTaskResult> future = m_watcher.future();
        const bool cancelled = future.isCanceled() || future.resultCount() == 0;
        emit finished(cancelled ? FeedTaskResult{} : future.result(), cancelled);
    });
}

FeedModelTask::~FeedModelTask() {
    m_watcher.disconnect(this);
    m_watcher.cancel();
    m_watcher.waitForFinished();
}

bool FeedModelTask::busy() const {
    return m_watcher.isRunning();
}

void FeedModelTask::cancel() {
    m_watcher.cancel();
}

template <typename Work>
void FeedModelTask::run(Work work) {
    if (busy()) return;
    m_watcher.setFuture(QtConcurrent::run([work](QPromise<FeedTaskResult>& promise) {
        promise.setProgressRange(0, 100);
        FeedTaskResult result;
        try {
            work(promise, result);
        } catch (const core::DeformationExperimentStopped&) {
            return;  // cancelled: no result
        } catch (const std::exception& e) {
            result.error = QString::fromStdString(e.what());
        }
        if (!promise.isCanceled()) promise.addResult(std::move(result));
    }));
}

void FeedModelTask::simulateAndFit(const config::FeedSchedulingSetup& setup, const QString& presetName,
                                   core::DeformationTermSet terms, bool stepwise) {
    run([setup, presetName, terms, stepwise](QPromise<FeedTaskResult>& promise, FeedTaskResult& result) {
        const core::DeformationSamples samples =
            core::runDeformationExperiment(setup.lathe, setup.experiment, [&](std::size_t done, std::size_t bars) {
                promise.setProgressValue(static_cast<int>(90 * done / bars));
                return !promise.isCanceled();
            });
        config::DeformationModelFile file = fitted(samples, terms, stepwise);
        file.sourceFile = QStringLiteral("simulated");
        file.preset = presetName;
        file.seed = setup.experiment.seed;
        file.job = setup.job;
        promise.setProgressValue(100);
        result.model = std::move(file);
        result.samples = samples;
    });
}

void FeedModelTask::fitCsv(const QString& path, core::DeformationTermSet terms, bool stepwise) {
    run([path, terms, stepwise](QPromise<FeedTaskResult>& promise, FeedTaskResult& result) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            throw std::runtime_error(QStringLiteral("cannot read %1: %2").arg(path, file.errorString()).toStdString());
        const config::DeformationCsv csv = config::parseDeformationCsv(file.readAll());
        promise.setProgressValue(30);
        config::DeformationModelFile model = fitted(csv.samples, terms, stepwise);
        model.sourceFile = QFileInfo(path).fileName();
        model.seed = csv.seed;
        if (!csv.preset.isEmpty()) {
            model.preset = csv.preset;
            model.job = config::feedPassJobFromPreset(config::PresetLibrary::load(csv.preset));
        }
        promise.setProgressValue(100);
        result.model = std::move(model);
        result.samples = csv.samples;
    });
}

void FeedModelTask::check(const core::LatheSetup& lathe, const core::FeedSchedule& schedule,
                          const core::FeedScheduleRequest& request) {
    run([lathe, schedule, request](QPromise<FeedTaskResult>& promise, FeedTaskResult& result) {
        const core::LathePass pass(lathe, request.depthMm);
        promise.setProgressValue(80);
        result.check = core::checkFeedSchedule(pass, schedule, request);
        promise.setProgressValue(100);
    });
}

void FeedModelTask::refine(const FeedRefineJob& job) {
    run([this, job](QPromise<FeedTaskResult>& promise, FeedTaskResult& result) {
        const int rounds = job.options.maxRounds;
        const auto progress = [&](int round, std::size_t done, std::size_t bars) {
            const double share = (round - 1 + static_cast<double>(done) / static_cast<double>(bars)) / rounds;
            promise.setProgressValue(static_cast<int>(100.0 * share));
            // Queued to the GUI thread: the label says which round and bar.
            QMetaObject::invokeMethod(
                this,
                [this, round, done, bars] {
                    emit refineProgress(round, static_cast<int>(done), static_cast<int>(bars));
                },
                Qt::QueuedConnection);
            return !promise.isCanceled();
        };
        core::FeedRefinement refinement =
            core::refineFeedSchedule(job.lathe, job.model.model, job.model.statistics.residualSigmaUm, job.measured,
                                     job.request, job.options, job.seed, progress);
        if (const core::FeedRefinementRound* last = refinement.lastScheduled())
            result.refinedModel = config::refinedModelFile(*last->fit, job.model, refinement.barCount());
        promise.setProgressValue(100);
        result.refinement = std::move(refinement);
    });
}

}  // namespace tt::ui
