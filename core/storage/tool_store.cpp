#include "core/storage/tool_store.h"

#include <QSqlQuery>
#include <QVariant>
#include <cmath>
#include <set>
#include <stdexcept>

#include "core/auth/access_guard.h"
#include "core/model/tool_table.h"

namespace tt::storage {

namespace {

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

const char* kToolColumns =
    "tool_id, name, section, diameter_mm, width_mm, height_mm, overhang_mm, material, youngs_modulus_mpa,"
    " measured_stiffness_n_per_mm, measured_on, measured_by, kp_n_per_a";

core::ToolRecord readTool(const QSqlQuery& q) {
    core::ToolRecord t;
    t.id = q.value(0).toString().toStdString();
    t.name = q.value(1).toString().toStdString();
    t.section.shape = core::sectionShapeFromString(q.value(2).toString().toStdString());
    t.section.diameterMm = q.value(3).toDouble();
    t.section.widthMm = q.value(4).toDouble();
    t.section.heightMm = q.value(5).toDouble();
    t.overhangMm = q.value(6).toDouble();
    t.material = q.value(7).toString().toStdString();
    t.youngsModulusMpa = q.value(8).toDouble();
    if (!q.value(9).isNull())
        t.measured = core::MeasuredStiffness{q.value(9).toDouble(), q.value(10).toString().toStdString(),
                                             q.value(11).toString().toStdString()};
    t.currentToForceGainNPerA = q.value(12).toDouble();
    return t;
}

void checkTool(const core::ToolRecord& tool) {
    const std::vector<std::string> problems = core::validateTool(tool);
    if (!problems.empty()) throw std::invalid_argument("tool '" + tool.id + "': " + problems.front());
}

}  // namespace

SchemaModule toolSchema() {
    SchemaModule module{QStringLiteral("tools"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("tool stiffness table, materials, audit record"), [](Database& db) {
             db.exec(QStringLiteral(
                 "CREATE TABLE tools (tool_id TEXT PRIMARY KEY, name TEXT NOT NULL, section TEXT NOT NULL,"
                 " diameter_mm {real} NOT NULL, width_mm {real} NOT NULL, height_mm {real} NOT NULL,"
                 " overhang_mm {real} NOT NULL, material TEXT NOT NULL, youngs_modulus_mpa {real} NOT NULL,"
                 " measured_stiffness_n_per_mm {real}, measured_on TEXT NOT NULL, measured_by TEXT NOT NULL,"
                 " kp_n_per_a {real} NOT NULL, updated_at TEXT NOT NULL, updated_by TEXT NOT NULL)"));
             db.exec(QStringLiteral(
                 "CREATE TABLE tool_materials (name TEXT PRIMARY KEY, youngs_modulus_mpa {real} NOT NULL)"));
             db.exec(QStringLiteral(
                 "CREATE TABLE tool_audit (id {pk}, changed_at TEXT NOT NULL, changed_by TEXT NOT NULL,"
                 " subject TEXT NOT NULL, field TEXT NOT NULL, old_value TEXT NOT NULL, new_value TEXT NOT NULL)"));
             for (const core::Material& m : core::defaultMaterials())
                 db.exec(QStringLiteral("INSERT INTO tool_materials (name, youngs_modulus_mpa) VALUES (?, ?)"),
                         {text(m.name), m.youngsModulusMpa});
         }});
    return module;
}

ToolStore::ToolStore(Database& database) : m_db(database) {
    m_db.migrate(toolSchema());
}

std::vector<core::ToolRecord> ToolStore::tools() {
    std::vector<core::ToolRecord> out;
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT %1 FROM tools ORDER BY tool_id").arg(QLatin1String(kToolColumns)));
    while (q.next())
        out.push_back(readTool(q));
    return out;
}

std::vector<core::Material> ToolStore::materials() {
    std::vector<core::Material> out;
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT name, youngs_modulus_mpa FROM tool_materials ORDER BY name"));
    while (q.next())
        out.push_back({q.value(0).toString().toStdString(), q.value(1).toDouble()});
    return out;
}

std::optional<core::ToolRecord> ToolStore::load(const std::string& id) {
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT %1 FROM tools WHERE tool_id = ?").arg(QLatin1String(kToolColumns)),
                            {text(id)});
    if (!q.next()) return std::nullopt;
    return readTool(q);
}

void ToolStore::write(const core::ToolRecord& t, const QString& who, const QString& now) {
    const bool measured = t.measured.has_value();
    m_db.exec(
        QStringLiteral("INSERT INTO tools (%1, updated_at, updated_by) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                       "?, ?, ?)")
            .arg(QLatin1String(kToolColumns)),
        {text(t.id), text(t.name), text(core::toString(t.section.shape)), t.section.diameterMm, t.section.widthMm,
         t.section.heightMm, t.overhangMm, text(t.material), t.youngsModulusMpa,
         nullable<double>(measured ? std::optional<double>(t.measured->stiffnessNPerMm) : std::nullopt),
         text(measured ? t.measured->measuredOn : std::string()),
         text(measured ? t.measured->measuredBy : std::string()), t.currentToForceGainNPerA, now, who});
}

ToolAuditEntry ToolStore::record(const QString& now, const QString& who, const QString& subject, const QString& field,
                                 const QString& before, const QString& after) {
    // A null QString binds as SQL NULL; the columns hold "" for "nothing".
    auto notNull = [](const QString& s) { return s.isNull() ? QStringLiteral("") : s; };
    QSqlQuery q = m_db.exec(QStringLiteral("INSERT INTO tool_audit (changed_at, changed_by, subject, field, old_value,"
                                           " new_value) VALUES (?, ?, ?, ?, ?, ?)"),
                            {now, who, subject, field, notNull(before), notNull(after)});
    return {m_db.lastInsertId(q), now, who, subject, field, notNull(before), notNull(after)};
}

QString ToolStore::actor(const QString& who) const {
    if (!m_access) return who;
    return QString::fromStdString(m_access->require(core::auth::Permission::EditTools).name);
}

std::vector<ToolAuditEntry> ToolStore::apply(const std::vector<ToolEdit>& edits, const QString& operatorName) {
    const QString who = actor(operatorName);
    if (who.trimmed().isEmpty())
        throw std::invalid_argument("the operator's name is needed for the audit record (Settings → Operator)");
    for (const ToolEdit& e : edits) {
        if (!e.originalId && !e.after) throw std::invalid_argument("an edit needs an original tool or a new one");
        if (e.after) checkTool(*e.after);
    }
    const QString now = utcNowText();
    std::vector<ToolAuditEntry> written;
    m_db.transaction([&] {
        // Removals and renames first free their ids; then every new state is written.
        std::vector<std::pair<std::optional<core::ToolRecord>, core::ToolRecord>> writes;
        for (const ToolEdit& e : edits) {
            std::optional<core::ToolRecord> before;
            if (e.originalId) {
                before = load(*e.originalId);
                if (!before) throw std::invalid_argument("tool '" + *e.originalId + "' is not in the table any more");
                m_db.exec(QStringLiteral("DELETE FROM tools WHERE tool_id = ?"), {text(*e.originalId)});
            }
            if (e.after) {
                writes.emplace_back(before, *e.after);
            } else {
                for (core::ToolField f : core::allToolFields())
                    if (const std::string value = core::toolFieldText(*before, f); !value.empty())
                        written.push_back(
                            record(now, who, text(before->id), text(core::toolFieldKey(f)), text(value), QString()));
            }
        }
        std::set<std::string> ids;
        for (const core::ToolRecord& t : tools())
            ids.insert(t.id);
        for (const auto& [before, after] : writes) {
            if (!ids.insert(after.id).second)
                throw std::invalid_argument("tool id '" + after.id + "' is used twice; ids must be unique");
            write(after, who, now);
            std::vector<core::ToolFieldChange> changes;
            if (before) {
                changes = core::diffTool(*before, after);
            } else {  // a new tool: every field it has
                for (core::ToolField f : core::allToolFields())
                    if (std::string value = core::toolFieldText(after, f); !value.empty())
                        changes.push_back({f, std::string(), std::move(value)});
            }
            for (const core::ToolFieldChange& c : changes)
                written.push_back(record(now, who, text(before ? before->id : after.id),
                                         text(core::toolFieldKey(c.field)), text(c.before), text(c.after)));
        }
    });
    return written;
}

std::vector<ToolAuditEntry> ToolStore::saveMaterial(const core::Material& material, const QString& operatorName) {
    const QString who = actor(operatorName);
    if (who.trimmed().isEmpty())
        throw std::invalid_argument("the operator's name is needed for the audit record (Settings → Operator)");
    if (material.name.empty()) throw std::invalid_argument("material: the name must not be empty");
    if (!std::isfinite(material.youngsModulusMpa) || material.youngsModulusMpa < core::kMinYoungsModulusMpa ||
        material.youngsModulusMpa > core::kMaxYoungsModulusMpa)
        throw std::invalid_argument("material " + material.name + ": Young's modulus must be between " +
                                    std::to_string(static_cast<int>(core::kMinYoungsModulusMpa)) + " and " +
                                    std::to_string(static_cast<int>(core::kMaxYoungsModulusMpa)) + " MPa");
    const QString now = utcNowText();
    std::vector<ToolAuditEntry> written;
    m_db.transaction([&] {
        QSqlQuery q = m_db.exec(QStringLiteral("SELECT youngs_modulus_mpa FROM tool_materials WHERE name = ?"),
                                {text(material.name)});
        const bool exists = q.next();
        const QString before = exists ? QString::number(q.value(0).toDouble(), 'g', 10) : QString();
        const QString after = QString::number(material.youngsModulusMpa, 'g', 10);
        if (before == after) return;
        if (exists)
            m_db.exec(QStringLiteral("UPDATE tool_materials SET youngs_modulus_mpa = ? WHERE name = ?"),
                      {material.youngsModulusMpa, text(material.name)});
        else
            m_db.exec(QStringLiteral("INSERT INTO tool_materials (name, youngs_modulus_mpa) VALUES (?, ?)"),
                      {text(material.name), material.youngsModulusMpa});
        written.push_back(record(now, who, QStringLiteral("material ") + text(material.name),
                                 QStringLiteral("youngs_modulus_mpa"), before, after));
    });
    return written;
}

std::vector<ToolAuditEntry> ToolStore::removeMaterial(const std::string& name, const QString& operatorName) {
    const QString who = actor(operatorName);
    if (who.trimmed().isEmpty())
        throw std::invalid_argument("the operator's name is needed for the audit record (Settings → Operator)");
    const QString now = utcNowText();
    std::vector<ToolAuditEntry> written;
    m_db.transaction([&] {
        QSqlQuery q =
            m_db.exec(QStringLiteral("SELECT youngs_modulus_mpa FROM tool_materials WHERE name = ?"), {text(name)});
        if (!q.next()) throw std::invalid_argument("material '" + name + "' is not in the list");
        const QString before = QString::number(q.value(0).toDouble(), 'g', 10);
        m_db.exec(QStringLiteral("DELETE FROM tool_materials WHERE name = ?"), {text(name)});
        written.push_back(record(now, who, QStringLiteral("material ") + text(name),
                                 QStringLiteral("youngs_modulus_mpa"), before, {}));
    });
    return written;
}

std::vector<ToolAuditEntry> ToolStore::audit(int limit) {
    std::vector<ToolAuditEntry> out;
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT id, changed_at, changed_by, subject, field, old_value, new_value"
                                           " FROM tool_audit ORDER BY id DESC LIMIT ?"),
                            {limit});
    while (q.next())
        out.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(), q.value(3).toString(),
                       q.value(4).toString(), q.value(5).toString(), q.value(6).toString()});
    return out;
}

}  // namespace tt::storage
