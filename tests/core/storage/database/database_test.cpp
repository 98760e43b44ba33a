#include "core/storage/database.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QSqlQuery>

#include "scratch_database.h"

namespace tt::storage {
namespace {

SchemaModule sampleModule(int versions) {
    SchemaModule module{QStringLiteral("sample"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("parts"),
         [](Database& db) { db.exec(QStringLiteral("CREATE TABLE parts (id {pk}, diameter_mm {real} NOT NULL)")); }});
    if (versions >= 2)
        module.migrations.push_back({2, QStringLiteral("points"), [](Database& db) {
                                         db.exec(QStringLiteral(
                                             "CREATE TABLE points (id {pk}, part_id {bigint} NOT NULL "
                                             "REFERENCES parts(id) ON DELETE CASCADE, x_mm {real} NOT NULL)"));
                                     }});
    return module;
}

qint64 countRows(Database& db, const QString& table) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT COUNT(*) FROM ") + table);
    return q.next() ? q.value(0).toLongLong() : -1;
}

class DatabaseTest : public ::testing::TestWithParam<std::string> {};

TEST_P(DatabaseTest, MigratesModulesInOrderAndOnlyOnce) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    EXPECT_EQ(db.schemaVersion(QStringLiteral("sample")), 0);
    db.migrate(sampleModule(1));
    EXPECT_EQ(db.schemaVersion(QStringLiteral("sample")), 1);
    db.migrate(sampleModule(2));
    db.migrate(sampleModule(2));
    EXPECT_EQ(db.schemaVersion(QStringLiteral("sample")), 2);
    EXPECT_EQ(countRows(db, QStringLiteral("schema_versions")), 2);
}

TEST_P(DatabaseTest, RefusesASchemaNewerThanItKnows) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    db.migrate(sampleModule(2));
    try {
        db.migrate(sampleModule(1));
        FAIL() << "expected a refusal";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("newer than this TrueTurn knows"), std::string::npos) << e.what();
    }
}

TEST_P(DatabaseTest, TransactionRollsBackOnException) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    db.migrate(sampleModule(1));
    db.transaction([&] { db.exec(QStringLiteral("INSERT INTO parts (diameter_mm) VALUES (?)"), {27.0}); });
    EXPECT_THROW(db.transaction([&] {
        db.exec(QStringLiteral("INSERT INTO parts (diameter_mm) VALUES (?)"), {26.5});
        throw std::runtime_error("gauge failed mid-part");
    }),
                 std::runtime_error);
    EXPECT_EQ(countRows(db, QStringLiteral("parts")), 1);
}

TEST_P(DatabaseTest, EnforcesForeignKeys) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    db.migrate(sampleModule(2));
    EXPECT_THROW(db.exec(QStringLiteral("INSERT INTO points (part_id, x_mm) VALUES (?, ?)"), {999, 12.5}),
                 StorageError);
    QSqlQuery insert = db.exec(QStringLiteral("INSERT INTO parts (diameter_mm) VALUES (?)"), {24.8});
    const qint64 id = db.lastInsertId(insert);
    db.exec(QStringLiteral("INSERT INTO points (part_id, x_mm) VALUES (?, ?)"), {id, 162.5});
    db.exec(QStringLiteral("DELETE FROM parts WHERE id = ?"), {id});
    EXPECT_EQ(countRows(db, QStringLiteral("points")), 0) << "ON DELETE CASCADE";
}

INSTANTIATE_TEST_SUITE_P(Backends, DatabaseTest, ::testing::ValuesIn(test::backends()));

TEST(SqliteDatabase, UsesWriteAheadLog) {
    test::ScratchDatabase scratch("sqlite");
    Database db(scratch.config());
    QSqlQuery q = db.exec(QStringLiteral("PRAGMA journal_mode"));
    ASSERT_TRUE(q.next());
    EXPECT_EQ(q.value(0).toString(), QStringLiteral("wal"));
}

TEST(SqliteDatabase, DamagedFileIsReportedAndLeftUntouched) {
    test::ScratchDatabase scratch("sqlite");
    const QByteArray garbage = QByteArray("not a database at all, just bytes").repeated(200);
    {
        QFile f(scratch.config().sqlitePath);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(garbage);
    }
    try {
        Database db(scratch.config());
        FAIL() << "expected StorageError";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("is damaged or not a TrueTurn database"), std::string::npos) << e.what();
    }
    QFile f(scratch.config().sqlitePath);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), garbage);
}

TEST(DatabaseConfig, ParsesPostgresUrlsAndRejectsOthers) {
    const DatabaseConfig c =
        DatabaseConfig::postgresUrl(QStringLiteral("postgresql://qe:secret@db.plant:6543/history"));
    EXPECT_EQ(c.host, QStringLiteral("db.plant"));
    EXPECT_EQ(c.port, 6543);
    EXPECT_EQ(c.databaseName, QStringLiteral("history"));
    EXPECT_EQ(c.user, QStringLiteral("qe"));
    EXPECT_EQ(c.password, QStringLiteral("secret"));
    EXPECT_FALSE(c.describe().contains(QStringLiteral("secret")));
    EXPECT_THROW(DatabaseConfig::postgresUrl(QStringLiteral("mysql://x@y/z")), StorageError);
    EXPECT_THROW(DatabaseConfig::postgresUrl(QStringLiteral("postgresql://x@y")), StorageError);
}

TEST(PostgresDatabase, UnreachableServerIsReportedClearly) {
    DatabaseConfig c = DatabaseConfig::postgresUrl(QStringLiteral("postgresql://nobody@127.0.0.1:1/none"));
    try {
        Database db(c);
        FAIL() << "expected StorageError";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot connect to PostgreSQL nobody@127.0.0.1:1/none"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace tt::storage
