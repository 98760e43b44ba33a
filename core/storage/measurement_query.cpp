#include "core/storage/measurement_query.h"

#include <QSqlQuery>
#include <QStringList>

#include "core/storage/history_store.h"

namespace tt::storage {

std::vector<MeasurementRow> queryMeasurements(Database& db, const MeasurementFilter& filter) {
    db.migrate(historySchema());
    QStringList where{QStringLiteral("m.measured_mm IS NOT NULL"),
                      QStringLiteral("(m.reason_kind IS NULL OR m.reason_kind NOT IN ('implausible', 'not-finite', "
                                     "'not-a-number'))")};
    QVariantList bindings;
    if (filter.runId) {
        where << QStringLiteral("r.id = ?");
        bindings << QVariant(static_cast<qlonglong>(*filter.runId));
    }
    if (filter.pointIndex) {
        where << QStringLiteral("m.point_index = ?");
        bindings << *filter.pointIndex;
    }
    if (filter.fromUtc) {
        where << QStringLiteral("p.recorded_at >= ?");
        bindings << QString::fromStdString(*filter.fromUtc);
    }
    if (filter.toUtc) {
        where << QStringLiteral("p.recorded_at < ?");
        bindings << QString::fromStdString(*filter.toUtc);
    }
    if (filter.machine) {
        where << QStringLiteral("r.machine = ?");
        bindings << QString::fromStdString(*filter.machine);
    }
    QSqlQuery q = db.exec(
        QStringLiteral("SELECT r.id, r.machine, p.part_number, p.recorded_at, m.measured_s, m.point_index, m.z_mm,"
                       " m.nominal_mm, m.measured_mm, m.accepted, m.verdict, m.lower_limit_mm, m.upper_limit_mm"
                       " FROM measurements m JOIN parts p ON p.id = m.part_id JOIN runs r ON r.id = p.run_id"
                       " WHERE ") +
            where.join(QStringLiteral(" AND ")) + QStringLiteral(" ORDER BY r.id, p.part_number, m.point_index"),
        bindings);
    std::vector<MeasurementRow> rows;
    while (q.next()) {
        MeasurementRow row;
        row.runId = q.value(0).toLongLong();
        row.machine = q.value(1).toString().toStdString();
        row.partNumber = q.value(2).toLongLong();
        row.recordedAt = q.value(3).toString().toStdString();
        row.timeS = q.value(4).toDouble();
        row.pointIndex = q.value(5).toInt();
        row.zMm = q.value(6).toDouble();
        row.nominalMm = q.value(7).toDouble();
        row.measuredMm = q.value(8).toDouble();
        row.accepted = q.value(9).toInt() != 0;
        if (!q.value(10).isNull()) row.verdict = core::toleranceVerdictFromName(q.value(10).toString().toStdString());
        if (!q.value(11).isNull()) row.lowerLimitMm = q.value(11).toDouble();
        if (!q.value(12).isNull()) row.upperLimitMm = q.value(12).toDouble();
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace tt::storage
