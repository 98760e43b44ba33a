#include "runtime/reports/report_task.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "core/storage/history_store.h"
#include "runtime/reports/chart_adaptations.h"
#include "runtime/reports/report_files.h"

namespace tt::runtime {

namespace {

/// A progress callback of the report functions mapping (done, total) into `from` .. `to` % of the promise.
ReportProgress progressOf(QPromise<ReportTaskResult>& promise, int from, int to) {
    return [&promise, from, to](std::size_t done, std::size_t total) {
        const double share = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
        promise.setProgressValue(from + static_cast<int>(share * (to - from)));
        return !promise.isCanceled();
    };
}

/// The adaptations of the runs whose readings are in `readings`, into `byRun`; returns the storage's message when
/// they cannot be read: the report stands without them.
QString readAdaptations(storage::SqlHistoryStore& store, const std::vector<storage::PointReadings>& readings,
                        RunAdaptations& byRun) {
    try {
        byRun = readRunAdaptations(store, readings);
        return {};
    } catch (const std::exception& e) {
        byRun.clear();
        return QString::fromStdString(e.what());
    }
}

}  // namespace

ReportTask::ReportTask(QObject* parent) : QObject(parent) {
    connect(&m_watcher, &QFutureWatcher<ReportTaskResult>::progressValueChanged, this, &ReportTask::progress);
    connect(&m_watcher, &QFutureWatcher<ReportTaskResult>::finished, this, [this] {
        const QFuture<ReportTaskResult> future = m_watcher.future();
        const bool cancelled = future.isCanceled() || future.resultCount() == 0;
        emit finished(cancelled ? ReportTaskResult{} : future.result(), cancelled);
    });
}

ReportTask::~ReportTask() {
    m_watcher.disconnect(this);
    m_watcher.cancel();
    m_watcher.waitForFinished();
}

bool ReportTask::busy() const {
    return m_watcher.isRunning();
}

void ReportTask::cancel() {
    m_watcher.cancel();
}

template <typename Work>
void ReportTask::run(Work work) {
    if (busy()) return;
    m_watcher.setFuture(QtConcurrent::run([work](QPromise<ReportTaskResult>& promise) {
        promise.setProgressRange(0, 100);
        ReportTaskResult result;
        try {
            work(promise, result);
        } catch (const ReportCancelled&) {
            return;  // cancelled: no result
        } catch (const std::exception& e) {
            result.error = QString::fromStdString(e.what());
        }
        if (!promise.isCanceled()) promise.addResult(std::move(result));
    }));
}

void ReportTask::analyse(const storage::DatabaseConfig& config, const storage::MeasurementFilter& filter,
                         const core::PointAnalysisSettings& settings) {
    run([config, filter, settings](QPromise<ReportTaskResult>& promise, ReportTaskResult& result) {
        std::vector<storage::PointReadings> readings;
        RunAdaptations byRun;
        {
            storage::Database db(config);  // this thread's own connection (QtSql)
            readings = storage::queryPointReadings(db, filter);
            promise.setProgressValue(30);
            if (promise.isCanceled()) throw ReportCancelled();
            // Every column of every reading: the part profiles and the CSV, DFQ and PDF files.
            result.rows = storage::queryMeasurements(db, filter);
            promise.setProgressValue(50);
            if (promise.isCanceled()) throw ReportCancelled();
            storage::SqlHistoryStore store(db);
            result.runs = store.runs();
            result.adaptationsError = readAdaptations(store, readings, byRun);
        }
        result.points = analyseReport(readings, settings, progressOf(promise, 50, 100));
        placeAdaptations(result.points, byRun);
    });
}

void ReportTask::writeFile(std::vector<storage::MeasurementRow> rows, const QString& path, bool dfq) {
    run([rows = std::move(rows), path, dfq](QPromise<ReportTaskResult>& promise, ReportTaskResult& result) {
        if (dfq)
            writeMeasurementsDfq(path, rows, progressOf(promise, 0, 100));
        else
            writeMeasurementsCsv(path, rows, progressOf(promise, 0, 100));
        result.writtenFile = path;
    });
}

}  // namespace tt::runtime
