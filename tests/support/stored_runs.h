#pragma once

// Reading a run back from a real history file, and cutting a run of the real `trueturn simulate --db` off with
// SIGTERM part-way, for the tests of resume (command line and Run page). Header-only.
#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QThread>
#include <algorithm>
#include <csignal>
#include <vector>

#include "core/storage/database.h"
#include "core/storage/history_store.h"

namespace tt::test {

/// Every stored diameter of the run `runIndex` (0: the newest) of the SQLite history `path`, part by part and
/// point by point (-1 for a point not measured); empty when there is no such run.
inline std::vector<double> storedDiameters(const QString& path, std::size_t runIndex = 0) {
    storage::Database db(storage::DatabaseConfig::sqlite(path));
    storage::SqlHistoryStore history(db);
    std::vector<double> out;
    const std::vector<core::RunSummary> runs = history.runs();
    if (runs.size() <= runIndex) return out;
    for (const core::StoredPart& part : history.parts(runs[runIndex].runId))
        if (part.measurement)
            for (const core::PointMeasurementRecord& p : part.measurement->points)
                out.push_back(p.measuredMm.value_or(-1.0));
    return out;
}

/// Starts `trueturn simulate <arguments> --progress` (paced, so it can be caught), waits until the closed loop
/// has finished `afterParts` parts by its progress on stderr, and sends SIGTERM. Returns the exit code (130
/// when it stopped after a part), or -1 when the run ended or did not start before it could be cut off.
inline int interruptedSimulate(const QString& exe, const QStringList& arguments, int afterParts) {
    QProcess process;
    process.start(exe, QStringList{QStringLiteral("simulate")} + arguments + QStringList{QStringLiteral("--progress")});
    if (!process.waitForStarted()) return -1;
    QString err;
    static const QRegularExpression done(QStringLiteral("closed loop: part (\\d+) of"));
    auto partsDone = [&] {
        int most = 0;
        for (auto it = done.globalMatch(err); it.hasNext();)
            most = std::max(most, it.next().captured(1).toInt());
        return most;
    };
    while (partsDone() < afterParts && process.state() == QProcess::Running) {
        process.waitForReadyRead(100);
        err += QString::fromUtf8(process.readAllStandardError());
    }
    if (process.state() != QProcess::Running) return -1;
    ::kill(static_cast<pid_t>(process.processId()), SIGTERM);
    process.waitForFinished(-1);
    return process.exitCode();
}

}  // namespace tt::test
