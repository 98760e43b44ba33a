// The audit trail's hash chain (core/storage/audit_chain.h), on SQLite and PostgreSQL: the canonical
// encoding and its SHA-256 against Python's hashlib (the reference values below were computed with
// `hashlib.sha256` over the same netstrings); an intact chain; an edited, a deleted and an inserted row each
// named by id; rows written before the chain existed chained by the migration; on PostgreSQL, a terminal's
// own (non-superuser) role that cannot UPDATE, DELETE or TRUNCATE audit rows after the migration.
#include "core/storage/audit_chain.h"

#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QUuid>

#include "core/storage/audit_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

using Kind = AuditChainProblem::Kind;

AuditChainRow exampleRow() {
    AuditChainRow r;
    r.changedAt = QStringLiteral("2026-01-02T03:04:05.678Z");
    r.changedBy = QStringLiteral("Olga");
    r.role = QStringLiteral("engineer");
    r.category = QStringLiteral("controller");
    r.subject = QStringLiteral("controller");
    r.field = QStringLiteral("point 1 R1");
    r.oldValue = QStringLiteral("0.01");
    r.newValue = QStringLiteral("0.02");
    return r;
}

TEST(AuditChainEncoding, NetstringsAndSha256MatchPythonHashlib) {
    const AuditChainRow first = exampleRow();
    EXPECT_EQ(auditRowEncoding(first, kAuditGenesisHash, 1),
              QByteArray("16:trueturn-audit-1,64:" + QByteArray(64, '0') +
                         ",1:1,24:2026-01-02T03:04:05.678Z,4:Olga,8:engineer,10:controller,10:controller,10:point 1 "
                         "R1,4:0.01,4:0.02,"));
    // python3: hashlib.sha256(<the bytes above>).hexdigest()
    const QString h1 = auditRowHash(first, kAuditGenesisHash, 1);
    EXPECT_EQ(h1, QStringLiteral("3c1f752f965d72f208a55f7c039dcba8bd0f98f1e69d1d4d66a12fec5f12f569"));
    AuditChainRow second;
    second.changedAt = QStringLiteral("2026-01-02T03:04:06.000Z");
    second.changedBy = QStringLiteral("Иван");  // UTF-8: the length is in bytes
    second.role = QStringLiteral("operator");
    second.category = QStringLiteral("session");
    second.subject = QStringLiteral("user Иван");
    second.field = QStringLiteral("log-in");
    second.newValue = QStringLiteral("logged in");
    EXPECT_EQ(auditRowHash(second, h1, 2),
              QStringLiteral("599e00fef28d2ca86b94f55cdcd3689fe02f08bbe524075e09ecc4f77e5a91f8"));
}

TEST(AuditChainEncoding, AFieldBoundaryMovedChangesTheHash) {
    AuditChainRow a = exampleRow();
    AuditChainRow b = exampleRow();
    a.oldValue = QStringLiteral("0.0");
    a.newValue = QStringLiteral("10.02");
    b.oldValue = QStringLiteral("0.01");
    b.newValue = QStringLiteral("0.02");
    EXPECT_NE(auditRowHash(a, kAuditGenesisHash, 1), auditRowHash(b, kAuditGenesisHash, 1));
}

/// A chain of `count` rows with ids 10, 20, 30 ... as appendAuditRow writes them.
std::vector<AuditChainRow> chainOf(int count) {
    std::vector<AuditChainRow> rows;
    QString prev = kAuditGenesisHash;
    for (int i = 1; i <= count; ++i) {
        AuditChainRow r = exampleRow();
        r.id = 10 * i;
        r.newValue = QString::number(i);
        r.seq = i;
        r.prevHash = prev;
        r.rowHash = auditRowHash(r, prev, i);
        prev = r.rowHash;
        rows.push_back(r);
    }
    return rows;
}

TEST(AuditChainWalk, ARowForgedIntoTheMiddleWithTheEncodingIsNamedNotTheRowsAfterIt) {
    std::vector<AuditChainRow> rows = chainOf(5);
    const AuditChainHead head{5, rows.back().rowHash};
    // Someone who knows the encoding writes a row after row 20 (id 25) hashed correctly onto it.
    AuditChainRow forged = exampleRow();
    forged.id = 25;
    forged.seq = 3;
    forged.prevHash = rows[1].rowHash;
    forged.rowHash = auditRowHash(forged, forged.prevHash, 3);
    rows.insert(rows.begin() + 2, forged);
    const AuditChainState state = verifyAuditChain(rows, head);
    ASSERT_EQ(state.problems.size(), 1u) << state.problems.front().message.toStdString();
    EXPECT_EQ(state.problems[0].kind, AuditChainProblem::Kind::Inserted);
    EXPECT_EQ(state.problems[0].rowId, 25);
    EXPECT_EQ(state.chainedRows, 5);
    EXPECT_EQ(state.headHash, head.rowHash);
}

TEST(AuditChainWalk, AnEditedRowWhoseLinkWasEditedTooIsStillNamedAsEdited) {
    std::vector<AuditChainRow> rows = chainOf(4);
    rows[1].newValue = QStringLiteral("changed");
    rows[1].prevHash = QString(64, QLatin1Char('f'));
    const AuditChainState state = verifyAuditChain(rows, AuditChainHead{4, rows.back().rowHash});
    ASSERT_EQ(state.problems.size(), 1u) << state.problems.front().message.toStdString();
    EXPECT_EQ(state.problems[0].kind, AuditChainProblem::Kind::Edited);
    EXPECT_EQ(state.problems[0].rowId, 20);
}

class AuditChainTest : public ::testing::TestWithParam<std::string> {
protected:
    static void recordChanges(AuditStore& audit, int count) {
        for (int i = 1; i <= count; ++i)
            audit.record({audit_category::kController, QStringLiteral("controller"), QStringLiteral("point 1 R1"),
                          QString::number(i - 1), QString::number(i)},
                         QStringLiteral("Olga"), QStringLiteral("engineer"));
    }
    static qint64 rowId(Database& db, int seq) {
        QSqlQuery q = db.exec(QStringLiteral("SELECT id FROM audit WHERE seq = ?"), {seq});
        return q.next() ? q.value(0).toLongLong() : -1;
    }
    static const AuditChainProblem* find(const AuditChainState& s, Kind kind, qint64 rowId) {
        for (const AuditChainProblem& p : s.problems)
            if (p.kind == kind && p.rowId == rowId) return &p;
        return nullptr;
    }
};

TEST_P(AuditChainTest, RecordsFormAnIntactChainWhoseHashesFollowFromTheContent) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    recordChanges(audit, 6);
    const AuditChainState state = audit.verifyChain();
    EXPECT_TRUE(state.intact()) << state.problems.front().message.toStdString();
    EXPECT_EQ(state.rows, 6);
    EXPECT_EQ(state.chainedRows, 6);
    // Recomputed here from the stored content alone: each hash from the one before, from 64 zeros.
    QSqlQuery q = db.exec(
        QStringLiteral("SELECT seq, prev_hash, row_hash, changed_at, changed_by, role, category, subject, field,"
                       " old_value, new_value FROM audit ORDER BY id"));
    QString prev = kAuditGenesisHash;
    qint64 seq = 0;
    while (q.next()) {
        AuditChainRow r;
        r.changedAt = q.value(3).toString();
        r.changedBy = q.value(4).toString();
        r.role = q.value(5).toString();
        r.category = q.value(6).toString();
        r.subject = q.value(7).toString();
        r.field = q.value(8).toString();
        r.oldValue = q.value(9).toString();
        r.newValue = q.value(10).toString();
        EXPECT_EQ(q.value(0).toLongLong(), ++seq);
        EXPECT_EQ(q.value(1).toString(), prev);
        prev = auditRowHash(r, prev, seq);
        EXPECT_EQ(q.value(2).toString(), prev);
    }
    EXPECT_EQ(state.headHash, prev);
}

TEST_P(AuditChainTest, AnEditedADeletedAndAnInsertedRowAreEachNamed) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    recordChanges(audit, 10);
    const qint64 edited = rowId(db, 3), beforeGap = rowId(db, 5), deleted = rowId(db, 6), afterGap = rowId(db, 7);
    // What someone with the database's tools could do (the test server's role is a superuser).
    db.exec(QStringLiteral("UPDATE audit SET new_value = '0.5' WHERE id = ?"), {edited});
    db.exec(QStringLiteral("DELETE FROM audit WHERE id = ?"), {deleted});
    QSqlQuery ins =
        db.exec(QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, old_value,"
                               " new_value) VALUES ('2026-01-01T00:00:00.000Z', 'Olga', 'engineer', 'controller',"
                               " 'controller', 'point 1 R1', '9', '10')"));
    const qint64 inserted = db.lastInsertId(ins);

    const AuditChainState state = verifyAuditChain(db);
    EXPECT_FALSE(state.intact());
    ASSERT_EQ(state.problems.size(), 3u);
    const AuditChainProblem* e = find(state, Kind::Edited, edited);
    ASSERT_NE(e, nullptr);
    EXPECT_TRUE(e->message.contains(QStringLiteral("row %1 was edited").arg(edited))) << e->message.toStdString();
    const AuditChainProblem* d = find(state, Kind::Deleted, afterGap);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->afterRowId, beforeGap);
    EXPECT_EQ(d->missingRows, 1);
    EXPECT_TRUE(
        d->message.contains(QStringLiteral("1 row(s) deleted between row %1 and row %2").arg(beforeGap).arg(afterGap)))
        << d->message.toStdString();
    const AuditChainProblem* i = find(state, Kind::Inserted, inserted);
    ASSERT_NE(i, nullptr);
    EXPECT_TRUE(i->message.contains(QStringLiteral("row %1").arg(inserted))) << i->message.toStdString();
    EXPECT_EQ(state.rows, 10);
    EXPECT_EQ(state.chainedRows, 9);
}

TEST_P(AuditChainTest, RowsDeletedAtTheEndAreFoundByTheHead) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    recordChanges(audit, 5);
    const qint64 last = rowId(db, 3);
    db.exec(QStringLiteral("DELETE FROM audit WHERE seq > 3"));
    const AuditChainState state = verifyAuditChain(db);
    ASSERT_EQ(state.problems.size(), 1u);
    EXPECT_EQ(state.problems[0].kind, Kind::Deleted);
    EXPECT_EQ(state.problems[0].afterRowId, last);
    EXPECT_EQ(state.problems[0].missingRows, 2);
}

TEST_P(AuditChainTest, ACopiedRowAndARowForgedWithTheEncodingAreNamedAsInserted) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    recordChanges(audit, 4);
    // A copy of row 2 with its chain columns.
    QSqlQuery copy = db.exec(
        QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, old_value, "
                       "new_value, seq, prev_hash, row_hash) SELECT changed_at, changed_by, role, category, subject, "
                       "field, old_value, new_value, seq, prev_hash, row_hash FROM audit WHERE seq = 2"));
    const qint64 copied = db.lastInsertId(copy);
    // A row hashed correctly after the last one by someone who knows the encoding: past the chain's head.
    QSqlQuery head = db.exec(QStringLiteral("SELECT row_hash FROM audit WHERE seq = 4"));
    ASSERT_TRUE(head.next());
    AuditChainRow forged = exampleRow();
    const QString prev = head.value(0).toString();
    QSqlQuery f =
        db.exec(QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, old_value, "
                               "new_value, seq, prev_hash, row_hash) VALUES (?, ?, ?, ?, ?, ?, ?, ?, 5, ?, ?)"),
                {forged.changedAt, forged.changedBy, forged.role, forged.category, forged.subject, forged.field,
                 forged.oldValue, forged.newValue, prev, auditRowHash(forged, prev, 5)});
    const qint64 forgedId = db.lastInsertId(f);
    const AuditChainState state = verifyAuditChain(db);
    EXPECT_NE(find(state, Kind::Inserted, copied), nullptr);
    EXPECT_NE(find(state, Kind::Inserted, forgedId), nullptr);
    EXPECT_EQ(state.problems.size(), 2u);
}

TEST_P(AuditChainTest, RowsWrittenBeforeTheChainAreChainedByTheMigration) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SchemaModule first = auditSchema();
    first.migrations.resize(1);  // the trail as version 1 wrote it
    db.migrate(first);
    for (int i = 0; i < 3; ++i)
        db.exec(QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, "
                               "old_value, new_value) VALUES (?, 'Anna', 'administrator', 'user', 'user Ivan', "
                               "'role', '', 'operator')"),
                {QStringLiteral("2025-05-0%1T10:00:00.000Z").arg(i + 1)});
    AuditStore audit(db);  // migrates to version 2
    EXPECT_EQ(db.schemaVersion(QStringLiteral("audit")), 2);
    recordChanges(audit, 2);
    const AuditChainState state = audit.verifyChain();
    EXPECT_TRUE(state.intact());
    EXPECT_EQ(state.rows, 5);
    EXPECT_EQ(state.chainedRows, 5);
}

INSTANTIATE_TEST_SUITE_P(Backends, AuditChainTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

/// A login role of its own on the test server (not a superuser, as a terminal's role is) owning a fresh
/// database; both dropped afterwards.
class TerminalRole {
public:
    TerminalRole() {
        const QString url = qEnvironmentVariable("TRUETURN_PG_URL");
        if (url.isEmpty()) return;
        m_admin = DatabaseConfig::postgresUrl(url);
        const QString suffix = QUuid::createUuid().toString(QUuid::Id128).left(12);
        m_config = m_admin;
        m_config.user = QStringLiteral("tt_terminal_") + suffix;
        m_config.databaseName = QStringLiteral("tt_audit_") + suffix;
        adminExec(QStringLiteral("CREATE ROLE %1 LOGIN NOSUPERUSER NOCREATEDB NOCREATEROLE").arg(m_config.user));
        adminExec(QStringLiteral("CREATE DATABASE %1 OWNER %2").arg(m_config.databaseName, m_config.user));
    }
    ~TerminalRole() {
        if (m_config.databaseName.isEmpty()) return;
        adminExec(QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(m_config.databaseName));
        adminExec(QStringLiteral("DROP ROLE IF EXISTS %1").arg(m_config.user));
    }
    bool available() const { return !m_config.databaseName.isEmpty(); }
    const DatabaseConfig& config() const { return m_config; }

private:
    void adminExec(const QString& sql) {
        Database admin(m_admin);
        admin.exec(sql);
    }
    DatabaseConfig m_admin, m_config;
};

TEST(AuditChainPostgres, TheTerminalsRoleCannotUpdateDeleteOrTruncateAuditRows) {
    TerminalRole role;
    TT_REQUIRE_BACKEND(role);
    Database db(role.config());
    AuditStore audit(db);  // the migration runs as the terminal's role: it owns the tables
    audit.record({audit_category::kSetting, QStringLiteral("terminal"), QStringLiteral("language"),
                  QStringLiteral("en"), QStringLiteral("ru")},
                 QStringLiteral("Olga"), QStringLiteral("engineer"));
    for (const char* sql : {"UPDATE audit SET new_value = 'de'", "DELETE FROM audit", "TRUNCATE audit"}) {
        try {
            db.exec(QString::fromLatin1(sql));
            ADD_FAILURE() << sql << " was allowed";
        } catch (const StorageError& e) {
            EXPECT_NE(std::string(e.what()).find("permission denied"), std::string::npos) << e.what();
        }
    }
    // Writing goes on (INSERT and the chain's head), and what was written is intact.
    audit.record({audit_category::kSetting, QStringLiteral("terminal"), QStringLiteral("language"),
                  QStringLiteral("ru"), QStringLiteral("en")},
                 QStringLiteral("Olga"), QStringLiteral("engineer"));
    const AuditChainState state = audit.verifyChain();
    EXPECT_TRUE(state.intact());
    EXPECT_EQ(state.rows, 2);
}

}  // namespace
}  // namespace tt::storage
