#pragma once

#include <QString>
#include <vector>

#include "core/storage/audit_chain.h"
#include "core/storage/database.h"

namespace tt::core::auth {
class AccessGuard;
}

namespace tt::storage {

/// The schema module "audit": the audit trail of every change of a setting, a user, the controller
/// tuning or anything else without its own record (audit: when, who, role, category, subject, field,
/// old, new). Tool changes (tool_audit) and calibrations (probe_tables, kp_calibrations) keep their own
/// records and are read into the same trail (AuditStore::query). Version 2 chains the rows of `audit` by
/// their hashes (core/storage/audit_chain.h).
SchemaModule auditSchema();

/// Categories of the audit trail.
namespace audit_category {
inline const QString kSetting = QStringLiteral("setting");
inline const QString kCalibration = QStringLiteral("calibration");
inline const QString kTool = QStringLiteral("tool");
inline const QString kUser = QStringLiteral("user");
inline const QString kController = QStringLiteral("controller");
inline const QString kSession = QStringLiteral("session");
}  // namespace audit_category

/// Who the adaptive loop's controller changes are recorded as (the loop itself, no user).
inline const QString kAdaptiveLoopName = QStringLiteral("adaptive loop");

/// What changed: category (audit_category), subject ("T12", "user Ivan", "controller"), field, the
/// value before (empty when created) and after (empty when removed).
struct AuditChange {
    QString category;
    QString subject;
    QString field;
    QString before;
    QString after;
};

/// One line of the audit trail.
struct AuditRecord {
    qint64 id = 0;      ///< row id within its source table
    QString changedAt;  ///< ISO 8601 UTC with milliseconds
    QString changedBy;  ///< the user's name
    QString role;       ///< the user's role key; empty for records kept before roles existed
    AuditChange change;
};

/// Which records query() returns: empty fields match everything.
struct AuditFilter {
    QString category;   ///< one of audit_category
    QString text;       ///< contained (case-insensitive) in who, subject, field, old or new value
    QString fromUtc;    ///< ISO 8601 prefix: records at or after
    QString toUtc;      ///< ISO 8601 prefix: records before
    int limit = 10000;  ///< newest first, at most kMaxAuditRows
};
inline constexpr int kMaxAuditRows = 100000;
/// Longer values are stored cut, ending in "… (N characters)".
inline constexpr int kMaxAuditValueChars = 4000;

/// The audit trail over SQL (SQLite or PostgreSQL). Use from the thread that opened the Database.
class AuditStore {
public:
    /// Applies the "audit" migrations (and those of the records it reads) to `database`.
    explicit AuditStore(Database& database);

    /// With a guard, query() needs the ViewAudit permission and record() writes the logged-in user
    /// (ignoring `who`); null = not access-controlled. The guard must outlive the store.
    void setAccess(const core::auth::AccessGuard* access) { m_access = access; }

    /// Writes one change now, as the next link of the hash chain (appendAuditRow). Throws
    /// std::invalid_argument for an empty category, subject, field or `who`, StorageError on a storage failure.
    AuditRecord record(const AuditChange& change, const QString& who, const QString& role);
    /// The trail with the tool and calibration records folded in, newest first. Throws
    /// core::auth::PermissionDenied (guarded, no ViewAudit) or std::invalid_argument (limit out of range).
    std::vector<AuditRecord> query(const AuditFilter& filter = {});
    /// The state of the audit table's hash chain (verifyAuditChain); needs ViewAudit when guarded.
    AuditChainState verifyChain();

private:
    void appendOwn(std::vector<AuditRecord>& out);
    void appendTools(std::vector<AuditRecord>& out);
    void appendCalibrations(std::vector<AuditRecord>& out);
    void appendAdaptations(std::vector<AuditRecord>& out);

    Database& m_db;
    const core::auth::AccessGuard* m_access = nullptr;
};

/// The records as CSV (RFC 4180, UTF-8, header when_utc,who,role,category,subject,field,old_value,
/// new_value); a cell a spreadsheet would run as a formula (=, +, @) is written with a leading '.
QString auditCsv(const std::vector<AuditRecord>& records);

}  // namespace tt::storage
