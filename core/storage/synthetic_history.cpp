#include "core/storage/synthetic_history.h"

#include <QDateTime>
#include <QSqlQuery>
#include <QTimeZone>
#include <charconv>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/common/tolerance.h"

namespace tt::storage {

namespace {

/// Parts written by one INSERT statement (their readings: this times the points).
constexpr std::int64_t kPartsPerStatement = 1000;
/// One part every minute.
constexpr double kPartCycleS = 60.0;

void requireRange(const char* name, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi))
        throw std::invalid_argument(std::string("synthetic history: ") + name + " = " + std::to_string(value) +
                                    " is outside " + std::to_string(lo) + " .. " + std::to_string(hi));
}

void appendNumber(std::string& sql, double v) {
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    sql.append(buffer, r.ptr);
}

void appendInteger(std::string& sql, std::int64_t v) {
    char buffer[24];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    sql.append(buffer, r.ptr);
}

std::int64_t maxId(Database& db, const char* table) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT MAX(id) FROM %1").arg(QLatin1String(table)));
    return q.next() && !q.value(0).isNull() ? q.value(0).toLongLong() : 0;
}

/// The diameter process of one control point of one run: offset + AR(1) drift + white scatter, mm.
struct PointProcess {
    double offsetMm = 0.0;
    double driftMm = 0.0;
};

class Generator {
public:
    Generator(Database& db, const SyntheticHistorySpec& spec)
        : m_db(db),
          m_spec(spec),
          m_random(spec.seed),
          m_zone{spec.nominalMm, spec.upperDeviationMm, spec.lowerDeviationMm} {}

    SyntheticHistoryResult write() {
        SyntheticHistoryResult result;
        if (m_db.isPostgres()) {
            // Part ids are given here: no other writer may take one meanwhile (they wait for the commit).
            m_db.exec(QStringLiteral("LOCK TABLE runs, parts IN SHARE ROW EXCLUSIVE MODE"));
        }
        m_nextPartId = maxId(m_db, "parts") + 1;
        const std::int64_t perRun = m_spec.parts / m_spec.runs;
        for (int r = 0; r < m_spec.runs; ++r) {
            const std::int64_t count = perRun + (r < m_spec.parts % m_spec.runs ? 1 : 0);
            const std::int64_t runId = writeRun(r, count);
            if (r == 0) result.firstRunId = runId;
            result.lastRunId = runId;
        }
        if (m_db.isPostgres()) {
            m_db.exec(
                QStringLiteral("SELECT setval(pg_get_serial_sequence('parts', 'id'), (SELECT MAX(id) FROM parts))"));
        }
        result.parts = m_spec.parts;
        result.readings = m_spec.parts * m_spec.points;
        return result;
    }

private:
    double zMm(int point) const { return 10.0 + 130.0 * point / std::max(1, m_spec.points - 1); }

    std::int64_t writeRun(int runIndex, std::int64_t count) {
        const int machine = runIndex % m_spec.machines;
        if (m_spec.machinesInParallel) m_partsWritten = m_machineParts[machine];
        const QString started = partTime(m_partsWritten);
        const QString finished = partTime(m_partsWritten + count);
        QSqlQuery insert = m_db.exec(
            QStringLiteral("INSERT INTO runs (started_at, finished_at, status, preset, controller, delay_parts,"
                           " nominal_diameter_mm, part_length_mm, settings, machine)"
                           " VALUES (?, ?, 'finished', 'synthetic', 'lqg', 1, ?, 150.0, '{}', ?)"),
            {started, finished, m_spec.nominalMm, QStringLiteral("lathe-%1").arg(machine + 1)});
        const std::int64_t runId = m_db.lastInsertId(insert);
        for (int p = 0; p < m_spec.points; ++p)
            m_db.exec(QStringLiteral("INSERT INTO run_points (run_id, point_index, z_mm) VALUES (?, ?, ?)"),
                      {QVariant(static_cast<qlonglong>(runId)), p, zMm(p)});
        std::vector<PointProcess> processes(static_cast<std::size_t>(m_spec.points));
        std::normal_distribution<double> offset(0.0, 0.002);
        for (PointProcess& process : processes)
            process.offsetMm = -0.0105 + offset(m_random);
        for (std::int64_t first = 0; first < count; first += kPartsPerStatement)
            writeParts(runId, first, std::min(kPartsPerStatement, count - first), processes);
        m_machineParts[machine] = m_partsWritten;
        return runId;
    }

    QString partTime(std::int64_t partIndex) const {
        return QDateTime::fromSecsSinceEpoch(m_spec.firstPartEpochS + partIndex * static_cast<qint64>(kPartCycleS),
                                             QTimeZone::utc())
            .toUTC()  // "...Z" as every stored time (utcNowText), so times compare as text
            .toString(Qt::ISODateWithMs);
    }

    void writeParts(std::int64_t runId, std::int64_t firstPart, std::int64_t count,
                    std::vector<PointProcess>& processes) {
        std::string parts = "INSERT INTO parts (id, run_id, part_number, started_s, finished_s, recorded_at) VALUES ";
        std::string readings =
            "INSERT INTO measurements (part_id, point_index, z_mm, measured_mm, nominal_mm, accepted, reason,"
            " measured_s, reason_kind, reason_value, reason_reference, reason_limit, verdict, lower_limit_mm,"
            " upper_limit_mm) VALUES ";
        for (std::int64_t i = 0; i < count; ++i) {
            const std::int64_t partNumber = firstPart + i + 1;
            const std::int64_t partId = m_nextPartId++;
            const double startedS = static_cast<double>(partNumber - 1) * kPartCycleS;
            if (i > 0) parts += ',';
            parts += '(';
            appendInteger(parts, partId);
            parts += ',';
            appendInteger(parts, runId);
            parts += ',';
            appendInteger(parts, partNumber);
            parts += ',';
            appendNumber(parts, startedS);
            parts += ',';
            appendNumber(parts, startedS + kPartCycleS - 5.0);
            parts += ",'";
            parts += partTime(m_partsWritten).toStdString();
            parts += "')";
            for (int p = 0; p < m_spec.points; ++p) {
                if (i > 0 || p > 0) readings += ',';
                appendReading(readings, partId, p, startedS + kPartCycleS, processes[static_cast<std::size_t>(p)]);
            }
            ++m_partsWritten;
        }
        m_db.exec(QString::fromStdString(parts));
        m_db.exec(QString::fromStdString(readings));
    }

    void appendReading(std::string& sql, std::int64_t partId, int point, double measuredS, PointProcess& process) {
        process.driftMm = 0.95 * process.driftMm + m_innovation(m_random);
        const bool implausible = m_uniform(m_random) < m_spec.implausibleFraction;
        const double measuredMm = implausible
                                      ? m_spec.nominalMm + 0.5
                                      : m_spec.nominalMm + process.offsetMm + process.driftMm + m_scatter(m_random);
        const auto text = [&sql](const char* value) { sql += value; };
        sql += '(';
        appendInteger(sql, partId);
        sql += ',';
        appendInteger(sql, point);
        sql += ',';
        appendNumber(sql, zMm(point));
        sql += ',';
        appendNumber(sql, measuredMm);
        sql += ',';
        appendNumber(sql, m_spec.nominalMm);
        if (implausible) {
            text(",0,'implausible reading',");
            appendNumber(sql, measuredS);
            text(",'implausible',");
            appendNumber(sql, measuredMm);
            sql += ',';
            appendNumber(sql, m_spec.nominalMm);
            text(",0.2,NULL,");
        } else {
            text(",1,'',");
            appendNumber(sql, measuredS);
            text(",NULL,NULL,NULL,NULL,'");
            text(core::toleranceVerdictName(core::outerDiameterVerdict(m_zone, measuredMm)).c_str());
            text("',");
        }
        appendNumber(sql, m_zone.lowerLimitMm());
        sql += ',';
        appendNumber(sql, m_zone.upperLimitMm());
        sql += ')';
    }

    Database& m_db;
    SyntheticHistorySpec m_spec;
    std::mt19937_64 m_random;
    core::ToleranceZone m_zone;
    std::normal_distribution<double> m_innovation{0.0, 0.0003};
    std::normal_distribution<double> m_scatter{0.0, 0.003};
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
    std::int64_t m_nextPartId = 1;
    std::int64_t m_partsWritten = 0;
    std::map<int, std::int64_t> m_machineParts;  ///< parts written per machine (machinesInParallel)
};

}  // namespace

SyntheticHistoryResult writeSyntheticHistory(Database& db, const SyntheticHistorySpec& spec) {
    requireRange("parts", static_cast<double>(spec.parts), 1, static_cast<double>(kMaxSyntheticParts));
    requireRange("points", spec.points, 1, 16);
    requireRange("runs", spec.runs, 1, std::min<double>(1000, static_cast<double>(spec.parts)));
    requireRange("machines", spec.machines, 1, 100);
    requireRange("nominal diameter, mm", spec.nominalMm, 0.1, core::kMaxToleranceNominalMm);
    requireRange("implausible fraction", spec.implausibleFraction, 0.0, 0.5);
    core::checkToleranceZone({spec.nominalMm, spec.upperDeviationMm, spec.lowerDeviationMm});
    SyntheticHistoryResult result;
    db.transaction([&] { result = Generator(db, spec).write(); });
    return result;
}

}  // namespace tt::storage
