#include <gtest/gtest.h>

#include <unistd.h>

#include <QDir>
#include <QFile>
#include <QProcess>

#include "cli_test.h"
#include "tests/support/patient_wait.h"

// The history file when someone else has it (issue 17, item 4): a second writer waits for the busy
// timeout and then names the process that holds the lock; a read-only folder is reported as
// read-only, not as damaged (also when the tests run as root: the command then runs as 'nobody').

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

class DatabaseAccess : public tt::test::CliTest {
protected:
    static QStringList simulate(const QString& db) {
        return {
            QStringLiteral("simulate"), QStringLiteral("--parts"), QStringLiteral("100"), QStringLiteral("--db"), db,
            QStringLiteral("--json")};
    }

    /// Runs trueturn with `args` as an unprivileged user: as 'nobody' through setpriv when the tests run
    /// as root (root writes into any folder), else as the test's own user.
    static CliResult runUnprivileged(const QStringList& args) {
        if (::geteuid() != 0) return runTrueturn(args);
        QProcess process;
        process.start(QStringLiteral("setpriv"),
                      QStringList{QStringLiteral("--reuid=65534"), QStringLiteral("--regid=65534"),
                                  QStringLiteral("--clear-groups"), QStringLiteral(TRUETURN_EXE)} +
                          args);
        process.waitForFinished(tt::test::kPatientWaitMs);
        return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
                QString::fromUtf8(process.readAllStandardOutput()), QString::fromUtf8(process.readAllStandardError())};
    }
};

TEST_F(DatabaseAccess, ASecondWriterWaitsAndThenNamesTheProcessHoldingTheLock) {
    const QString db = path(QStringLiteral("busy.sqlite"));
    ASSERT_EQ(runTrueturn(simulate(db)).exitCode, 0);
    // The sqlite3 shell takes the write lock and keeps it until its input ends.
    QProcess holder;
    holder.start(QStringLiteral("sqlite3"), {db});
    ASSERT_TRUE(holder.waitForStarted());
    holder.write("BEGIN IMMEDIATE;\nSELECT 'held';\n");
    QByteArray answer;
    while (!answer.contains("held") && holder.waitForReadyRead(tt::test::kPatientWaitMs))
        answer += holder.readAllStandardOutput();
    ASSERT_TRUE(answer.contains("held"));

    // Opening the history writes nothing (the schema is current), so the writer meets the lock at the run's first
    // part: it waits the busy timeout (30 s), then the run stops (exit 1) naming the holder; nothing was stored.
    const CliResult r = runTrueturn(simulate(db));
    EXPECT_EQ(r.exitCode, 1) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("kept the file locked for more than 30 s"))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("held by process %1 (sqlite3)").arg(holder.processId())))
        << qPrintable(r.err);
    EXPECT_EQ(r.err.trimmed().count(QLatin1Char('\n')), 0) << qPrintable(r.err);

    holder.closeWriteChannel();  // the shell ends, its transaction is rolled back
    ASSERT_TRUE(holder.waitForFinished(tt::test::kPatientWaitMs));
    EXPECT_EQ(runTrueturn(simulate(db)).exitCode, 0);
}

TEST_F(DatabaseAccess, AReadOnlyFolderIsReportedAsReadOnlyNotDamaged) {
    const QString folder = path(QStringLiteral("locked"));
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString existing = folder + QStringLiteral("/history.db");
    const auto readable = QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                          QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther;
    const auto writable = QFileDevice::WriteOwner | QFileDevice::WriteGroup | QFileDevice::WriteOther;
    ASSERT_TRUE(QFile::setPermissions(m_dir.path(), readable | QFileDevice::WriteOwner));
    ASSERT_TRUE(QFile::setPermissions(folder, readable | writable));
    const CliResult created = runUnprivileged(simulate(existing));  // while the folder is writable
    ASSERT_EQ(created.exitCode, 0) << qPrintable(created.err);
    ASSERT_TRUE(QFile::setPermissions(folder, readable));

    const CliResult old = runUnprivileged(simulate(existing));
    const CliResult fresh = runUnprivileged(simulate(folder + QStringLiteral("/new.db")));
    QFile::setPermissions(folder, readable | QFileDevice::WriteOwner);
    EXPECT_EQ(old.exitCode, 2);
    EXPECT_TRUE(old.err.contains(QStringLiteral("read-only"))) << qPrintable(old.err);
    EXPECT_FALSE(old.err.contains(QStringLiteral("damaged"))) << qPrintable(old.err);
    EXPECT_EQ(fresh.exitCode, 2);
    EXPECT_TRUE(fresh.err.contains(QStringLiteral("the folder '%1'").arg(folder))) << qPrintable(fresh.err);
    EXPECT_TRUE(fresh.err.contains(QStringLiteral("is read-only"))) << qPrintable(fresh.err);
}

}  // namespace
