#include "core/storage/history_store.h"

#include "core/storage/adaptation_json.h"
#include "core/storage/plant_roles.h"

#include <array>
#include <cmath>

#include <QJsonDocument>
#include <QSqlQuery>
#include <QUuid>
#include <QVariant>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

namespace tt::storage {

namespace {

/// Refuses a resume point that is not one of the run's stored parts (a history altered outside
/// TrueTurn), before any arithmetic on it can overflow.
void requireStoredPart(const core::RunSummary& run, std::int64_t lastPart) {
    const std::int64_t newest = run.lastPartNumber.value_or(0);
    if (lastPart < 0 || lastPart > newest)
        throw StorageError("run " + std::to_string(run.runId) + ": the stored resume point (last part " +
                           std::to_string(lastPart) + ") is outside the run's parts 0 .. " + std::to_string(newest) +
                           "; the history file was altered");
}

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QVariant id(std::int64_t v) {
    return QVariant(static_cast<qlonglong>(v));
}

void exec(Database& db, const char* sql, const QVariantList& bindings = {}) {
    db.exec(QString::fromLatin1(sql), bindings);
}

QVariant finiteOrNull(double v) {
    return std::isfinite(v) ? QVariant(v) : QVariant(QMetaType::fromType<double>());
}

/// The rejection of a stored point, its kind and numbers; none for an accepted point and for rows
/// stored before the kind was kept (only their words are).
core::Notice storedRejection(const core::PointMeasurementRecord& p, std::int64_t partNumber, const QVariant& kind,
                             const std::array<QVariant, 3>& numbers) {
    if (p.accepted || kind.isNull()) return {};
    core::Notice n(core::noticeKindFromName(kind.toString().toStdString()), partNumber);
    if (!n) return {};
    n.point = p.pointIndex + 1;
    n.zMm = p.zMm;
    double* fields[] = {&n.value, &n.reference, &n.limit};
    for (std::size_t i = 0; i < numbers.size(); ++i)
        if (!numbers[i].isNull()) *fields[i] = numbers[i].toDouble();
    return n;
}

}  // namespace

SchemaModule historySchema() {
    SchemaModule module{QStringLiteral("history"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("runs, parts, corrections, measurements, controller state, alarms"), [](Database& db) {
             exec(db,
                  "CREATE TABLE runs (id {pk}, started_at TEXT NOT NULL, finished_at TEXT, status TEXT NOT NULL,"
                  " preset TEXT NOT NULL, controller TEXT NOT NULL, delay_parts INTEGER NOT NULL,"
                  " nominal_diameter_mm {real} NOT NULL, part_length_mm {real} NOT NULL, settings TEXT NOT NULL)");
             exec(db,
                  "CREATE TABLE run_points (run_id {bigint} NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
                  " point_index INTEGER NOT NULL, z_mm {real} NOT NULL, PRIMARY KEY (run_id, point_index))");
             exec(db,
                  "CREATE TABLE parts (id {pk}, run_id {bigint} NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
                  " part_number {bigint} NOT NULL, started_s {real} NOT NULL, finished_s {real} NOT NULL,"
                  " recorded_at TEXT NOT NULL, UNIQUE (run_id, part_number))");
             exec(db,
                  "CREATE TABLE corrections (part_id {bigint} NOT NULL REFERENCES parts(id) ON DELETE CASCADE,"
                  " point_index INTEGER NOT NULL, z_mm {real} NOT NULL, computed_mm {real} NOT NULL,"
                  " applied_mm {real} NOT NULL, PRIMARY KEY (part_id, point_index))");
             exec(db,
                  "CREATE TABLE measurements (part_id {bigint} NOT NULL REFERENCES parts(id) ON DELETE CASCADE,"
                  " point_index INTEGER NOT NULL, z_mm {real} NOT NULL, measured_mm {real}, nominal_mm {real} NOT NULL,"
                  " accepted INTEGER NOT NULL, reason TEXT NOT NULL, measured_s {real} NOT NULL,"
                  " PRIMARY KEY (part_id, point_index))");
             exec(db,
                  "CREATE TABLE run_state (run_id {bigint} PRIMARY KEY REFERENCES runs(id) ON DELETE CASCADE,"
                  " last_part {bigint} NOT NULL, controller_kind TEXT NOT NULL, controller_state TEXT NOT NULL)");
             exec(db,
                  "CREATE TABLE alarms (id {pk}, run_id {bigint} NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
                  " part_number {bigint}, time_s {real} NOT NULL, kind TEXT NOT NULL, message TEXT NOT NULL,"
                  " recorded_at TEXT NOT NULL)");
             exec(db, "CREATE INDEX parts_by_run ON parts (run_id, part_number)");
             exec(db, "CREATE INDEX alarms_by_run ON alarms (run_id, id)");
         }});
    module.migrations.push_back(
        {2, QStringLiteral("why a measured value was not used, as a kind with its numbers"), [](Database& db) {
             exec(db, "ALTER TABLE measurements ADD COLUMN reason_kind TEXT");
             exec(db, "ALTER TABLE measurements ADD COLUMN reason_value {real}");
             exec(db, "ALTER TABLE measurements ADD COLUMN reason_reference {real}");
             exec(db, "ALTER TABLE measurements ADD COLUMN reason_limit {real}");
         }});
    module.migrations.push_back(
        {3,
         QStringLiteral(
             "tolerance verdicts (good, rework, scrap) with their limits; the machine of a run; readings by point"),
         [](Database& db) {
             exec(db, "ALTER TABLE measurements ADD COLUMN verdict TEXT");
             exec(db, "ALTER TABLE measurements ADD COLUMN lower_limit_mm {real}");
             exec(db, "ALTER TABLE measurements ADD COLUMN upper_limit_mm {real}");
             exec(db, "ALTER TABLE runs ADD COLUMN machine TEXT NOT NULL DEFAULT ''");
             // The report of one control point over the whole history reads the measurements of that point.
             exec(db, "CREATE INDEX measurements_by_point ON measurements (point_index, part_id)");
         }});
    module.migrations.push_back(
        {4, QStringLiteral("the report of one point reads its readings from one covering index"), [](Database& db) {
             // Every column the statistics of one control point read (measurement_query.cpp), so the report over
             // a whole history scans this index alone and joins the parts for their order; it replaces the
             // narrower index by point.
             exec(db,
                  "CREATE INDEX measurements_point_values ON measurements (point_index, part_id, measured_mm,"
                  " measured_s, reason_kind, verdict)");
             exec(db, "DROP INDEX measurements_by_point");
         }});
    module.migrations.push_back(
        {5,
         QStringLiteral(
             "the plant-wide history: runs known by a unique id, alarms by the terminal's sequence, the ends "
             "of runs as rows, the terminals' reports, the plant overview's indexes; on PostgreSQL the "
             "roles of the terminals and of the quality engineer with row-level security by machine"),
         [](Database& db) {
             // A run keeps its id wherever it is copied (a terminal's journal -> the plant database): the natural
             // key of a forwarded row is (run_uid, part, point), so a batch sent twice inserts nothing twice.
             exec(db, "ALTER TABLE runs ADD COLUMN run_uid TEXT");
             exec(db, "CREATE UNIQUE INDEX runs_by_uid ON runs (run_uid)");
             exec(db, "CREATE INDEX runs_by_machine ON runs (machine, id)");
             exec(db, "ALTER TABLE alarms ADD COLUMN terminal_seq {bigint}");
             exec(db, "CREATE UNIQUE INDEX alarms_by_terminal_seq ON alarms (run_id, terminal_seq)");
             // A run's end as a row (the plant database's roles insert and never update history).
             exec(db,
                  "CREATE TABLE run_ends (run_id {bigint} NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
                  " seq INTEGER NOT NULL, status TEXT NOT NULL, finished_at TEXT NOT NULL, PRIMARY KEY (run_id, seq))");
             // The parts of a machine stored on one day (the plant overview's counts).
             exec(db, "CREATE INDEX parts_by_run_time ON parts (run_id, recorded_at)");
             // What each terminal last said about itself: its journal's backlog (the plant overview shows it).
             exec(db,
                  "CREATE TABLE plant_terminal_status (machine TEXT PRIMARY KEY, reported_at TEXT NOT NULL,"
                  " backlog_parts {bigint} NOT NULL, journal_bytes {bigint} NOT NULL,"
                  " journal_limit_bytes {bigint} NOT NULL)");
             if (db.isPostgres()) createPlantRoles(db);
         }});
    return module;
}

SchemaModule adaptationSchema() {
    SchemaModule module{QStringLiteral("adaptation"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("what the adaptive loop did: fallback, adaptations, proposals, refused designs"),
         [](Database& db) {
             exec(
                 db,
                 "CREATE TABLE adaptations (id {pk}, run_id {bigint} NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
                 " part_number {bigint} NOT NULL, time_s {real} NOT NULL, kind TEXT NOT NULL, reason TEXT NOT NULL,"
                 " fallback TEXT NOT NULL, fallback_weight {real}, model_before TEXT NOT NULL, model_after TEXT,"
                 " margins TEXT NOT NULL, applied INTEGER NOT NULL, notice_kind TEXT NOT NULL, notice_part {bigint},"
                 " notice_other {bigint}, notice_point INTEGER, notice_value {real}, notice_reference {real},"
                 " notice_limit {real}, notice_cause TEXT NOT NULL, message TEXT NOT NULL, recorded_at TEXT NOT NULL)");
             exec(db, "CREATE INDEX adaptations_by_run ON adaptations (run_id, id)");
         }});
    return module;
}

std::string encodeControllerValues(const std::vector<double>& values) {
    std::string out;
    char buffer[40];
    for (double v : values) {
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        if (!out.empty()) out += ' ';
        out += buffer;
    }
    return out;
}

std::vector<double> decodeControllerValues(const std::string& textValue) {
    std::vector<double> values;
    const char* p = textValue.c_str();
    while (*p) {
        while (*p == ' ')
            ++p;
        if (!*p) break;
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(p, &end);
        if (end == p)
            throw StorageError("the stored controller state is damaged near '" + std::string(p).substr(0, 20) + "'");
        values.push_back(v);
        p = end;
    }
    return values;
}

SqlHistoryStore::SqlHistoryStore(Database& database) : m_db(database) {
    m_db.migrate(historySchema());
    m_db.migrate(adaptationSchema());
}

std::int64_t SqlHistoryStore::beginRun(const core::RunDescription& run) {
    std::int64_t runId = 0;
    m_db.transaction([&] {
        QSqlQuery insert =
            m_db.exec(QStringLiteral(
                          "INSERT INTO runs (started_at, status, preset, controller, delay_parts, nominal_diameter_mm,"
                          " part_length_mm, settings, machine, run_uid) VALUES (?, 'running', ?, ?, ?, ?, ?, ?, ?, ?)"),
                      {utcNowText(), text(run.preset), text(run.controller), run.delayParts, run.nominalDiameterMm,
                       run.partLengthMm, text(run.settingsJson), text(run.machine),
                       QUuid::createUuid().toString(QUuid::WithoutBraces)});
        runId = m_db.lastInsertId(insert);
        for (std::size_t i = 0; i < run.pointZMm.size(); ++i)
            m_db.exec(QStringLiteral("INSERT INTO run_points (run_id, point_index, z_mm) VALUES (?, ?, ?)"),
                      {id(runId), static_cast<int>(i), run.pointZMm[i]});
    });
    return runId;
}

qint64 SqlHistoryStore::partId(std::int64_t runId, std::int64_t partNumber) {
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT id FROM parts WHERE run_id = ? AND part_number = ?"),
                            {id(runId), id(partNumber)});
    if (!q.next())
        throw StorageError("part " + std::to_string(partNumber) + " of run " + std::to_string(runId) +
                           " is not stored, so its diameters cannot be");
    return q.value(0).toLongLong();
}

void SqlHistoryStore::writeMeasurement(qint64 part, const core::PartMeasurementRecord& m) {
    m_db.exec(QStringLiteral("DELETE FROM measurements WHERE part_id = ?"), {part});
    for (const core::PointMeasurementRecord& p : m.points)
        m_db.exec(
            QStringLiteral("INSERT INTO measurements (part_id, point_index, z_mm, measured_mm, nominal_mm,"
                           " accepted, reason, measured_s, reason_kind, reason_value, reason_reference,"
                           " reason_limit, verdict, lower_limit_mm, upper_limit_mm)"
                           " VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
            {part, p.pointIndex, p.zMm, nullable<double>(p.measuredMm), p.nominalMm, p.accepted ? 1 : 0, text(p.reason),
             m.timeS,
             p.rejection ? QVariant(QString::fromStdString(core::noticeKindName(p.rejection.kind)))
                         : QVariant(QMetaType::fromType<QString>()),
             finiteOrNull(p.rejection.value), finiteOrNull(p.rejection.reference), finiteOrNull(p.rejection.limit),
             p.verdict ? QVariant(QString::fromStdString(core::toleranceVerdictName(*p.verdict)))
                       : QVariant(QMetaType::fromType<QString>()),
             p.tolerance ? QVariant(p.tolerance->lowerLimitMm()) : QVariant(QMetaType::fromType<double>()),
             p.tolerance ? QVariant(p.tolerance->upperLimitMm()) : QVariant(QMetaType::fromType<double>())});
}

void SqlHistoryStore::recordPart(std::int64_t runId, const core::PartCompletionRecord& part) {
    m_db.transaction([&] {
        QSqlQuery insert =
            m_db.exec(QStringLiteral("INSERT INTO parts (run_id, part_number, started_s, finished_s, recorded_at)"
                                     " VALUES (?, ?, ?, ?, ?)"),
                      {id(runId), id(part.partNumber), part.startedS, part.finishedS, utcNowText()});
        const qint64 partRow = m_db.lastInsertId(insert);
        for (const core::PointCorrectionRecord& c : part.corrections)
            m_db.exec(QStringLiteral("INSERT INTO corrections (part_id, point_index, z_mm, computed_mm, applied_mm)"
                                     " VALUES (?, ?, ?, ?, ?)"),
                      {partRow, c.pointIndex, c.zMm, c.computedMm, c.appliedMm});
        if (part.usedMeasurement)
            writeMeasurement(partId(runId, part.usedMeasurement->partNumber), *part.usedMeasurement);
        m_db.exec(
            QStringLiteral("INSERT INTO run_state (run_id, last_part, controller_kind, controller_state)"
                           " VALUES (?, ?, ?, ?) ON CONFLICT (run_id) DO UPDATE SET last_part = excluded.last_part,"
                           " controller_kind = excluded.controller_kind,"
                           " controller_state = excluded.controller_state"),
            {id(runId), id(part.partNumber), text(part.controllerState.kind),
             text(encodeControllerValues(part.controllerState.values))});
    });
}

void SqlHistoryStore::recordMeasurement(std::int64_t runId, const core::PartMeasurementRecord& measurement) {
    m_db.transaction([&] { writeMeasurement(partId(runId, measurement.partNumber), measurement); });
}

void SqlHistoryStore::recordAlarm(std::int64_t runId, const core::AlarmRecord& alarm) {
    insertAlarm(runId, alarm);
}

std::int64_t SqlHistoryStore::insertAlarm(std::int64_t runId, const core::AlarmRecord& alarm) {
    QSqlQuery insert =
        m_db.exec(QStringLiteral("INSERT INTO alarms (run_id, part_number, time_s, kind, message, recorded_at)"
                                 " VALUES (?, ?, ?, ?, ?, ?)"),
                  {id(runId), nullable<qlonglong>(alarm.partNumber), alarm.timeS, text(alarm.kind), text(alarm.message),
                   utcNowText()});
    return m_db.lastInsertId(insert);
}

void SqlHistoryStore::finishRun(std::int64_t runId, const std::string& status) {
    m_db.exec(QStringLiteral("UPDATE runs SET status = ?, finished_at = ? WHERE id = ?"),
              {text(status), utcNowText(), id(runId)});
}

std::vector<core::RunSummary> SqlHistoryStore::runs() {
    std::vector<core::RunSummary> out;
    QSqlQuery q = m_db.exec(QStringLiteral(
        "SELECT r.id, r.started_at, COALESCE(e.finished_at, r.finished_at), COALESCE(e.status, r.status),"
        " r.preset, r.controller, r.delay_parts, r.nominal_diameter_mm, r.part_length_mm, r.settings,"
        " (SELECT COUNT(*) FROM parts p WHERE p.run_id = r.id),"
        " (SELECT MAX(part_number) FROM parts p WHERE p.run_id = r.id), r.machine"
        " FROM runs r LEFT JOIN run_ends e ON e.run_id = r.id"
        " AND e.seq = (SELECT MAX(seq) FROM run_ends x WHERE x.run_id = r.id) ORDER BY r.id DESC"));
    while (q.next()) {
        core::RunSummary s;
        s.runId = q.value(0).toLongLong();
        s.startedAt = q.value(1).toString().toStdString();
        s.finishedAt = q.value(2).isNull() ? std::string() : q.value(2).toString().toStdString();
        s.status = q.value(3).toString().toStdString();
        s.description.preset = q.value(4).toString().toStdString();
        s.description.controller = q.value(5).toString().toStdString();
        s.description.delayParts = q.value(6).toInt();
        s.description.nominalDiameterMm = q.value(7).toDouble();
        s.description.partLengthMm = q.value(8).toDouble();
        s.description.settingsJson = q.value(9).toString().toStdString();
        s.partCount = q.value(10).toLongLong();
        if (!q.value(11).isNull()) s.lastPartNumber = q.value(11).toLongLong();
        s.description.machine = q.value(12).toString().toStdString();
        out.push_back(std::move(s));
    }
    q.finish();
    for (core::RunSummary& s : out) {
        QSqlQuery points = m_db.exec(
            QStringLiteral("SELECT z_mm FROM run_points WHERE run_id = ? ORDER BY point_index"), {id(s.runId)});
        while (points.next())
            s.description.pointZMm.push_back(points.value(0).toDouble());
    }
    return out;
}

std::optional<core::RunSummary> SqlHistoryStore::run(std::int64_t runId) {
    for (core::RunSummary& s : runs())
        if (s.runId == runId) return s;
    return std::nullopt;
}

std::vector<core::StoredPart> SqlHistoryStore::loadParts(std::int64_t runId, std::int64_t fromPartNumber) {
    std::vector<core::StoredPart> parts;
    std::map<qint64, std::size_t> byRow;
    {
        QSqlQuery q = m_db.exec(QStringLiteral("SELECT id, part_number, started_s, finished_s FROM parts"
                                               " WHERE run_id = ? AND part_number >= ? ORDER BY part_number"),
                                {id(runId), id(fromPartNumber)});
        while (q.next()) {
            byRow[q.value(0).toLongLong()] = parts.size();
            parts.push_back({q.value(1).toLongLong(), q.value(2).toDouble(), q.value(3).toDouble(), {}, std::nullopt});
        }
    }
    {
        QSqlQuery q = m_db.exec(
            QStringLiteral("SELECT c.part_id, c.point_index, c.z_mm, c.computed_mm, c.applied_mm FROM corrections c"
                           " JOIN parts p ON p.id = c.part_id WHERE p.run_id = ? AND p.part_number >= ?"
                           " ORDER BY p.part_number, c.point_index"),
            {id(runId), id(fromPartNumber)});
        while (q.next()) {
            const auto it = byRow.find(q.value(0).toLongLong());
            if (it == byRow.end()) continue;
            parts[it->second].corrections.push_back(
                {q.value(1).toInt(), q.value(2).toDouble(), q.value(3).toDouble(), q.value(4).toDouble()});
        }
    }
    {
        QSqlQuery q = m_db.exec(
            QStringLiteral("SELECT m.part_id, m.point_index, m.z_mm, m.measured_mm, m.nominal_mm, m.accepted, m.reason,"
                           " m.measured_s, m.reason_kind, m.reason_value, m.reason_reference, m.reason_limit,"
                           " m.verdict, m.lower_limit_mm, m.upper_limit_mm"
                           " FROM measurements m JOIN parts p ON p.id = m.part_id"
                           " WHERE p.run_id = ? AND p.part_number >= ? ORDER BY p.part_number, m.point_index"),
            {id(runId), id(fromPartNumber)});
        while (q.next()) {
            const auto it = byRow.find(q.value(0).toLongLong());
            if (it == byRow.end()) continue;
            core::StoredPart& part = parts[it->second];
            if (!part.measurement)
                part.measurement = core::PartMeasurementRecord{part.partNumber, q.value(7).toDouble(), {}};
            core::PointMeasurementRecord p;
            p.pointIndex = q.value(1).toInt();
            p.zMm = q.value(2).toDouble();
            if (!q.value(3).isNull()) p.measuredMm = q.value(3).toDouble();
            p.nominalMm = q.value(4).toDouble();
            p.accepted = q.value(5).toInt() != 0;
            p.reason = q.value(6).toString().toStdString();
            p.rejection = storedRejection(p, part.partNumber, q.value(8), {q.value(9), q.value(10), q.value(11)});
            if (!q.value(12).isNull()) p.verdict = core::toleranceVerdictFromName(q.value(12).toString().toStdString());
            if (!q.value(13).isNull() && !q.value(14).isNull())
                p.tolerance = core::ToleranceZone{p.nominalMm, q.value(14).toDouble() - p.nominalMm,
                                                  q.value(13).toDouble() - p.nominalMm};
            part.measurement->points.push_back(std::move(p));
        }
    }
    return parts;
}

std::vector<core::StoredPart> SqlHistoryStore::parts(std::int64_t runId) {
    return loadParts(runId, std::numeric_limits<std::int64_t>::min());
}

void SqlHistoryStore::recordAdaptation(std::int64_t runId, const core::AdaptationRecord& a) {
    auto json = [](const QJsonObject& o) { return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)); };
    const core::Notice& n = a.notice;
    m_db.exec(
        QStringLiteral("INSERT INTO adaptations (run_id, part_number, time_s, kind, reason, fallback, fallback_weight,"
                       " model_before, model_after, margins, applied, notice_kind, notice_part, notice_other,"
                       " notice_point, notice_value, notice_reference, notice_limit, notice_cause, message,"
                       " recorded_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
        {id(runId),
         id(a.partNumber),
         a.timeS,
         text(a.kind),
         text(a.reason),
         text(a.fallback),
         finiteOrNull(a.fallbackWeight),
         json(plantModelJson(a.modelBefore)),
         a.modelAfter ? QVariant(json(plantModelJson(*a.modelAfter))) : QVariant(QMetaType::fromType<QString>()),
         json(marginsJson(a.margins)),
         a.applied ? 1 : 0,
         text(core::noticeKindName(n.kind)),
         id(n.part),
         id(n.otherPart),
         n.point,
         finiteOrNull(n.value),
         finiteOrNull(n.reference),
         finiteOrNull(n.limit),
         text(n.cause),
         text(core::describe(n)),
         utcNowText()});
}

std::vector<core::AdaptationRecord> SqlHistoryStore::adaptations(std::int64_t runId) {
    auto object = [](const QVariant& v) { return QJsonDocument::fromJson(v.toString().toUtf8()).object(); };
    auto number = [](const QVariant& v) {
        return v.isNull() ? std::numeric_limits<double>::quiet_NaN() : v.toDouble();
    };
    std::vector<core::AdaptationRecord> out;
    QSqlQuery q = m_db.exec(
        QStringLiteral("SELECT part_number, time_s, kind, reason, fallback, fallback_weight, model_before, model_after,"
                       " margins, applied, notice_kind, notice_part, notice_other, notice_point, notice_value,"
                       " notice_reference, notice_limit, notice_cause FROM adaptations WHERE run_id = ? ORDER BY id"),
        {id(runId)});
    while (q.next()) {
        core::AdaptationRecord a;
        a.partNumber = q.value(0).toLongLong();
        a.timeS = q.value(1).toDouble();
        a.kind = q.value(2).toString().toStdString();
        a.reason = q.value(3).toString().toStdString();
        a.fallback = q.value(4).toString().toStdString();
        a.fallbackWeight = number(q.value(5));
        try {
            a.modelBefore = plantModelFromJson(object(q.value(6)));
            if (!q.value(7).isNull()) a.modelAfter = plantModelFromJson(object(q.value(7)));
        } catch (const std::invalid_argument& e) {
            throw StorageError("run " + std::to_string(runId) + ": a stored adaptation is damaged (" + e.what() + ")");
        }
        a.margins = marginsFromJson(object(q.value(8)));
        a.applied = q.value(9).toInt() != 0;
        a.notice = core::Notice(core::noticeKindFromName(q.value(10).toString().toStdString()),
                                q.value(11).toLongLong(), q.value(12).toLongLong());
        a.notice.point = q.value(13).toInt();
        a.notice.value = number(q.value(14));
        a.notice.reference = number(q.value(15));
        a.notice.limit = number(q.value(16));
        a.notice.cause = q.value(17).toString().toStdString();
        out.push_back(std::move(a));
    }
    return out;
}

std::vector<core::AlarmRecord> SqlHistoryStore::alarms(std::int64_t runId) {
    std::vector<core::AlarmRecord> out;
    QSqlQuery q =
        m_db.exec(QStringLiteral("SELECT part_number, time_s, kind, message FROM alarms WHERE run_id = ? ORDER BY id"),
                  {id(runId)});
    while (q.next()) {
        core::AlarmRecord a;
        if (!q.value(0).isNull()) a.partNumber = q.value(0).toLongLong();
        a.timeS = q.value(1).toDouble();
        a.kind = q.value(2).toString().toStdString();
        a.message = q.value(3).toString().toStdString();
        out.push_back(std::move(a));
    }
    return out;
}

std::optional<core::ResumePoint> SqlHistoryStore::resumePoint(std::optional<std::int64_t> runId) {
    std::optional<core::RunSummary> summary;
    if (runId) {
        summary = run(*runId);
        if (!summary) throw StorageError("there is no run " + std::to_string(*runId) + " in the history");
    } else {
        const auto all = runs();
        if (all.empty()) return std::nullopt;
        summary = all.front();
    }
    QSqlQuery q =
        m_db.exec(QStringLiteral("SELECT last_part, controller_kind, controller_state FROM run_state WHERE run_id = ?"),
                  {id(summary->runId)});
    if (!q.next()) return std::nullopt;
    core::ResumePoint point;
    point.run = *summary;
    point.lastPartNumber = q.value(0).toLongLong();
    requireStoredPart(*summary, point.lastPartNumber);
    point.controllerState.kind = q.value(1).toString().toStdString();
    point.controllerState.values = decodeControllerValues(q.value(2).toString().toStdString());
    q.finish();
    point.pendingParts = loadParts(summary->runId, point.lastPartNumber - summary->description.delayParts + 1);
    return point;
}

}  // namespace tt::storage
