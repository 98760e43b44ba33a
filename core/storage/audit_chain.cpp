#include "core/storage/audit_chain.h"

#include <QCryptographicHash>
#include <QSqlQuery>
#include <QVariant>
#include <map>
#include <set>

#include "core/storage/database.h"

namespace tt::storage {

namespace {

void appendNetstring(QByteArray& out, const QByteArray& bytes) {
    out += QByteArray::number(bytes.size());
    out += ':';
    out += bytes;
    out += ',';
}

bool hasChainColumns(const AuditChainRow& r) {
    return r.seq.has_value() && !r.rowHash.isEmpty() && !r.prevHash.isEmpty();
}

/// The walk over the rows in id order (see verifyAuditChain).
class ChainWalk {
public:
    ChainWalk(const std::vector<AuditChainRow>& rows, const std::optional<AuditChainHead>& head)
        : m_rows(rows), m_head(head) {
        for (const AuditChainRow& r : rows)
            if (hasChainColumns(r)) m_linkedTo.insert(r.prevHash);
    }

    AuditChainState run() {
        for (std::size_t i = 0; i < m_rows.size(); ++i)
            visit(i);
        AuditChainState state;
        state.rows = static_cast<qint64>(m_rows.size());
        state.chainedRows = static_cast<qint64>(m_kept.size());
        state.headHash = expectedPrev();
        if (m_head) checkHead(*m_head);
        state.problems = std::move(m_problems);
        return state;
    }

private:
    const AuditChainRow& row(std::size_t i) const { return m_rows[i]; }
    QString expectedPrev() const { return m_kept.empty() ? kAuditGenesisHash : row(m_kept.back()).rowHash; }
    qint64 expectedSeq() const { return m_kept.empty() ? 1 : *row(m_kept.back()).seq + 1; }
    qint64 lastKeptId() const { return m_kept.empty() ? 0 : row(m_kept.back()).id; }

    void problem(AuditChainProblem::Kind kind, qint64 rowId, const QString& message, qint64 after = 0,
                 qint64 missing = 0) {
        m_problems.push_back({kind, rowId, after, missing, message});
    }

    void keep(std::size_t i) {
        m_keptAt[row(i).rowHash] = m_kept.size();
        m_kept.push_back(i);
    }

    void visit(std::size_t i) {
        const AuditChainRow& r = row(i);
        if (!hasChainColumns(r)) {
            problem(AuditChainProblem::Kind::Inserted, r.id,
                    QStringLiteral("row %1 has no hash: it was inserted outside TrueTurn").arg(r.id));
            return;
        }
        if (m_keptAt.count(r.rowHash)) {
            problem(AuditChainProblem::Kind::Inserted, r.id,
                    QStringLiteral("row %1 carries the hash of row %2: it is a copy inserted outside TrueTurn")
                        .arg(r.id)
                        .arg(row(m_kept[m_keptAt[r.rowHash]]).id));
            return;
        }
        const bool contentOk = auditRowHash(r, r.prevHash, *r.seq) == r.rowHash;
        const bool linkOk = r.prevHash == expectedPrev();
        if (!contentOk) {
            if (linkOk || m_linkedTo.count(r.rowHash)) {
                problem(AuditChainProblem::Kind::Edited, r.id,
                        QStringLiteral("row %1 was edited: its content no longer matches its hash").arg(r.id));
                keep(i);
            } else {
                problem(AuditChainProblem::Kind::Inserted, r.id,
                        QStringLiteral("row %1 is not part of the chain (its hash matches neither its content nor "
                                       "its place): it was inserted outside TrueTurn")
                            .arg(r.id));
            }
            return;
        }
        if (linkOk || brokenLink(r)) keep(i);
    }

    /// Whether a row that follows nothing else follows `r` (the end of a chain) and is not the head.
    bool endsWithoutHead(const AuditChainRow& r) const {
        return !m_linkedTo.count(r.rowHash) && !(m_head && m_head->rowHash == r.rowHash);
    }

    /// An intact row `r` whose predecessor is not the last row kept. When its predecessor is an earlier row
    /// in the chain (or the start), two rows claim one place: the one the chain goes on from (a later row
    /// follows it, or the head names it) is the trail's, the other was inserted. Otherwise rows before `r`
    /// were deleted. Returns whether `r` stays in the chain.
    bool brokenLink(const AuditChainRow& r) {
        const auto earlier = m_keptAt.find(r.prevHash);
        if (earlier != m_keptAt.end() || r.prevHash == kAuditGenesisHash) {
            if (endsWithoutHead(r) && !endsWithoutHead(row(m_kept.back()))) {
                problem(AuditChainProblem::Kind::Inserted, r.id,
                        QStringLiteral("row %1 is not part of the chain (row %2 holds its place): it was inserted "
                                       "outside TrueTurn")
                            .arg(r.id)
                            .arg(row(m_kept[earlier != m_keptAt.end() ? earlier->second + 1 : 0]).id));
                return false;
            }
            const std::size_t from = earlier != m_keptAt.end() ? earlier->second + 1 : 0;
            for (std::size_t k = from; k < m_kept.size(); ++k) {
                m_keptAt.erase(row(m_kept[k]).rowHash);
                problem(AuditChainProblem::Kind::Inserted, row(m_kept[k]).id,
                        QStringLiteral("row %1 is not part of the chain (row %2 follows the row before it): it was "
                                       "inserted outside TrueTurn")
                            .arg(row(m_kept[k]).id)
                            .arg(r.id));
            }
            m_kept.resize(from);
            return true;
        }
        const qint64 missing = *r.seq - expectedSeq();
        const qint64 after = lastKeptId();
        problem(AuditChainProblem::Kind::Deleted, r.id,
                (missing > 0 ? QStringLiteral("%1 row(s) deleted").arg(missing) : QStringLiteral("rows deleted")) +
                    (after ? QStringLiteral(" between row %1 and row %2").arg(after).arg(r.id)
                           : QStringLiteral(" before row %1").arg(r.id)),
                after, std::max<qint64>(missing, 0));
        return true;
    }

    void checkHead(const AuditChainHead& head) {
        const qint64 lastSeq = expectedSeq() - 1;
        if (head.seq == lastSeq && head.rowHash == expectedPrev()) return;
        if (head.seq > lastSeq) {
            problem(AuditChainProblem::Kind::Deleted, 0,
                    QStringLiteral("%1 row(s) deleted at the end (after row %2): the chain's head counts %3 rows")
                        .arg(head.seq - lastSeq)
                        .arg(lastKeptId())
                        .arg(head.seq),
                    lastKeptId(), head.seq - lastSeq);
            return;
        }
        for (std::size_t k = 0; k < m_kept.size(); ++k)
            if (*row(m_kept[k]).seq > head.seq)
                problem(AuditChainProblem::Kind::Inserted, row(m_kept[k]).id,
                        QStringLiteral("row %1 lies past the chain's head (%2 rows): it was inserted outside TrueTurn")
                            .arg(row(m_kept[k]).id)
                            .arg(head.seq));
        if (head.seq == lastSeq)
            problem(AuditChainProblem::Kind::Head, 0,
                    QStringLiteral("the chain's head does not match its last row %1").arg(lastKeptId()));
    }

    const std::vector<AuditChainRow>& m_rows;
    std::optional<AuditChainHead> m_head;
    std::set<QString> m_linkedTo;             // every prev_hash some row points at
    std::vector<std::size_t> m_kept;          // the rows in the chain, in order
    std::map<QString, std::size_t> m_keptAt;  // row_hash -> index in m_kept
    std::vector<AuditChainProblem> m_problems;
};

std::optional<AuditChainHead> readHead(Database& db) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT seq, row_hash FROM audit_chain_head WHERE id = 1"));
    if (!q.next()) return std::nullopt;
    return AuditChainHead{q.value(0).toLongLong(), q.value(1).toString()};
}

std::vector<AuditChainRow> readRows(Database& db) {
    QSqlQuery q = db.exec(
        QStringLiteral("SELECT id, seq, prev_hash, row_hash, changed_at, changed_by, role, category, subject, field,"
                       " old_value, new_value FROM audit ORDER BY id"));
    std::vector<AuditChainRow> rows;
    while (q.next()) {
        AuditChainRow r;
        r.id = q.value(0).toLongLong();
        if (!q.value(1).isNull()) r.seq = q.value(1).toLongLong();
        r.prevHash = q.value(2).toString();
        r.rowHash = q.value(3).toString();
        r.changedAt = q.value(4).toString();
        r.changedBy = q.value(5).toString();
        r.role = q.value(6).toString();
        r.category = q.value(7).toString();
        r.subject = q.value(8).toString();
        r.field = q.value(9).toString();
        r.oldValue = q.value(10).toString();
        r.newValue = q.value(11).toString();
        rows.push_back(std::move(r));
    }
    return rows;
}

QVariantList contentBindings(const AuditChainRow& r) {
    return {r.changedAt, r.changedBy, r.role, r.category, r.subject, r.field, r.oldValue, r.newValue};
}

}  // namespace

QByteArray auditRowEncoding(const AuditChainRow& row, const QString& prevHash, qint64 seq) {
    QByteArray out;
    appendNetstring(out, QByteArrayLiteral("trueturn-audit-1"));
    appendNetstring(out, prevHash.toUtf8());
    appendNetstring(out, QByteArray::number(seq));
    for (const QString* text : {&row.changedAt, &row.changedBy, &row.role, &row.category, &row.subject, &row.field,
                                &row.oldValue, &row.newValue})
        appendNetstring(out, text->toUtf8());
    return out;
}

QString auditRowHash(const AuditChainRow& row, const QString& prevHash, qint64 seq) {
    return QString::fromLatin1(
        QCryptographicHash::hash(auditRowEncoding(row, prevHash, seq), QCryptographicHash::Sha256).toHex());
}

AuditChainState verifyAuditChain(const std::vector<AuditChainRow>& rowsById,
                                 const std::optional<AuditChainHead>& head) {
    return ChainWalk(rowsById, head).run();
}

AuditChainState verifyAuditChain(Database& database) {
    if (database.schemaVersion(QStringLiteral("audit")) < 2)
        throw StorageError("the database has no chained audit trail (audit schema version " +
                           std::to_string(database.schemaVersion(QStringLiteral("audit"))) +
                           "; TrueTurn adds the chain when it opens the database for writing)");
    std::optional<AuditChainHead> head;
    std::vector<AuditChainRow> rows;
    database.transaction([&] {  // one snapshot of the rows and the head
        head = readHead(database);
        rows = readRows(database);
    });
    if (!head) throw StorageError("the audit trail's chain head (table audit_chain_head) is missing");
    return verifyAuditChain(rows, head);
}

qint64 appendAuditRow(Database& database, const AuditChainRow& row) {
    qint64 id = 0;
    database.transaction([&] {
        QSqlQuery h = database.exec(
            database.isPostgres() ? QStringLiteral("SELECT seq, row_hash FROM audit_chain_head WHERE id = 1 FOR UPDATE")
                                  : QStringLiteral("SELECT seq, row_hash FROM audit_chain_head WHERE id = 1"));
        if (!h.next()) throw StorageError("the audit trail's chain head (table audit_chain_head) is missing");
        const qint64 seq = h.value(0).toLongLong() + 1;
        const QString prevHash = h.value(1).toString();
        h.finish();
        const QString hash = auditRowHash(row, prevHash, seq);
        QVariantList bindings = contentBindings(row);
        bindings << seq << prevHash << hash;
        QSqlQuery q = database.exec(
            QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, old_value,"
                           " new_value, seq, prev_hash, row_hash) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
            bindings);
        id = database.lastInsertId(q);
        database.exec(QStringLiteral("UPDATE audit_chain_head SET seq = ?, row_hash = ? WHERE id = 1"), {seq, hash});
    });
    return id;
}

void addAuditChain(Database& db) {
    db.exec(QStringLiteral("ALTER TABLE audit ADD COLUMN seq {bigint}"));
    db.exec(QStringLiteral("ALTER TABLE audit ADD COLUMN prev_hash TEXT"));
    db.exec(QStringLiteral("ALTER TABLE audit ADD COLUMN row_hash TEXT"));
    db.exec(
        QStringLiteral("CREATE TABLE audit_chain_head (id INTEGER PRIMARY KEY, seq {bigint} NOT NULL,"
                       " row_hash TEXT NOT NULL)"));
    QString prevHash = kAuditGenesisHash;
    qint64 seq = 0;
    for (const AuditChainRow& row : readRows(db)) {
        ++seq;
        const QString hash = auditRowHash(row, prevHash, seq);
        db.exec(QStringLiteral("UPDATE audit SET seq = ?, prev_hash = ?, row_hash = ? WHERE id = ?"),
                {seq, prevHash, hash, row.id});
        prevHash = hash;
    }
    db.exec(QStringLiteral("INSERT INTO audit_chain_head (id, seq, row_hash) VALUES (1, ?, ?)"), {seq, prevHash});
    if (db.isPostgres()) {
        db.exec(QStringLiteral("REVOKE UPDATE, DELETE, TRUNCATE ON audit FROM PUBLIC"));
        db.exec(QStringLiteral("REVOKE UPDATE, DELETE, TRUNCATE ON audit FROM CURRENT_USER"));
    }
}

}  // namespace tt::storage
