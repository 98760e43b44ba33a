#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <vector>

#include "core/ports/history_store.h"
#include "core/storage/database.h"
#include "core/storage/measurement_query.h"
#include "runtime/reports/point_report.h"

namespace tt::runtime {

/// What a task of the Reports page produced: the readings and each point's report, a written file, or why
/// not.
struct ReportTaskResult {
    std::vector<storage::MeasurementRow> rows;
    std::vector<PointReport> points;
    std::vector<core::RunSummary> runs;
    QString adaptationsError;  ///< why the adaptations of the runs could not be read (the report stands without them)
    QString writtenFile;
    QString error;  ///< the storage's or the statistics' message when it failed
};

/// The long work of the Reports page in a worker thread (QtConcurrent) with progress and cancel: reading the
/// history on the worker's own connection and computing every point's report, and writing the CSV or DFQ
/// file. One task at a time.
class ReportTask : public QObject {
    Q_OBJECT
public:
    explicit ReportTask(QObject* parent = nullptr);
    /// Cancels a running task and waits for it.
    ~ReportTask() override;

    bool busy() const;
    /// Reads the readings chosen by `filter` from the database `config` and analyses every point.
    void analyse(const storage::DatabaseConfig& config, const storage::MeasurementFilter& filter,
                 const core::PointAnalysisSettings& settings);
    /// Writes `rows` as CSV (dfq false) or AQDEF DFQ to `path`.
    void writeFile(std::vector<storage::MeasurementRow> rows, const QString& path, bool dfq);
    /// Asks the running task to stop; `finished` then reports it as cancelled.
    void cancel();

signals:
    /// Progress of the running task, 0 .. 100 %.
    void progress(int percent);
    /// The task ended: its result, or `cancelled`.
    void finished(const tt::runtime::ReportTaskResult& result, bool cancelled);

private:
    template <typename Work>
    void run(Work work);

    QFutureWatcher<ReportTaskResult> m_watcher;
};

}  // namespace tt::runtime
