#include "core/storage/plant_query.h"

#include <QSqlError>
#include <QSqlQuery>
#include <algorithm>
#include <map>

#include "core/storage/history_store.h"

namespace tt::storage {

namespace {

QVariant id(std::int64_t v) {
    return QVariant(static_cast<qlonglong>(v));
}

/// A read-only query run front to back.
QSqlQuery select(Database& db, const QString& sql, const QVariantList& bindings = {}) {
    QSqlQuery q(db.connection());
    q.setForwardOnly(true);
    bool ok = q.prepare(db.dialectSql(sql));
    if (ok) {
        for (const QVariant& v : bindings)
            q.addBindValue(v);
        ok = q.exec();
    }
    if (!ok)
        throw StorageError("reading the plant overview failed: " + q.lastError().text().trimmed().toStdString() +
                           " [" + sql.left(80).toStdString() + "]");
    return q;
}

const QString kVerdictNumber = QStringLiteral(
    "CASE m.verdict WHEN 'good' THEN 1 WHEN 'rework' THEN 2 WHEN 'scrap' THEN 3 ELSE 0 END");

/// The machine's runs, newest first, with their latest status.
std::vector<std::pair<std::int64_t, std::string>> runsOf(Database& db, const std::string& machine) {
    QSqlQuery q = select(db,
                         QStringLiteral("SELECT r.id, COALESCE((SELECT e.status FROM run_ends e WHERE e.run_id = r.id"
                                        " ORDER BY e.seq DESC LIMIT 1), r.status) FROM runs r WHERE r.machine = ?"
                                        " ORDER BY r.id DESC"),
                         {QString::fromStdString(machine)});
    std::vector<std::pair<std::int64_t, std::string>> runs;
    while (q.next())
        runs.emplace_back(q.value(0).toLongLong(), q.value(1).toString().toStdString());
    return runs;
}

void readDayParts(Database& db, PlantMachineRow& row, const PlantQuery& query) {
    QSqlQuery q = select(
        db,
        QStringLiteral("SELECT w, COUNT(*) FROM (SELECT p.id AS id, MAX(") + kVerdictNumber +
            QStringLiteral(") AS w FROM runs r JOIN parts p ON p.run_id = r.id LEFT JOIN measurements m ON"
                           " m.part_id = p.id WHERE r.machine = ? AND p.recorded_at >= ? AND p.recorded_at < ?"
                           " GROUP BY p.id) t GROUP BY w"),
        {QString::fromStdString(row.machine), QString::fromStdString(query.dayFromUtc),
         QString::fromStdString(query.dayToUtc)});
    while (q.next()) {
        const std::int64_t n = q.value(1).toLongLong();
        row.dayPartCount += n;
        switch (q.value(0).toInt()) {
            case 1:
                row.dayParts.good += n;
                break;
            case 2:
                row.dayParts.rework += n;
                break;
            case 3:
                row.dayParts.scrap += n;
                break;
            default:
                break;
        }
    }
}

/// One reading as the overview collects it, newest first.
struct Reading {
    std::int64_t runId = 0, partNumber = 0;
    double valueMm = 0.0, timeS = 0.0, zMm = 0.0, nominalMm = 0.0;
    int verdict = 0;
    std::optional<double> lowerMm, upperMm;
};

/// The newest `wanted` plausible readings of every point of the machine's runs, newest first.
std::map<int, std::vector<Reading>> newestReadings(Database& db, const std::vector<std::int64_t>& runs,
                                                   std::size_t wanted) {
    std::map<int, std::vector<Reading>> points;
    const auto enough = [&] {
        return !points.empty() &&
               std::all_of(points.begin(), points.end(), [&](const auto& p) { return p.second.size() >= wanted; });
    };
    const auto slice = static_cast<std::int64_t>(wanted) + 16;
    for (const std::int64_t run : runs) {
        QSqlQuery top = select(db, QStringLiteral("SELECT MAX(part_number) FROM parts WHERE run_id = ?"), {id(run)});
        if (!top.next() || top.value(0).isNull()) continue;
        for (std::int64_t hi = top.value(0).toLongLong(); hi > 0 && !enough(); hi -= slice) {
            QSqlQuery q = select(
                db,
                QStringLiteral("SELECT p.part_number, m.point_index, m.measured_mm, m.measured_s, ") + kVerdictNumber +
                    QStringLiteral(", m.lower_limit_mm, m.upper_limit_mm, m.nominal_mm, m.z_mm FROM parts p JOIN"
                                   " measurements m ON m.part_id = p.id WHERE p.run_id = ? AND p.part_number > ? AND"
                                   " p.part_number <= ? AND ") +
                    plausibleReadingCondition() + QStringLiteral(" ORDER BY p.part_number DESC"),
                {id(run), id(hi - slice), id(hi)});
            while (q.next()) {
                std::vector<Reading>& list = points[q.value(1).toInt()];
                if (list.size() >= wanted) continue;
                Reading r{run,
                          q.value(0).toLongLong(),
                          q.value(2).toDouble(),
                          q.value(3).toDouble(),
                          q.value(8).toDouble(),
                          q.value(7).toDouble(),
                          q.value(4).toInt(),
                          {},
                          {}};
                if (!q.value(5).isNull()) r.lowerMm = q.value(5).toDouble();
                if (!q.value(6).isNull()) r.upperMm = q.value(6).toDouble();
                list.push_back(r);
            }
        }
        if (enough()) break;
    }
    return points;
}

/// The readings of one point in production order, as queryPointReadings gives them.
PointReadings pointReadingsOf(int point, const std::vector<Reading>& newestFirst) {
    PointReadings p;
    p.pointIndex = point;
    for (auto it = newestFirst.rbegin(); it != newestFirst.rend(); ++it) {
        p.valuesMm.push_back(it->valueMm);
        p.partNumbers.push_back(it->partNumber);
        p.timesS.push_back(it->timeS);
        if (it->verdict == 1) ++p.verdicts.good;
        if (it->verdict == 2) ++p.verdicts.rework;
        if (it->verdict == 3) ++p.verdicts.scrap;
    }
    if (!newestFirst.empty()) {
        p.zMm = newestFirst.back().zMm;
        p.nominalMm = newestFirst.back().nominalMm;
    }
    for (const Reading& r : newestFirst)
        if (r.lowerMm && r.upperMm) {
            p.lowerLimitMm = r.lowerMm;
            p.upperLimitMm = r.upperMm;
            p.limitsNominalMm = r.nominalMm;
            break;
        }
    return p;
}

void readAlarms(Database& db, PlantMachineRow& row) {
    if (!row.newestRunOpen || !row.newestRunId) return;
    QSqlQuery count = select(db, QStringLiteral("SELECT COUNT(*) FROM alarms WHERE run_id = ?"), {id(*row.newestRunId)});
    row.openAlarmCount = count.next() ? count.value(0).toLongLong() : 0;
    QSqlQuery q = select(db,
                         QStringLiteral("SELECT part_number, kind, message, recorded_at FROM alarms WHERE run_id = ?"
                                        " ORDER BY id DESC LIMIT 5"),
                         {id(*row.newestRunId)});
    while (q.next()) {
        PlantAlarm a;
        a.runId = *row.newestRunId;
        if (!q.value(0).isNull()) a.partNumber = q.value(0).toLongLong();
        a.kind = q.value(1).toString().toStdString();
        a.message = q.value(2).toString().toStdString();
        a.recordedAt = q.value(3).toString().toStdString();
        row.openAlarms.push_back(std::move(a));
    }
}

PlantMachineRow readMachine(Database& db, const std::string& machine, const PlantQuery& query) {
    PlantMachineRow row;
    row.machine = machine;
    const auto runs = runsOf(db, machine);
    std::vector<std::int64_t> runIds;
    for (const auto& [runId, status] : runs)
        runIds.push_back(runId);
    if (!runs.empty()) {
        row.newestRunId = runs.front().first;
        row.newestRunStatus = runs.front().second;
        row.newestRunOpen = row.newestRunStatus == "running";
    }
    for (const std::int64_t run : runIds) {
        QSqlQuery q = select(db, QStringLiteral("SELECT MAX(recorded_at) FROM parts WHERE run_id = ?"), {id(run)});
        if (q.next() && !q.value(0).isNull()) {
            row.lastPartAt = q.value(0).toString().toStdString();
            break;
        }
    }
    QSqlQuery t = select(db,
                         QStringLiteral("SELECT reported_at, backlog_parts, journal_bytes, journal_limit_bytes FROM"
                                        " plant_terminal_status WHERE machine = ?"),
                         {QString::fromStdString(machine)});
    if (t.next())
        row.terminal = TerminalReportRow{t.value(0).toString().toStdString(), t.value(1).toLongLong(),
                                         t.value(2).toLongLong(), t.value(3).toLongLong()};
    t.finish();
    readDayParts(db, row, query);
    for (const auto& [point, readings] : newestReadings(db, runIds, 2 * static_cast<std::size_t>(query.windowParts)))
        row.recent.push_back(pointReadingsOf(point, readings));
    readAlarms(db, row);
    return row;
}

}  // namespace

std::vector<PlantMachineRow> queryPlant(Database& db, const PlantQuery& query) {
    if (query.windowParts < 2 || query.windowParts > 100000)
        throw StorageError("the capability window of " + std::to_string(query.windowParts) +
                           " parts is outside 2 .. 100000");
    db.migrate(historySchema());
    std::vector<std::string> machines;
    {
        QSqlQuery q = select(db, QStringLiteral("SELECT machine FROM runs GROUP BY machine UNION SELECT machine FROM"
                                                " plant_terminal_status ORDER BY 1"));
        while (q.next())
            machines.push_back(q.value(0).toString().toStdString());
    }
    std::vector<PlantMachineRow> rows;
    for (const std::string& machine : machines)
        rows.push_back(readMachine(db, machine, query));
    return rows;
}

}  // namespace tt::storage
