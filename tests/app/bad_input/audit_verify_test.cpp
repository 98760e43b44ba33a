// `trueturn audit verify`: an untouched trail exits 0; a trail where one row was edited, one deleted and one
// inserted with the database's own tools exits 1 and names all three rows; bad input exits 2.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QSqlQuery>

#include "cli_test.h"
#include "core/storage/audit_store.h"
#include "core/storage/database.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;
namespace storage = tt::storage;

class AuditVerify : public tt::test::CliTest {
protected:
    /// A history with `count` audit rows written by TrueTurn.
    QString trail(int count) {
        const QString file = path(QStringLiteral("audit.sqlite"));
        storage::Database db(storage::DatabaseConfig::sqlite(file));
        storage::AuditStore audit(db);
        for (int i = 1; i <= count; ++i)
            audit.record({storage::audit_category::kSetting, QStringLiteral("terminal"), QStringLiteral("contrast"),
                          QString::number(i - 1), QString::number(i)},
                         QStringLiteral("Olga"), QStringLiteral("engineer"));
        return file;
    }
    static void exec(const QString& file, const QString& sql) {
        storage::Database db(storage::DatabaseConfig::sqlite(file));
        db.exec(sql);
    }
};

TEST_F(AuditVerify, AnUntouchedTrailIsIntact) {
    const QString file = trail(8);
    const CliResult r = runTrueturn({"audit", "verify", "--db", file, "--json"});
    EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_TRUE(j.value("intact").toBool());
    EXPECT_EQ(j.value("rows").toInt(), 8);
    EXPECT_EQ(j.value("head_hash").toString().size(), 64);
    const CliResult text = runTrueturn({"audit", "verify", "--db", file});
    EXPECT_EQ(text.exitCode, 0);
    EXPECT_TRUE(text.out.contains(QStringLiteral("the chain is intact"))) << qPrintable(text.out);
}

TEST_F(AuditVerify, AnEditedADeletedAndAnInsertedRowAreNamedAndExitOne) {
    const QString file = trail(8);
    exec(file, QStringLiteral("UPDATE audit SET changed_by = 'Boris' WHERE id = 2"));
    exec(file, QStringLiteral("DELETE FROM audit WHERE id = 5"));
    exec(file, QStringLiteral("INSERT INTO audit (changed_at, changed_by, role, category, subject, field, old_value,"
                              " new_value) VALUES ('2026-03-01T08:00:00.000Z', 'Boris', 'engineer', 'setting',"
                              " 'terminal', 'contrast', '8', '9')"));
    const CliResult r = runTrueturn({"audit", "verify", "--db", file, "--json"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err.trimmed().count(QLatin1Char('\n')), 0) << "one line: " << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("3 problem(s)"))) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_FALSE(j.value("intact").toBool());
    QStringList found;
    for (const QJsonValue p : j.value("problems").toArray())
        found << QStringLiteral("%1 %2")
                     .arg(p.toObject().value("kind").toString())
                     .arg(p.toObject().value("row_id").toInt());
    found.sort();
    EXPECT_EQ(found, (QStringList{"deleted 6", "edited 2", "inserted 9"})) << qPrintable(found.join(", "));
    const CliResult text = runTrueturn({"audit", "verify", "--db", file});
    EXPECT_EQ(text.exitCode, 1);
    for (const char* phrase : {"edited: row 2 was edited", "deleted: 1 row(s) deleted between row 4 and row 6",
                               "inserted: row 9 has no hash", "the chain is broken: 3 problem(s)"})
        EXPECT_TRUE(text.out.contains(QString::fromUtf8(phrase))) << phrase << " in: " << qPrintable(text.out);
}

TEST_F(AuditVerify, BadInputIsRefused) {
    expectRefused({"audit", "verify"}, QStringLiteral("--db: is required"));
    expectRefused({"audit", "check", "--db", "x.sqlite"}, QStringLiteral("'check' is not an audit action"));
    expectRefused({"audit", "verify", "--db", path(QStringLiteral("none.sqlite"))}, QStringLiteral("does not exist"));
    const QString empty = path(QStringLiteral("empty.sqlite"));
    { storage::Database db(storage::DatabaseConfig::sqlite(empty)); }
    expectRefused({"audit", "verify", "--db", empty}, QStringLiteral("has no chained audit trail"));
}

}  // namespace
