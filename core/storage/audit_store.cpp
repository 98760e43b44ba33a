#include "core/storage/audit_store.h"

#include <QJsonDocument>
#include <QSqlQuery>
#include <QStringList>
#include <algorithm>
#include <map>
#include <stdexcept>

#include "core/auth/access_guard.h"
#include "core/storage/adaptation_json.h"
#include "core/storage/audit_chain.h"
#include "core/storage/calibration_store.h"
#include "core/storage/history_store.h"
#include "core/storage/tool_store.h"

namespace tt::storage {

namespace {

QString bounded(const QString& value) {
    if (value.size() <= kMaxAuditValueChars) return value;
    return value.left(kMaxAuditValueChars - 40) + QStringLiteral("… (%1 characters)").arg(value.size());
}

QString planeName(int plane) {
    return plane == 0 ? QStringLiteral("X") : QStringLiteral("Y");
}

bool matches(const AuditRecord& r, const AuditFilter& f) {
    if (!f.category.isEmpty() && r.change.category != f.category) return false;
    if (!f.fromUtc.isEmpty() && r.changedAt < f.fromUtc) return false;
    if (!f.toUtc.isEmpty() && r.changedAt >= f.toUtc) return false;
    if (f.text.isEmpty()) return true;
    for (const QString* s : {&r.changedBy, &r.change.subject, &r.change.field, &r.change.before, &r.change.after})
        if (s->contains(f.text, Qt::CaseInsensitive)) return true;
    return false;
}

QString csvCell(QString s) {
    if (!s.isEmpty() && (s[0] == QLatin1Char('=') || s[0] == QLatin1Char('+') || s[0] == QLatin1Char('@')))
        s.prepend(QLatin1Char('\''));
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')) || s.contains(QLatin1Char('\n')) ||
        s.contains(QLatin1Char('\r')))
        s = QLatin1Char('"') + s.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return s;
}

}  // namespace

SchemaModule auditSchema() {
    SchemaModule module{QStringLiteral("audit"), {}};
    module.migrations.push_back({1, QStringLiteral("audit trail"), [](Database& db) {
                                     db.exec(QStringLiteral(
                                         "CREATE TABLE audit (id {pk}, changed_at TEXT NOT NULL, changed_by TEXT "
                                         "NOT NULL, role TEXT NOT NULL, category TEXT NOT NULL, subject TEXT NOT "
                                         "NULL, field TEXT NOT NULL, old_value TEXT NOT NULL, new_value TEXT NOT "
                                         "NULL)"));
                                     db.exec(QStringLiteral("CREATE INDEX audit_changed_at ON audit (changed_at)"));
                                 }});
    module.migrations.push_back(
        {2, QStringLiteral("hash chain of the audit trail; no UPDATE or DELETE of audit rows on PostgreSQL"),
         addAuditChain});
    return module;
}

AuditStore::AuditStore(Database& database) : m_db(database) {
    m_db.migrate(auditSchema());
    m_db.migrate(toolSchema());
    m_db.migrate(calibrationSchema());
    m_db.migrate(historySchema());
    m_db.migrate(adaptationSchema());
}

AuditRecord AuditStore::record(const AuditChange& change, const QString& who, const QString& role) {
    AuditRecord r{0, utcNowText(), who.trimmed(), role, change};
    if (m_access && m_access->identity()) {
        r.changedBy = QString::fromStdString(m_access->identity()->name);
        r.role = QString::fromStdString(core::auth::roleKey(m_access->identity()->role));
    }
    if (r.change.category.isEmpty() || r.change.subject.isEmpty() || r.change.field.isEmpty())
        throw std::invalid_argument("an audit record needs a category, a subject and a field");
    if (r.changedBy.isEmpty()) throw std::invalid_argument("an audit record needs the name of who changed it");
    r.change.before = bounded(r.change.before.isNull() ? QStringLiteral("") : r.change.before);
    r.change.after = bounded(r.change.after.isNull() ? QStringLiteral("") : r.change.after);
    r.role = r.role.isNull() ? QStringLiteral("") : r.role;
    r.change.subject = bounded(r.change.subject);
    r.change.field = bounded(r.change.field);
    AuditChainRow row;
    row.changedAt = r.changedAt;
    row.changedBy = r.changedBy;
    row.role = r.role;
    row.category = r.change.category;
    row.subject = r.change.subject;
    row.field = r.change.field;
    row.oldValue = r.change.before;
    row.newValue = r.change.after;
    r.id = appendAuditRow(m_db, row);
    return r;
}

void AuditStore::appendOwn(std::vector<AuditRecord>& out) {
    QSqlQuery q = m_db.exec(
        QStringLiteral("SELECT id, changed_at, changed_by, role, category, subject, field, old_value, new_value"
                       " FROM audit"));
    while (q.next())
        out.push_back({q.value(0).toLongLong(),
                       q.value(1).toString(),
                       q.value(2).toString(),
                       q.value(3).toString(),
                       {q.value(4).toString(), q.value(5).toString(), q.value(6).toString(), q.value(7).toString(),
                        q.value(8).toString()}});
}

void AuditStore::appendTools(std::vector<AuditRecord>& out) {
    QSqlQuery q = m_db.exec(
        QStringLiteral("SELECT id, changed_at, changed_by, subject, field, old_value, new_value FROM tool_audit"));
    while (q.next())
        out.push_back({q.value(0).toLongLong(),
                       q.value(1).toString(),
                       q.value(2).toString(),
                       QString(),
                       {audit_category::kTool, q.value(3).toString(), q.value(4).toString(), q.value(5).toString(),
                        q.value(6).toString()}});
}

void AuditStore::appendCalibrations(std::vector<AuditRecord>& out) {
    // Each saved table is a change from the previous version of its probe and plane.
    QSqlQuery t =
        m_db.exec(QStringLiteral("SELECT id, created_at, created_by, probe, plane, version, coefficients, uploaded_at,"
                                 " uploaded_by, verified FROM probe_tables ORDER BY id"));
    std::map<std::pair<QString, int>, QString> previous;
    while (t.next()) {
        const QString subject =
            QStringLiteral("probe %1 plane %2").arg(t.value(3).toString(), planeName(t.value(4).toInt()));
        const QString now = QStringLiteral("v%1: %2").arg(t.value(5).toInt()).arg(t.value(6).toString());
        QString& before = previous[{t.value(3).toString(), t.value(4).toInt()}];
        out.push_back({t.value(0).toLongLong(),
                       t.value(1).toString(),
                       t.value(2).toString(),
                       QString(),
                       {audit_category::kCalibration, subject, QStringLiteral("linearisation_table"), before, now}});
        before = now;
        if (!t.value(7).toString().isEmpty())
            out.push_back({t.value(0).toLongLong(),
                           t.value(7).toString(),
                           t.value(8).toString(),
                           QString(),
                           {audit_category::kCalibration, subject, QStringLiteral("uploaded_table"), QString(),
                            QStringLiteral("v%1 %2")
                                .arg(t.value(5).toInt())
                                .arg(t.value(9).toInt() != 0 ? QStringLiteral("verified")
                                                             : QStringLiteral("read-back differs"))}});
    }
    QSqlQuery k = m_db.exec(
        QStringLiteral("SELECT id, created_at, created_by, drive, kp_n_per_a FROM kp_calibrations ORDER BY id"));
    std::map<QString, QString> previousKp;
    while (k.next()) {
        const QString now = QString::number(k.value(4).toDouble(), 'g', 10);
        QString& before = previousKp[k.value(3).toString()];
        out.push_back({k.value(0).toLongLong(),
                       k.value(1).toString(),
                       k.value(2).toString(),
                       QString(),
                       {audit_category::kCalibration, QStringLiteral("drive ") + k.value(3).toString(),
                        QStringLiteral("kp_n_per_a"), before, now}});
        before = now;
    }
}

void AuditStore::appendAdaptations(std::vector<AuditRecord>& out) {
    // What the adaptive loop changed (or proposed, or refused) in a run, with the model before and after.
    QSqlQuery q = m_db.exec(
        QStringLiteral("SELECT a.id, a.recorded_at, a.run_id, r.machine, a.part_number, a.kind, a.model_before,"
                       " a.model_after, a.margins, a.message FROM adaptations a JOIN runs r ON r.id = a.run_id"));
    auto summary = [](const QVariant& v) {
        return v.isNull() ? QString()
                          : modelSummary(plantModelFromJson(QJsonDocument::fromJson(v.toString().toUtf8()).object()));
    };
    while (q.next()) {
        const QString machine = q.value(3).toString();
        QString subject = QStringLiteral("run %1, part %2").arg(q.value(2).toLongLong()).arg(q.value(4).toLongLong());
        if (!machine.isEmpty()) subject = machine + QStringLiteral(", ") + subject;
        QString after = q.value(9).toString();
        try {
            const QString model = summary(q.value(7));
            if (!model.isEmpty()) after += QStringLiteral(" | ") + model;
            out.push_back(
                {q.value(0).toLongLong(),
                 q.value(1).toString(),
                 kAdaptiveLoopName,
                 QString(),
                 {audit_category::kController, subject, QStringLiteral("adaptation: ") + q.value(5).toString(),
                  summary(q.value(6)), after + QStringLiteral(" | margins ") + q.value(8).toString()}});
        } catch (const std::invalid_argument&) {
            out.push_back({q.value(0).toLongLong(),
                           q.value(1).toString(),
                           kAdaptiveLoopName,
                           QString(),
                           {audit_category::kController, subject,
                            QStringLiteral("adaptation: ") + q.value(5).toString(), QString(), after}});
        }
    }
}

std::vector<AuditRecord> AuditStore::query(const AuditFilter& filter) {
    if (m_access) m_access->require(core::auth::Permission::ViewAudit);
    if (filter.limit < 1 || filter.limit > kMaxAuditRows)
        throw std::invalid_argument("the audit view shows between 1 and " + std::to_string(kMaxAuditRows) +
                                    " records (asked for " + std::to_string(filter.limit) + ")");
    std::vector<AuditRecord> all;
    appendOwn(all);
    appendTools(all);
    appendCalibrations(all);
    appendAdaptations(all);
    std::vector<AuditRecord> out;
    std::copy_if(all.begin(), all.end(), std::back_inserter(out),
                 [&](const AuditRecord& r) { return matches(r, filter); });
    std::stable_sort(out.begin(), out.end(), [](const AuditRecord& a, const AuditRecord& b) {
        return a.changedAt != b.changedAt ? a.changedAt > b.changedAt : a.id > b.id;
    });
    if (out.size() > static_cast<std::size_t>(filter.limit)) out.resize(static_cast<std::size_t>(filter.limit));
    return out;
}

AuditChainState AuditStore::verifyChain() {
    if (m_access) m_access->require(core::auth::Permission::ViewAudit);
    return verifyAuditChain(m_db);
}

QString auditCsv(const std::vector<AuditRecord>& records) {
    QString csv = QStringLiteral("when_utc,who,role,category,subject,field,old_value,new_value\r\n");
    for (const AuditRecord& r : records) {
        const QStringList cells{r.changedAt,      r.changedBy,    r.role,          r.change.category,
                                r.change.subject, r.change.field, r.change.before, r.change.after};
        QStringList quoted;
        for (const QString& c : cells)
            quoted << csvCell(c);
        csv += quoted.join(QLatin1Char(',')) + QStringLiteral("\r\n");
    }
    return csv;
}

}  // namespace tt::storage
