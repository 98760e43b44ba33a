#include "core/storage/measurement_query.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/storage/history_store.h"
#include "core/storage/numeric_rows.h"

namespace tt::storage {

namespace {}  // namespace

QString plausibleReadingCondition() {
    return QStringLiteral(
        "m.measured_mm IS NOT NULL AND (m.reason_kind IS NULL OR m.reason_kind NOT IN"
        " ('implausible', 'not-finite', 'not-a-number'))");
}

namespace {

/// The FROM and WHERE of the plausible readings a filter chooses (a value measured and not refused as
/// implausible or not a number), with their bindings.
struct Selection {
    QString from;
    QString where;
    QVariantList bindings;
};

/// How the readings meet their parts.
enum class PartsJoin {
    AsNeeded,    ///< only when the filter names runs, machines or dates
    Always,      ///< the parts' numbers and order are read
    PartsFirst,  ///< walk the parts in their index order (run, part) and look up each one's reading: the first or
                 ///< last reading in production order (ORDER BY ... LIMIT 1) without visiting the others
};

Selection selectionOf(const MeasurementFilter& filter, PartsJoin join) {
    QStringList where{plausibleReadingCondition()};
    Selection s;
    if (filter.runId) {
        where << QStringLiteral("p.run_id = ?");
        s.bindings << QVariant(static_cast<qlonglong>(*filter.runId));
    }
    if (filter.pointIndex) {
        where << QStringLiteral("m.point_index = ?");
        s.bindings << *filter.pointIndex;
    }
    if (filter.fromUtc) {
        where << QStringLiteral("p.recorded_at >= ?");
        s.bindings << QString::fromStdString(*filter.fromUtc);
    }
    if (filter.toUtc) {
        where << QStringLiteral("p.recorded_at < ?");
        s.bindings << QString::fromStdString(*filter.toUtc);
    }
    if (filter.machine) {
        where << QStringLiteral("r.machine = ?");
        s.bindings << QString::fromStdString(*filter.machine);
    }
    if (join == PartsJoin::PartsFirst) {
        // SQLite keeps the order of a CROSS JOIN; PostgreSQL plans it like any inner join.
        s.from = QStringLiteral(" FROM parts p CROSS JOIN measurements m");
        where << QStringLiteral("p.id = m.part_id");
    } else {
        s.from = QStringLiteral(" FROM measurements m");
        if (join == PartsJoin::Always || filter.runId || filter.fromUtc || filter.toUtc || filter.machine)
            s.from += QStringLiteral(" JOIN parts p ON p.id = m.part_id");
    }
    if (filter.machine) s.from += QStringLiteral(" JOIN runs r ON r.id = p.run_id");
    s.where = QStringLiteral(" WHERE ") + where.join(QStringLiteral(" AND "));
    return s;
}

/// A read whose rows are taken once, front to back: SQLite then keeps no copy of the rows already read.
QSqlQuery select(Database& db, const QString& sql, const QVariantList& bindings) {
    QSqlQuery q(db.connection());
    if (!db.isPostgres()) q.setForwardOnly(true);
    bool ok = q.prepare(db.dialectSql(sql));
    if (ok) {
        for (const QVariant& value : bindings)
            q.addBindValue(value);
        ok = q.exec();
    }
    if (!ok)
        throw StorageError("reading the history failed: " + q.lastError().text().trimmed().toStdString() + " [" +
                           sql.left(80).toStdString() + "]");
    return q;
}

/// The verdicts of the chosen readings counted per point in SQL.
std::map<int, core::VerdictCounts> verdictCounts(Database& db, const MeasurementFilter& filter) {
    const Selection s = selectionOf(filter, PartsJoin::AsNeeded);
    QSqlQuery q = select(db,
                         QStringLiteral("SELECT m.point_index, m.verdict, COUNT(*)") + s.from + s.where +
                             QStringLiteral(" AND m.verdict IS NOT NULL GROUP BY m.point_index, m.verdict"),
                         s.bindings);
    std::map<int, core::VerdictCounts> counts;
    while (q.next()) {
        const std::optional<core::ToleranceVerdict> verdict =
            core::toleranceVerdictFromName(q.value(1).toString().toStdString());
        if (!verdict) continue;  // a name this program does not know is not counted (as in the rows' reading)
        core::VerdictCounts& c = counts[q.value(0).toInt()];
        const std::int64_t n = q.value(2).toLongLong();
        if (*verdict == core::ToleranceVerdict::Good)
            c.good += n;
        else if (*verdict == core::ToleranceVerdict::Rework)
            c.rework += n;
        else
            c.scrap += n;
    }
    return counts;
}

/// Where the point is and its nominal (its first chosen reading), and the tolerance of its latest chosen reading
/// that has one.
void readPointFacts(Database& db, const MeasurementFilter& filter, PointReadings& point) {
    MeasurementFilter one = filter;
    one.pointIndex = point.pointIndex;
    const Selection s = selectionOf(one, PartsJoin::PartsFirst);
    {
        QSqlQuery q = select(db,
                             QStringLiteral("SELECT m.z_mm, m.nominal_mm") + s.from + s.where +
                                 QStringLiteral(" ORDER BY p.run_id, p.part_number LIMIT 1"),
                             s.bindings);
        if (q.next()) {
            point.zMm = q.value(0).toDouble();
            point.nominalMm = q.value(1).toDouble();
        }
    }
    QSqlQuery q = select(db,
                         QStringLiteral("SELECT m.lower_limit_mm, m.upper_limit_mm, m.nominal_mm") + s.from + s.where +
                             QStringLiteral(" AND m.lower_limit_mm IS NOT NULL AND m.upper_limit_mm IS NOT NULL"
                                            " ORDER BY p.run_id DESC, p.part_number DESC LIMIT 1"),
                         s.bindings);
    if (q.next()) {
        point.lowerLimitMm = q.value(0).toDouble();
        point.upperLimitMm = q.value(1).toDouble();
        point.limitsNominalMm = q.value(2).toDouble();
    }
}

}  // namespace

namespace {

/// One reading as the one-pass read takes it.
struct PointRow {
    std::int64_t runId = 0;
    std::int64_t partNumber = 0;
    double timeS = 0.0;
    double valueMm = 0.0;
    int verdict = 0;  ///< 1 good, 2 rework, 3 scrap, 0 none
};

/// The rows of one point in production order (run, part), as the statistics take them; with a window of the
/// filter (lastReadings, skipNewest) only those.
PointReadings pointReadingsOf(int pointIndex, std::vector<PointRow>& rows, const MeasurementFilter& filter) {
    const auto before = [](const PointRow& a, const PointRow& b) {
        return a.runId != b.runId ? a.runId < b.runId : a.partNumber < b.partNumber;
    };
    // Parts are numbered as they are stored, so the rows usually come in order already.
    if (!std::is_sorted(rows.begin(), rows.end(), before)) std::sort(rows.begin(), rows.end(), before);
    auto last = rows.end() - static_cast<std::ptrdiff_t>(
                                 std::min<std::int64_t>(filter.skipNewest, static_cast<std::int64_t>(rows.size())));
    auto first = rows.begin();
    if (filter.lastReadings && last - first > *filter.lastReadings)
        first = last - static_cast<std::ptrdiff_t>(*filter.lastReadings);
    PointReadings p;
    p.pointIndex = pointIndex;
    p.valuesMm.reserve(static_cast<std::size_t>(last - first));
    p.partNumbers.reserve(static_cast<std::size_t>(last - first));
    p.timesS.reserve(static_cast<std::size_t>(last - first));
    for (auto it = first; it != last; ++it) {
        const PointRow& r = *it;
        p.valuesMm.push_back(r.valueMm);
        p.partNumbers.push_back(r.partNumber);
        if (p.runStarts.empty() || p.runStarts.back().runId != r.runId)
            p.runStarts.push_back({r.runId, p.valuesMm.size() - 1});
        p.timesS.push_back(r.timeS);
        if (r.verdict == 1) ++p.verdicts.good;
        if (r.verdict == 2) ++p.verdicts.rework;
        if (r.verdict == 3) ++p.verdicts.scrap;
    }
    return p;
}

}  // namespace

std::vector<PointReadings> queryPointReadings(Database& db, const MeasurementFilter& filter) {
    db.migrate(historySchema());
    std::map<int, std::vector<PointRow>> rows;
    {
        const Selection s = selectionOf(filter, PartsJoin::Always);
        // The verdict as a small number in the same pass (no string per reading, no second scan). No ORDER BY:
        // the join streams from the covering index in part-id order (PostgreSQL: a merge join) instead of a
        // sort of every row spilling to disk; the rows are put in production order here.
        NumericRows q(db,
                      QStringLiteral("SELECT m.point_index, p.run_id, p.part_number, m.measured_s, m.measured_mm,"
                                     " CASE m.verdict WHEN 'good' THEN 1 WHEN 'rework' THEN 2"
                                     " WHEN 'scrap' THEN 3 ELSE 0 END") +
                          s.from + s.where,
                      s.bindings);
        std::vector<PointRow>* current = nullptr;
        int currentIndex = -1;
        while (q.next()) {
            const auto index = static_cast<int>(q.integer(0));
            if (!current || index != currentIndex) {
                current = &rows[index];
                currentIndex = index;
            }
            current->push_back({q.integer(1), q.integer(2), q.real(3), q.real(4), static_cast<int>(q.integer(5))});
        }
    }
    std::vector<PointReadings> points;
    for (auto& [index, pointRows] : rows) {
        points.push_back(pointReadingsOf(index, pointRows, filter));
        std::vector<PointRow>().swap(pointRows);
        if (points.back().valuesMm.empty()) {
            points.pop_back();
            continue;
        }
        readPointFacts(db, filter, points.back());
    }
    return points;
}

std::vector<PointAggregate> queryPointAggregates(Database& db, const MeasurementFilter& filter) {
    db.migrate(historySchema());
    const Selection s = selectionOf(filter, PartsJoin::AsNeeded);
    // Two passes (the mean, then the squared deviations from it): no cancellation of sum(x^2) - n mean^2.
    QSqlQuery q = select(
        db,
        QStringLiteral("WITH a AS (SELECT m.point_index AS point_index, COUNT(*) AS n, AVG(m.measured_mm) AS mean_mm,"
                       " MIN(m.measured_mm) AS min_mm, MAX(m.measured_mm) AS max_mm") +
            s.from + s.where +
            QStringLiteral(" GROUP BY m.point_index) SELECT a.point_index, a.n, a.mean_mm, a.min_mm, a.max_mm,"
                           " SUM((m.measured_mm - a.mean_mm) * (m.measured_mm - a.mean_mm))") +
            s.from + QStringLiteral(" JOIN a ON a.point_index = m.point_index") + s.where +
            QStringLiteral(" GROUP BY a.point_index, a.n, a.mean_mm, a.min_mm, a.max_mm ORDER BY a.point_index"),
        s.bindings + s.bindings);
    std::vector<PointAggregate> out;
    while (q.next()) {
        PointAggregate a;
        a.pointIndex = q.value(0).toInt();
        a.count = q.value(1).toLongLong();
        a.meanMm = q.value(2).toDouble();
        a.minMm = q.value(3).toDouble();
        a.maxMm = q.value(4).toDouble();
        a.sigmaOverallMm = a.count > 1 ? std::sqrt(q.value(5).toDouble() / static_cast<double>(a.count - 1)) : 0.0;
        out.push_back(a);
    }
    q.finish();
    const std::map<int, core::VerdictCounts> verdicts = verdictCounts(db, filter);
    for (PointAggregate& a : out)
        if (const auto it = verdicts.find(a.pointIndex); it != verdicts.end()) a.verdicts = it->second;
    return out;
}

core::VerdictCounts queryPartVerdicts(Database& db, const MeasurementFilter& filter) {
    db.migrate(historySchema());
    const Selection s = selectionOf(filter, PartsJoin::AsNeeded);
    QSqlQuery q = select(db,
                         QStringLiteral("SELECT w, COUNT(*) FROM (SELECT m.part_id AS part_id, MAX(CASE m.verdict WHEN"
                                        " 'good' THEN 1 WHEN 'rework' THEN 2 WHEN 'scrap' THEN 3 ELSE 0 END) AS w") +
                             s.from + s.where + QStringLiteral(" GROUP BY m.part_id) t GROUP BY w"),
                         s.bindings);
    core::VerdictCounts counts;
    while (q.next()) {
        const std::int64_t n = q.value(1).toLongLong();
        switch (q.value(0).toInt()) {
            case 1:
                counts.good += n;
                break;
            case 2:
                counts.rework += n;
                break;
            case 3:
                counts.scrap += n;
                break;
            default:
                break;
        }
    }
    return counts;
}

std::vector<MeasurementRow> queryMeasurements(Database& db, const MeasurementFilter& filter) {
    db.migrate(historySchema());
    const Selection s = selectionOf(filter, PartsJoin::Always);
    QSqlQuery q = select(
        db,
        QStringLiteral("SELECT p.run_id, r.machine, p.part_number, p.recorded_at, m.measured_s, m.point_index, m.z_mm,"
                       " m.nominal_mm, m.measured_mm, m.accepted, m.verdict, m.lower_limit_mm, m.upper_limit_mm") +
            s.from + (filter.machine ? QString() : QStringLiteral(" JOIN runs r ON r.id = p.run_id")) + s.where +
            QStringLiteral(" ORDER BY p.run_id, p.part_number, m.point_index"),
        s.bindings);
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
