// `trueturn generate-history`: writes a generated quality history (storage::writeSyntheticHistory) for the
// benchmarks of the reports at shop scale and for demonstrations of the Reports page.
#include <QDateTime>
#include <QElapsedTimer>
#include <QTimeZone>
#include <QJsonObject>
#include <QString>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "core/storage/history_store.h"
#include "core/storage/synthetic_history.h"

namespace tt::cli {

namespace {

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("generate-history"),
        QStringLiteral("Appends a generated quality history to a database in one transaction: parts measured at "
                       "their control points against an h7 tolerance on 27 mm (offset, slow drift and scatter per "
                       "run and point), with verdicts and a few refused readings, over several runs and machines. "
                       "For benchmarks (docs/BENCHMARKS.md) and demonstrations; never into a production history."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The history: an SQLite file (created when missing) or "
                                    "postgresql://user@host:port/database."),
                     QStringLiteral("db"));
    parser.addOption(QStringLiteral("parts"), QStringLiteral("Parts to write, 1..10000000 (default 1000)."),
                     QStringLiteral("n"), QStringLiteral("1000"));
    parser.addOption(QStringLiteral("points"), QStringLiteral("Control points per part, 1..16 (default 5)."),
                     QStringLiteral("n"), QStringLiteral("5"));
    parser.addOption(QStringLiteral("runs"),
                     QStringLiteral("Runs the parts are spread over, 1..1000 and at most the parts (default 10)."),
                     QStringLiteral("n"), QStringLiteral("10"));
    parser.addOption(QStringLiteral("machines"), QStringLiteral("Machines the runs take turns on, 1..100 (default 3)."),
                     QStringLiteral("n"), QStringLiteral("3"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Seed of the values, 0..2^53 (default 1)."),
                     QStringLiteral("n"), QStringLiteral("1"));
    parser.addOption(QStringLiteral("start"),
                     QStringLiteral("When the first part is stored, ISO 8601 (default 2026-01-01T00:00:00Z; a time "
                                    "without zone is UTC)."),
                     QStringLiteral("time"));
    parser.addOption(QStringLiteral("parallel"),
                     QStringLiteral("The machines work side by side: each machine's parts one minute apart from "
                                    "--start (default: one part of the history per minute)."));
    parser.parse(arguments);

    storage::SyntheticHistorySpec spec;
    spec.parts = parser.integer(QStringLiteral("parts"), 1, storage::kMaxSyntheticParts);
    spec.points = static_cast<int>(parser.integer(QStringLiteral("points"), 1, 16));
    spec.runs = static_cast<int>(parser.integer(QStringLiteral("runs"), 1, std::min<long long>(1000, spec.parts)));
    spec.machines = static_cast<int>(parser.integer(QStringLiteral("machines"), 1, 100));
    spec.seed = static_cast<std::uint64_t>(parser.integer(QStringLiteral("seed"), 0, 1LL << 53));
    spec.machinesInParallel = parser.isSet(QStringLiteral("parallel"));
    if (parser.isSet(QStringLiteral("start"))) {
        QDateTime start = QDateTime::fromString(parser.value(QStringLiteral("start")), Qt::ISODateWithMs);
        if (!start.isValid())
            throw UsageError("--start: '" + parser.value(QStringLiteral("start")).toStdString() +
                             "' is not an ISO 8601 date and time");
        if (start.timeSpec() == Qt::LocalTime) start.setTimeZone(QTimeZone::utc());
        spec.firstPartEpochS = start.toSecsSinceEpoch();
    }
    const QString dbValue = parser.required(QStringLiteral("db"));

    QElapsedTimer timer;
    timer.start();
    storage::SyntheticHistoryResult result;
    try {
        storage::Database db(databaseConfigFromOption(dbValue));
        db.migrate(storage::historySchema());
        result = storage::writeSyntheticHistory(db, spec);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    const double seconds = static_cast<double>(timer.elapsed()) / 1000.0;
    if (parser.json()) {
        printJson(QJsonObject{{QStringLiteral("parts"), static_cast<qint64>(result.parts)},
                              {QStringLiteral("readings"), static_cast<qint64>(result.readings)},
                              {QStringLiteral("first_run"), static_cast<qint64>(result.firstRunId)},
                              {QStringLiteral("last_run"), static_cast<qint64>(result.lastRunId)},
                              {QStringLiteral("seconds"), seconds}});
        return kExitOk;
    }
    printLine(QStringLiteral("%1 parts (%2 readings) written as runs %3..%4 in %5 s")
                  .arg(result.parts)
                  .arg(result.readings)
                  .arg(result.firstRunId)
                  .arg(result.lastRunId)
                  .arg(seconds, 0, 'f', 1));
    return kExitOk;
}

}  // namespace

Command makeGenerateHistoryCommand() {
    return {QStringLiteral("generate-history"),
            QStringLiteral("Generated quality history (parts, readings, verdicts over runs and machines) for "
                           "benchmarks and demonstrations"),
            run};
}

}  // namespace tt::cli
