// Least privilege on the plant database, with the real roles on a real PostgreSQL server (the history migration
// creates the group roles and the row-level-security policies; scripts/start-test-postgres.sh creates the logins
// terminal_m1 .. terminal_m20 and quality, made here too when the server lacks them): a terminal inserts the
// history of its own machine and nothing else, never updates or deletes history; the quality engineer reads only.
#include <gtest/gtest.h>

#include <QSqlQuery>

#include "core/storage/journal_batch.h"
#include "core/storage/plant_forwarder.h"
#include "core/storage/plant_roles.h"
#include "journal_support.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

qint64 scalar(Database& db, const QString& sql) {
    QSqlQuery q = db.exec(sql);
    return q.next() ? q.value(0).toLongLong() : -1;
}

/// The server's refusal of `sql` as `db`'s role, in its words ("" when it was accepted).
std::string refusal(Database& db, const QString& sql) {
    try {
        db.exec(sql);
        return {};
    } catch (const StorageError& e) {
        return e.what();
    }
}

class PlantRoles : public ::testing::Test {
protected:
    void SetUp() override {
        if (!scratch.available()) {
            if (TRUETURN_POSTGRES_REQUIRED) FAIL() << "TRUETURN_PG_URL is not set";
            GTEST_SKIP() << "needs TRUETURN_PG_URL (scripts/start-test-postgres.sh)";
        }
        owner = std::make_unique<Database>(scratch.config());
        owner->migrate(historySchema());  // as the owner: tables, group roles, policies
        owner->exec(QStringLiteral(
            "DO $$ BEGIN IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = 'terminal_m1') THEN CREATE ROLE "
            "terminal_m1 LOGIN IN ROLE trueturn_terminal; END IF; IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname "
            "= 'quality') THEN CREATE ROLE quality LOGIN IN ROLE trueturn_quality; END IF; END $$"));
        owner->exec(QStringLiteral("INSERT INTO plant_terminals (login, machine) VALUES ('terminal_m1', 'm1')"));
        // Some history of another machine, written by the owner (a terminal role cannot).
        HistoryJournal other(journal(QStringLiteral("m2")));
        const std::int64_t run = other.beginRun(test::plantRun("m2"));
        test::writeParts(other, run, 1, 5);
        other.finishRun(run, "complete");
        writePlantBatch(*owner, readJournalBatch(other.database(), 0, 100));
    }

    JournalOptions journal(const QString& machine) const {
        return {scratch.folder() + QStringLiteral("/") + machine + QStringLiteral(".sqlite"), machine,
                QStringLiteral("plant"), kDefaultJournalLimitBytes};
    }
    DatabaseConfig as(const char* login) const {
        DatabaseConfig c = scratch.config();
        c.user = QString::fromLatin1(login);
        c.password.clear();
        return c;
    }

    test::ScratchDatabase scratch{"postgres"};
    std::unique_ptr<Database> owner;
};

TEST_F(PlantRoles, ATerminalForwardsItsOwnMachineAndNeverAnothers) {
    // Its own machine: the whole forwarding path under the terminal's role.
    const JournalOptions m1 = journal(QStringLiteral("m1"));
    {
        HistoryJournal j(m1);
        const std::int64_t run = j.beginRun(test::plantRun("m1"));
        test::writeParts(j, run, 1, 20);
        j.finishRun(run, "complete");
    }
    PlantForwarder forwarder(m1.path, as("terminal_m1"), m1.machine, m1.limitBytes);
    while (forwarder.sendBatch()) {
    }
    EXPECT_EQ(scalar(*owner, QStringLiteral("SELECT COUNT(*) FROM parts p JOIN runs r ON r.id = p.run_id WHERE"
                                            " r.machine = 'm1'")),
              20);
    // A journal of machine m2 forwarded with m1's login: refused by the server, nothing of it kept.
    const JournalOptions m2 = journal(QStringLiteral("m2-again"));
    {
        JournalOptions o = m2;
        o.machine = QStringLiteral("m2");
        HistoryJournal j(o);
        const std::int64_t run = j.beginRun(test::plantRun("m2"));
        test::writeParts(j, run, 1, 3);
    }
    PlantForwarder wrong(m2.path, as("terminal_m1"), QStringLiteral("m2"), m2.limitBytes);
    try {
        wrong.sendBatch();
        FAIL() << "the server took another machine's run";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("row-level security"), std::string::npos) << e.what();
    }
    EXPECT_EQ(scalar(*owner, QStringLiteral("SELECT COUNT(*) FROM runs WHERE machine = 'm2'")), 1);

    Database terminal(as("terminal_m1"));
    // Rows of another machine's run, straight in SQL: refused by the row-level security.
    const qint64 otherRun = scalar(*owner, QStringLiteral("SELECT id FROM runs WHERE machine = 'm2'"));
    EXPECT_NE(refusal(terminal, QStringLiteral("INSERT INTO parts (run_id, part_number, started_s, finished_s,"
                                               " recorded_at) VALUES (%1, 99, 0, 1, 'x')")
                                    .arg(otherRun))
                  .find("row-level security"),
              std::string::npos);
    EXPECT_NE(refusal(terminal, QStringLiteral("INSERT INTO runs (started_at, status, preset, controller, delay_parts,"
                                               " nominal_diameter_mm, part_length_mm, settings, machine) VALUES ('x',"
                                               " 'running', 'p', 'lqg', 1, 27, 325, '{}', 'm2')"))
                  .find("row-level security"),
              std::string::npos);
    // It does not even see them.
    EXPECT_EQ(scalar(terminal, QStringLiteral("SELECT COUNT(*) FROM runs WHERE machine = 'm2'")), 0);
    // History is never updated or deleted, not even its own.
    for (const char* sql : {"UPDATE measurements SET measured_mm = 27.0", "UPDATE parts SET finished_s = 0",
                            "UPDATE runs SET status = 'complete'", "DELETE FROM measurements", "DELETE FROM parts",
                            "DELETE FROM runs", "DELETE FROM alarms", "TRUNCATE measurements"}) {
        SCOPED_TRACE(sql);
        EXPECT_NE(refusal(terminal, QString::fromLatin1(sql)).find("permission denied"), std::string::npos);
    }
    EXPECT_EQ(scalar(*owner, QStringLiteral("SELECT COUNT(*) FROM measurements")), 125);
}

TEST_F(PlantRoles, TheQualityEngineerReadsEverythingAndChangesNothing) {
    Database quality(as("quality"));
    EXPECT_EQ(scalar(quality, QStringLiteral("SELECT COUNT(*) FROM measurements")), 25);
    EXPECT_EQ(scalar(quality, QStringLiteral("SELECT COUNT(*) FROM runs")), 1);
    for (const char* sql : {"INSERT INTO plant_terminals (login, machine) VALUES ('quality', 'm9')",
                            "UPDATE measurements SET measured_mm = 27.0", "DELETE FROM parts",
                            "INSERT INTO run_ends (run_id, seq, status, finished_at) SELECT id, 9, 'x', 'x' FROM runs"}) {
        SCOPED_TRACE(sql);
        EXPECT_NE(refusal(quality, QString::fromLatin1(sql)).find("permission denied"), std::string::npos);
    }
    EXPECT_EQ(scalar(*owner, QStringLiteral("SELECT COUNT(*) FROM run_ends")), 1);
}

}  // namespace
}  // namespace tt::storage
