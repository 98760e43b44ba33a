#pragma once

// The audit trail's hash chain (tamper evidence, docs/DECISIONS.md "A tamper-evident audit trail"): every row
// of the `audit` table carries its place in the chain (seq 1, 2, 3 ...), the hash of the row before it
// (prev_hash) and its own hash (row_hash), and the table audit_chain_head the last seq and hash. A row's hash
// is SHA-256 over its canonical encoding (auditRowEncoding), which contains the previous row's hash, so an
// edited row no longer matches its hash, a deleted row leaves the next one pointing at a hash no row has, and
// a row inserted by hand has no hash or one that matches neither its content nor its place.
#include <QByteArray>
#include <QString>
#include <optional>
#include <vector>

namespace tt::storage {

class Database;

/// The previous hash of the first row: 64 zeros.
inline const QString kAuditGenesisHash = QString(64, QLatin1Char('0'));

/// One row of the `audit` table as stored, with its chain columns (empty / none when the row has none).
struct AuditChainRow {
    qint64 id = 0;
    std::optional<qint64> seq;
    QString prevHash;
    QString rowHash;
    QString changedAt, changedBy, role, category, subject, field, oldValue, newValue;
};

/// The canonical encoding of a row, version 1: netstrings (D. J. Bernstein; `<decimal byte length>:<bytes>,`)
/// of, in this order, the tag "trueturn-audit-1", `prevHash` (64 lower-case hex digits), `seq` (decimal),
/// changed_at, changed_by, role, category, subject, field, old_value, new_value, each text as UTF-8 exactly as
/// stored. The row id is not in it (on PostgreSQL it is known only after the insert, and ids may have gaps).
QByteArray auditRowEncoding(const AuditChainRow& row, const QString& prevHash, qint64 seq);

/// SHA-256 of auditRowEncoding, as 64 lower-case hex digits.
QString auditRowHash(const AuditChainRow& row, const QString& prevHash, qint64 seq);

/// What the chain says of one place in the trail.
struct AuditChainProblem {
    enum class Kind {
        Edited,    ///< the row's content no longer matches its hash (it keeps its place)
        Deleted,   ///< rows are missing before `rowId` (after `afterRowId`), or at the end
        Inserted,  ///< the row is not part of the chain (no hash, a copied hash, or a hash of nothing here)
        Head,      ///< the chain's head (audit_chain_head) does not match its last row
    };
    Kind kind = Kind::Edited;
    qint64 rowId = 0;        ///< the row named (0: none, e.g. rows deleted at the end)
    qint64 afterRowId = 0;   ///< Deleted: the last intact row before the gap (0: the start)
    qint64 missingRows = 0;  ///< Deleted: how many (from the seq numbers)
    QString message;         ///< in English, naming the rows by id
};

/// The chain's head as stored (audit_chain_head).
struct AuditChainHead {
    qint64 seq = 0;
    QString rowHash;
};

/// The state of the whole chain.
struct AuditChainState {
    qint64 rows = 0;         ///< rows in the audit table
    qint64 chainedRows = 0;  ///< rows found in their place (intact or edited)
    QString headHash;        ///< the hash of the last row in the chain (kAuditGenesisHash when none)
    std::vector<AuditChainProblem> problems;
    /// No problem found.
    bool intact() const { return problems.empty(); }
};

/// Checks rows given in id order against each other and the head (none: not checked).
AuditChainState verifyAuditChain(const std::vector<AuditChainRow>& rowsById, const std::optional<AuditChainHead>& head);

/// Reads the audit table and its head from `database` (audit schema version 2 or later) and checks them.
/// Throws StorageError when the database has no chained audit trail.
AuditChainState verifyAuditChain(Database& database);

/// Appends one row to the chain inside the caller's transaction: takes the head (locked FOR UPDATE on
/// PostgreSQL; an SQLite transaction is already the only writer), writes the row with its seq, prev_hash and
/// row_hash, moves the head. Returns the new row's id.
qint64 appendAuditRow(Database& database, const AuditChainRow& row);

/// The migration step that adds the chain: the columns seq, prev_hash, row_hash, the table audit_chain_head,
/// every existing row chained in id order; on PostgreSQL UPDATE, DELETE and TRUNCATE on `audit` revoked from
/// PUBLIC and from the role that migrates (the terminal's), so only INSERT and SELECT remain.
void addAuditChain(Database& database);

}  // namespace tt::storage
