#include "core/storage/journal_batch.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <algorithm>
#include <set>

#include "core/storage/history_journal.h"

namespace tt::storage {

namespace {

/// The columns of a run copied to the plant (run_uid last: the natural key).
const QString kRunColumns = QStringLiteral(
    "started_at, finished_at, status, preset, controller, delay_parts, nominal_diameter_mm, part_length_mm, settings,"
    " machine, run_uid");
constexpr int kRunColumnCount = 11;
/// The columns of a reading after part_id.
const QString kMeasurementColumns = QStringLiteral(
    "point_index, z_mm, measured_mm, nominal_mm, accepted, reason, measured_s, reason_kind, reason_value,"
    " reason_reference, reason_limit, verdict, lower_limit_mm, upper_limit_mm");
constexpr int kMeasurementColumnCount = 14;
/// Bound values per INSERT (PostgreSQL allows 65535, SQLite 32766).
constexpr int kMaxBindingsPerStatement = 30000;

QVariant id(std::int64_t v) {
    return QVariant(static_cast<qlonglong>(v));
}

/// A prepared statement on the journal, executed many times.
class Prepared {
public:
    Prepared(Database& db, const QString& sql) : m_query(db.connection()), m_sql(sql) {
        m_query.setForwardOnly(true);
        if (!m_query.prepare(db.dialectSql(sql))) fail();
    }
    QSqlQuery& run(const QVariantList& bindings) {
        for (int i = 0; i < bindings.size(); ++i)
            m_query.bindValue(i, bindings[i]);
        if (!m_query.exec()) fail();
        return m_query;
    }

private:
    [[noreturn]] void fail() {
        throw StorageError("reading the journal failed: " + m_query.lastError().text().trimmed().toStdString() + " [" +
                           m_sql.left(80).toStdString() + "]");
    }
    QSqlQuery m_query;
    QString m_sql;
};

QVariantList rowOf(const QSqlQuery& q, int from, int count) {
    QVariantList row;
    row.reserve(count);
    for (int i = from; i < from + count; ++i)
        row << q.value(i);
    return row;
}

/// Reads the rows the outbox entries name.
class BatchReader {
public:
    explicit BatchReader(Database& db)
        : m_db(db),
          m_part(db, QStringLiteral("SELECT id, started_s, finished_s, recorded_at FROM parts WHERE run_id = ? AND "
                                    "part_number = ?")),
          m_corrections(db, QStringLiteral("SELECT point_index, z_mm, computed_mm, applied_mm FROM corrections WHERE "
                                           "part_id = ? ORDER BY point_index")),
          m_measurements(db, QStringLiteral("SELECT m.") + QString(kMeasurementColumns).replace(
                                                                QStringLiteral(", "), QStringLiteral(", m.")) +
                                 QStringLiteral(" FROM measurements m JOIN parts p ON p.id = m.part_id WHERE "
                                                "p.run_id = ? AND p.part_number = ? ORDER BY m.point_index")),
          m_alarm(db, QStringLiteral("SELECT part_number, time_s, kind, message, recorded_at FROM alarms WHERE id = ?")) {
    }

    QString runUid(std::int64_t runId, JournalBatch& batch) {
        if (const auto it = m_uids.find(runId); it != m_uids.end()) return it->second;
        QSqlQuery q = m_db.exec(QStringLiteral("SELECT ") + kRunColumns + QStringLiteral(" FROM runs WHERE id = ?"),
                                {id(runId)});
        if (!q.next()) throw StorageError("the journal's outbox names run " + std::to_string(runId) + ", which it lacks");
        JournalBatch::Run run;
        run.columns = rowOf(q, 0, kRunColumnCount);
        run.uid = q.value(kRunColumnCount - 1).toString();
        q.finish();
        if (run.uid.isEmpty())
            throw StorageError("run " + std::to_string(runId) + " of the journal has no unique id; it was not sent");
        QSqlQuery points = m_db.exec(
            QStringLiteral("SELECT point_index, z_mm FROM run_points WHERE run_id = ? ORDER BY point_index"),
            {id(runId)});
        while (points.next())
            run.points.push_back(rowOf(points, 0, 2));
        m_uids[runId] = run.uid;
        batch.runs.push_back(std::move(run));
        return m_uids[runId];
    }

    void part(std::int64_t runId, std::int64_t partNumber, JournalBatch& batch) {
        JournalBatch::Part part{runUid(runId, batch), partNumber, {}, {}};
        QSqlQuery& q = m_part.run({id(runId), id(partNumber)});
        if (!q.next()) return;  // deleted by hand from the journal: nothing to send
        const qlonglong rowId = q.value(0).toLongLong();
        part.columns = rowOf(q, 1, 3);
        q.finish();
        QSqlQuery& c = m_corrections.run({rowId});
        while (c.next())
            part.corrections.push_back(rowOf(c, 0, 4));
        c.finish();
        batch.parts.push_back(std::move(part));
    }

    void measurement(std::int64_t runId, std::int64_t partNumber, JournalBatch& batch) {
        JournalBatch::Measurement m{runUid(runId, batch), partNumber, {}};
        QSqlQuery& q = m_measurements.run({id(runId), id(partNumber)});
        while (q.next())
            m.points.push_back(rowOf(q, 0, kMeasurementColumnCount));
        q.finish();
        if (!m.points.empty()) batch.measurements.push_back(std::move(m));
    }

    void alarm(std::int64_t runId, std::int64_t alarmId, JournalBatch& batch) {
        JournalBatch::Alarm a{runUid(runId, batch), alarmId, {}};
        QSqlQuery& q = m_alarm.run({id(alarmId)});
        if (!q.next()) return;
        a.columns = rowOf(q, 0, 5);
        q.finish();
        batch.alarms.push_back(std::move(a));
    }

private:
    Database& m_db;
    Prepared m_part, m_corrections, m_measurements, m_alarm;
    std::map<std::int64_t, QString> m_uids;
};

/// INSERT of many rows of `columns` values each, in statements of at most kMaxBindingsPerStatement values:
/// `head` ("INSERT INTO t (a, b)") + " VALUES (?, ?), ..." + `tail` (" ON CONFLICT ... DO NOTHING").
void insertRows(Database& db, const QString& head, const QString& tail, int columns,
                const std::vector<QVariantList>& rows) {
    QStringList marks;
    for (int i = 0; i < columns; ++i)
        marks << QStringLiteral("?");
    const QString tuple = QLatin1Char('(') + marks.join(QStringLiteral(", ")) + QLatin1Char(')');
    if (!db.isPostgres()) {
        // SQLite: one prepared row, executed per row (Qt binds SQLite's positional values by a search over the
        // statement's parameters, quadratic in a multi-row statement; a row costs microseconds in a transaction).
        if (rows.empty()) return;
        QSqlQuery q(db.connection());
        const QString sql = head + QStringLiteral(" VALUES ") + tuple + tail;
        if (!q.prepare(sql))
            throw StorageError("database statement failed: " + q.lastError().text().toStdString() + " [" +
                               sql.left(80).toStdString() + "]");
        for (const QVariantList& row : rows) {
            for (int i = 0; i < row.size(); ++i)
                q.bindValue(i, row[i]);
            if (!q.exec())
                throw StorageError("database statement failed: " + q.lastError().text().toStdString() + " [" +
                                   sql.left(80).toStdString() + "]");
        }
        return;
    }
    const std::size_t perStatement = static_cast<std::size_t>(std::max(1, kMaxBindingsPerStatement / columns));
    for (std::size_t first = 0; first < rows.size(); first += perStatement) {
        const std::size_t n = std::min(perStatement, rows.size() - first);
        QString sql = head + QStringLiteral(" VALUES ");
        QVariantList bindings;
        bindings.reserve(static_cast<qsizetype>(n) * columns);
        for (std::size_t i = 0; i < n; ++i) {
            if (i) sql += QStringLiteral(", ");
            sql += tuple;
            bindings += rows[first + i];
        }
        db.exec(sql + tail, bindings);
    }
}

/// The plant's ids of the batch's runs (inserted when missing) by uid.
std::map<QString, qlonglong> plantRuns(Database& plant, const JournalBatch& batch) {
    std::map<QString, qlonglong> ids;
    for (const JournalBatch::Run& run : batch.runs) {
        insertRows(plant, QStringLiteral("INSERT INTO runs (") + kRunColumns + QLatin1Char(')'),
                   QStringLiteral(" ON CONFLICT (run_uid) DO NOTHING"), kRunColumnCount, {run.columns});
        QSqlQuery q = plant.exec(QStringLiteral("SELECT id FROM runs WHERE run_uid = ?"), {run.uid});
        if (!q.next())
            throw StorageError("the plant database did not take run " + run.uid.toStdString() + " of machine '" +
                               run.columns.value(9).toString().toStdString() +
                               "': this login may not write that machine's history (its administrator lists the "
                               "login's machines in plant_terminals)");
        const qlonglong runId = q.value(0).toLongLong();
        q.finish();
        ids[run.uid] = runId;
        std::vector<QVariantList> points;
        for (const QVariantList& p : run.points)
            points.push_back(QVariantList{runId} + p);
        insertRows(plant, QStringLiteral("INSERT INTO run_points (run_id, point_index, z_mm)"),
                   QStringLiteral(" ON CONFLICT (run_id, point_index) DO NOTHING"), 3, points);
    }
    return ids;
}

/// The plant's part ids of the parts the batch names, by (run uid, part number).
std::map<std::pair<QString, std::int64_t>, qlonglong> plantParts(Database& plant, const JournalBatch& batch,
                                                                  const std::map<QString, qlonglong>& runs) {
    std::map<QString, std::pair<std::int64_t, std::int64_t>> ranges;  // per run: first and last part named
    const auto name = [&ranges](const QString& uid, std::int64_t part) {
        auto [it, fresh] = ranges.try_emplace(uid, part, part);
        if (!fresh) it->second = {std::min(it->second.first, part), std::max(it->second.second, part)};
    };
    for (const JournalBatch::Part& p : batch.parts)
        name(p.runUid, p.partNumber);
    for (const JournalBatch::Measurement& m : batch.measurements)
        name(m.runUid, m.partNumber);
    std::map<std::pair<QString, std::int64_t>, qlonglong> ids;
    for (const auto& [uid, range] : ranges) {
        QSqlQuery q = plant.exec(
            QStringLiteral("SELECT id, part_number FROM parts WHERE run_id = ? AND part_number BETWEEN ? AND ?"),
            {runs.at(uid), id(range.first), id(range.second)});
        while (q.next())
            ids[{uid, q.value(1).toLongLong()}] = q.value(0).toLongLong();
    }
    return ids;
}

void writeReport(Database& plant, const TerminalReport& s) {
    plant.exec(QStringLiteral("INSERT INTO plant_terminal_status (machine, reported_at, backlog_parts, journal_bytes,"
                              " journal_limit_bytes) VALUES (?, ?, ?, ?, ?) ON CONFLICT (machine) DO UPDATE SET"
                              " reported_at = excluded.reported_at, backlog_parts = excluded.backlog_parts,"
                              " journal_bytes = excluded.journal_bytes,"
                              " journal_limit_bytes = excluded.journal_limit_bytes"),
               {s.machine, utcNowText(), id(s.backlogParts), id(s.journalBytes), id(s.journalLimitBytes)});
}

void writeRows(Database& plant, const JournalBatch& batch) {
    const std::map<QString, qlonglong> runs = plantRuns(plant, batch);
    std::vector<QVariantList> parts;
    for (const JournalBatch::Part& p : batch.parts)
        parts.push_back(QVariantList{runs.at(p.runUid), id(p.partNumber)} + p.columns);
    insertRows(plant, QStringLiteral("INSERT INTO parts (run_id, part_number, started_s, finished_s, recorded_at)"),
               QStringLiteral(" ON CONFLICT (run_id, part_number) DO NOTHING"), 5, parts);
    const auto partIds = plantParts(plant, batch, runs);
    const auto partId = [&partIds](const QString& uid, std::int64_t part) {
        const auto it = partIds.find({uid, part});
        if (it == partIds.end())
            throw StorageError("part " + std::to_string(part) + " of run " + uid.toStdString() +
                               " is not in the plant database, so its readings cannot be");
        return it->second;
    };
    std::vector<QVariantList> corrections, readings;
    for (const JournalBatch::Part& p : batch.parts)
        for (const QVariantList& c : p.corrections)
            corrections.push_back(QVariantList{partId(p.runUid, p.partNumber)} + c);
    for (const JournalBatch::Measurement& m : batch.measurements)
        for (const QVariantList& r : m.points)
            readings.push_back(QVariantList{partId(m.runUid, m.partNumber)} + r);
    insertRows(plant, QStringLiteral("INSERT INTO corrections (part_id, point_index, z_mm, computed_mm, applied_mm)"),
               QStringLiteral(" ON CONFLICT (part_id, point_index) DO NOTHING"), 5, corrections);
    insertRows(plant, QStringLiteral("INSERT INTO measurements (part_id, ") + kMeasurementColumns + QLatin1Char(')'),
               QStringLiteral(" ON CONFLICT (part_id, point_index) DO NOTHING"), kMeasurementColumnCount + 1, readings);
    std::vector<QVariantList> alarms, ends;
    for (const JournalBatch::Alarm& a : batch.alarms)
        alarms.push_back(QVariantList{runs.at(a.runUid), id(a.seq)} + a.columns);
    for (const JournalBatch::End& e : batch.ends)
        ends.push_back({runs.at(e.runUid), id(e.seq), e.status, e.finishedAt});
    insertRows(plant,
               QStringLiteral("INSERT INTO alarms (run_id, terminal_seq, part_number, time_s, kind, message, "
                              "recorded_at)"),
               QStringLiteral(" ON CONFLICT (run_id, terminal_seq) DO NOTHING"), 7, alarms);
    insertRows(plant, QStringLiteral("INSERT INTO run_ends (run_id, seq, status, finished_at)"),
               QStringLiteral(" ON CONFLICT (run_id, seq) DO NOTHING"), 4, ends);
}

}  // namespace

JournalBatch readJournalBatch(Database& journal, std::int64_t afterSeq, int maxParts) {
    JournalBatch batch;
    QSqlQuery entries = journal.exec(
        QStringLiteral("SELECT seq, kind, run_id, item, status, at FROM journal_outbox WHERE seq > ? ORDER BY seq"
                       " LIMIT ?"),
        {id(afterSeq), 8 * std::max(1, maxParts)});
    struct Entry {
        std::int64_t seq, runId, item;
        QString kind, status, at;
    };
    std::vector<Entry> list;
    int parts = 0;
    while (entries.next()) {
        Entry e{entries.value(0).toLongLong(), entries.value(2).toLongLong(), entries.value(3).toLongLong(),
                entries.value(1).toString(),   entries.value(4).toString(),   entries.value(5).toString()};
        if (e.kind == u"part" && parts == maxParts) break;
        if (e.kind == u"part") ++parts;
        list.push_back(std::move(e));
    }
    entries.finish();
    if (list.empty()) return batch;
    BatchReader reader(journal);
    for (const Entry& e : list) {
        if (e.kind == u"run")
            reader.runUid(e.runId, batch);
        else if (e.kind == u"part")
            reader.part(e.runId, e.item, batch);
        else if (e.kind == u"measurement")
            reader.measurement(e.runId, e.item, batch);
        else if (e.kind == u"alarm")
            reader.alarm(e.runId, e.item, batch);
        else if (e.kind == u"end")
            batch.ends.push_back({reader.runUid(e.runId, batch), e.item, e.status, e.at});
    }
    batch.firstSeq = list.front().seq;
    batch.lastSeq = list.back().seq;
    return batch;
}

void writePlantBatch(Database& plant, const JournalBatch& batch, const std::optional<TerminalReport>& status) {
    plant.transaction([&] {
        writeRows(plant, batch);
        if (status) writeReport(plant, *status);
    });
}

void writeTerminalReport(Database& plant, const TerminalReport& status) {
    plant.transaction([&] { writeReport(plant, status); });
}

std::int64_t journalSentSeq(Database& journal) {
    QSqlQuery q = journal.exec(QStringLiteral("SELECT value FROM journal_state WHERE key = 'sent_seq'"));
    return q.next() ? q.value(0).toLongLong() : 0;
}

void markJournalSent(Database& journal, std::int64_t seq) {
    journal.transaction([&] {
        if (seq <= journalSentSeq(journal)) return;
        journal.exec(QStringLiteral("INSERT INTO journal_state (key, value) VALUES ('sent_seq', ?)"
                                    " ON CONFLICT (key) DO UPDATE SET value = excluded.value"),
                     {QString::number(seq)});
    });
}

std::int64_t journalBacklogParts(Database& journal) {
    QSqlQuery q = journal.exec(QStringLiteral("SELECT COUNT(*) FROM journal_outbox WHERE kind = 'part' AND seq > ?"),
                               {id(journalSentSeq(journal))});
    return q.next() ? q.value(0).toLongLong() : 0;
}

std::int64_t trimJournal(Database& journal, std::int64_t keepBytes, int maxParts) {
    if (journalUsedBytes(journal) <= keepBytes) return 0;
    std::int64_t deleted = 0;
    journal.transaction([&] {
        const std::int64_t sent = journalSentSeq(journal);
        // Parts whose part and readings the plant committed, outside each run's resume window.
        QSqlQuery q = journal.exec(
            QStringLiteral(
                "SELECT p.id, o.run_id, o.item FROM journal_outbox o JOIN parts p ON p.run_id = o.run_id"
                " AND p.part_number = o.item WHERE o.kind = 'part' AND o.seq <= ? AND EXISTS (SELECT 1 FROM"
                " journal_outbox m WHERE m.run_id = o.run_id AND m.kind = 'measurement' AND m.item = o.item AND"
                " m.seq <= ?) AND o.item < (SELECT s.last_part - r.delay_parts FROM run_state s JOIN runs r ON"
                " r.id = s.run_id WHERE s.run_id = o.run_id) ORDER BY o.seq LIMIT ?"),
            {id(sent), id(sent), maxParts});
        std::vector<QVariantList> parts;
        while (q.next())
            parts.push_back(rowOf(q, 0, 3));
        q.finish();
        for (const QVariantList& part : parts) {
            journal.exec(QStringLiteral("DELETE FROM parts WHERE id = ?"), {part[0]});
            journal.exec(QStringLiteral("DELETE FROM journal_outbox WHERE run_id = ? AND kind IN ('part',"
                                        " 'measurement') AND item = ?"),
                         {part[1], part[2]});
        }
        deleted = static_cast<std::int64_t>(parts.size());
        QSqlQuery a = journal.exec(
            QStringLiteral("SELECT seq, item FROM journal_outbox WHERE kind = 'alarm' AND seq <= ? ORDER BY seq LIMIT ?"),
            {id(sent), maxParts});
        std::vector<QVariantList> alarms;
        while (a.next())
            alarms.push_back(rowOf(a, 0, 2));
        a.finish();
        for (const QVariantList& alarm : alarms) {
            journal.exec(QStringLiteral("DELETE FROM alarms WHERE id = ?"), {alarm[1]});
            journal.exec(QStringLiteral("DELETE FROM journal_outbox WHERE seq = ?"), {alarm[0]});
        }
    });
    return deleted;
}

}  // namespace tt::storage
