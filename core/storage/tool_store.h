#pragma once

#include <QString>
#include <optional>
#include <string>
#include <vector>

#include "core/model/tool_stiffness.h"
#include "core/storage/database.h"

namespace tt::core::auth {
class AccessGuard;
}

namespace tt::storage {

/// The schema module "tools": the tool stiffness table (tools), the materials list with Young's
/// modulus (tool_materials, seeded with core::defaultMaterials) and the audit record of every
/// applied change (tool_audit: when, who, what, field, old, new).
SchemaModule toolSchema();

/// One line of the audit record.
struct ToolAuditEntry {
    qint64 id = 0;
    QString changedAt;  ///< ISO 8601 UTC
    QString changedBy;  ///< the operator's name
    QString subject;    ///< tool id, or "material <name>"
    QString field;      ///< field key (core::toolFieldKey), "youngs_modulus_mpa" for materials
    QString before;     ///< empty when the tool or material was added
    QString after;      ///< empty when it was removed
};

/// One applied edit of a tool-table row: `originalId` empty = a new tool; `after` empty = the
/// tool `originalId` is removed; both = the stored tool `originalId` becomes `after` (its id may change).
struct ToolEdit {
    std::optional<std::string> originalId;
    std::optional<core::ToolRecord> after;
};

/// The tool stiffness table over SQL (SQLite or PostgreSQL). Use from the thread that opened the
/// Database. Every change is one transaction together with its audit entries: either all of it
/// is stored or nothing (a bad record, a duplicate id, or a storage failure changes nothing).
class ToolStore {
public:
    /// Applies the "tools" migrations to `database` (which must outlive the store).
    explicit ToolStore(Database& database);
    /// With a guard every change needs the EditTools permission (else core::auth::PermissionDenied,
    /// nothing changed) and is audited under the logged-in user's name whatever `who` says; null = not
    /// access-controlled (the command line). The guard must outlive the store.
    void setAccess(const core::auth::AccessGuard* access) { m_access = access; }

    /// Every stored tool, ordered by id.
    std::vector<core::ToolRecord> tools();
    /// The materials list, ordered by name.
    std::vector<core::Material> materials();

    /// Applies the edits with `who` and the current time in the audit. Throws std::invalid_argument
    /// (a record validateTool rejects, two tools with one id, an unknown original id, an empty
    /// `who`) or StorageError; nothing is stored then. Returns the audit entries written.
    std::vector<ToolAuditEntry> apply(const std::vector<ToolEdit>& edits, const QString& who);
    /// Adds a material or changes its modulus (audited). Throws std::invalid_argument for an empty
    /// name or a modulus outside kMinYoungsModulusMpa .. kMaxYoungsModulusMpa.
    std::vector<ToolAuditEntry> saveMaterial(const core::Material& material, const QString& who);
    /// Removes a material (audited); tools keep their stored modulus.
    std::vector<ToolAuditEntry> removeMaterial(const std::string& name, const QString& who);

    /// The newest `limit` audit entries, newest first.
    std::vector<ToolAuditEntry> audit(int limit = 1000);

private:
    std::optional<core::ToolRecord> load(const std::string& id);
    void write(const core::ToolRecord& tool, const QString& who, const QString& now);
    ToolAuditEntry record(const QString& now, const QString& who, const QString& subject, const QString& field,
                          const QString& before, const QString& after);

    /// The name audited for a change by `who`: the logged-in user when guarded (after the check).
    QString actor(const QString& who) const;

    Database& m_db;
    const core::auth::AccessGuard* m_access = nullptr;
};

}  // namespace tt::storage
