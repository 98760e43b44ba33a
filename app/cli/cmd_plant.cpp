// `trueturn plant`: argument parsing and output only. The overview is ui/reports' plantOverview (the plant
// database read by storage::queryPlant, the capability windows by the report's own analysis), the same as the
// Plant page shows.
#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimeZone>
#include <memory>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "core/storage/history_store.h"
#include "runtime/reports/plant_report.h"

namespace tt::cli {

namespace {

QString cpkText(const std::optional<double>& v) {
    return v ? QString::number(*v, 'f', 2) : QStringLiteral("-");
}

void printText(const runtime::PlantOverview& overview) {
    printLine(QStringLiteral("Plant at %1 UTC, the day from %2 UTC; Cpk of the last %3 parts (change against the %3 "
                             "before)")
                  .arg(overview.at.toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                       overview.dayFrom.toString(QStringLiteral("yyyy-MM-dd HH:mm")))
                  .arg(overview.windowParts));
    for (const runtime::PlantMachine& m : overview.machines) {
        QString line = QStringLiteral("%1  %2")
                           .arg(QString::fromStdString(m.machine), -12)
                           .arg(QString::fromStdString(runtime::machineStateName(m.state)), -8);
        line += m.lastPartAt
                    ? QStringLiteral("  last part %1").arg(m.lastPartAt->toString(QStringLiteral("MM-dd HH:mm")))
                    : QStringLiteral("  no part");
        if (m.backlogParts) line += QStringLiteral("  backlog %1").arg(*m.backlogParts);
        line += QStringLiteral("  today %1/%2/%3").arg(m.today.good).arg(m.today.rework).arg(m.today.scrap);
        for (const runtime::PlantPointCapability& p : m.points) {
            const std::optional<double> change = p.change();
            line += QStringLiteral("  P%1 %2%3")
                        .arg(p.pointIndex + 1)
                        .arg(cpkText(p.cpk))
                        .arg(change ? QStringLiteral(" (%1%2)").arg(*change >= 0 ? "+" : "").arg(*change, 0, 'f', 2)
                                    : QString());
        }
        if (m.openAlarmCount > 0) line += QStringLiteral("  alarms %1").arg(m.openAlarmCount);
        printLine(line);
    }
}

/// `--setup`: migrates the history schema with write access (on PostgreSQL also the plant's roles and policies).
void setUpPlantDatabase(const storage::DatabaseConfig& config) {
    try {
        storage::Database db(config);
        db.migrate(storage::historySchema());
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--setup: the plant database cannot be set up (it needs its owner's login, "
                                     "allowed to create roles or with the two group roles made first): ") +
                         e.what());
    }
}

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("plant"),
        QStringLiteral("Every machine of the plant database: its state (running, idle, offline with the time of its "
                       "last part), the parts its terminal still keeps, the day's good, rework and scrap parts, per "
                       "control point the Cpk of its last parts and the change against the ones before, and its open "
                       "alarms. Read-only (also from a hot standby or with the quality engineer's role)."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The plant database, postgresql://user@host:port/database (or an SQLite history)."),
                     QStringLiteral("db"));
    parser.addOption(QStringLiteral("at"),
                     QStringLiteral("Judge the states and the day at this ISO 8601 time (default: now; a time without "
                                    "zone is UTC)."),
                     QStringLiteral("time"));
    parser.addOption(
        QStringLiteral("window"),
        QStringLiteral("Parts in a capability window, 10..10000 (default %1).").arg(runtime::kPlantWindowParts),
        QStringLiteral("n"));
    parser.addOption(
        QStringLiteral("setup"),
        QStringLiteral("First bring the plant database up to date, as its owner: the history tables, the "
                       "group roles trueturn_terminal and trueturn_quality, their rights and the row-level "
                       "policies (once for a new plant database and after an update of TrueTurn)."));
    parser.parse(arguments);

    storage::DatabaseConfig config = databaseConfigFromOption(parser.required(QStringLiteral("db")));
    if (parser.isSet(QStringLiteral("setup"))) setUpPlantDatabase(config);
    config.readOnly = config.kind == storage::DatabaseConfig::Kind::Postgres;  // a hot standby, the quality role
    QDateTime at = QDateTime::currentDateTimeUtc();
    if (parser.isSet(QStringLiteral("at"))) {
        at = QDateTime::fromString(parser.value(QStringLiteral("at")), Qt::ISODateWithMs);
        if (!at.isValid())
            throw UsageError("--at: '" + parser.value(QStringLiteral("at")).toStdString() +
                             "' is not an ISO 8601 date and time");
        if (at.timeSpec() == Qt::LocalTime) at.setTimeZone(QTimeZone::utc());
    }
    const int window = parser.isSet(QStringLiteral("window"))
                           ? static_cast<int>(parser.integer(QStringLiteral("window"), 10, 10000))
                           : runtime::kPlantWindowParts;
    if (config.kind == storage::DatabaseConfig::Kind::Sqlite && !QFile::exists(config.sqlitePath))
        throw UsageError("--db: '" + config.sqlitePath.toStdString() + "' does not exist");
    runtime::PlantOverview overview;
    try {
        storage::Database db(config);
        overview = runtime::plantOverview(db, at, window);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    if (parser.json())
        printJson(runtime::plantOverviewJson(overview));
    else
        printText(overview);
    return kExitOk;
}

}  // namespace

Command makePlantCommand() {
    return {QStringLiteral("plant"),
            QStringLiteral("Overview of the plant database: every machine's state, backlog, the day's verdicts, Cpk "
                           "of its last parts per point, open alarms"),
            run};
}

}  // namespace tt::cli
