// The history a terminal's runs write (runtime::TerminalHistory): an SQLite file is the history itself, with no
// forwarder; a plant database is written through the terminal's journal, which takes parts while the plant
// database cannot be reached (a closed port here) and says so through the forwarder's status.
#include "runtime/history/terminal_history.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "tests/support/patient_wait.h"

namespace tt::runtime {
namespace {

core::RunDescription aRun(const std::string& machine) {
    return {"paper-2012", "lqg", 1, 27.0, 325.0, {0.0, 100.0}, "{}", machine};
}

/// A port on 127.0.0.1 nobody listens on (TCP port 1, tcpmux, is served by nothing here).
constexpr int kClosedPort = 1;

TEST(TerminalHistory, AnSqliteFileIsTheHistoryWithoutAForwarder) {
    QTemporaryDir dir;
    TerminalHistoryOptions options;
    options.location = dir.filePath(QStringLiteral("history.sqlite"));
    TerminalHistory history(options);
    EXPECT_EQ(history.forwarder(), nullptr);
    EXPECT_EQ(history.journal(), nullptr);
    const std::int64_t run = history.store().beginRun(aRun("L1"));
    EXPECT_EQ(history.store().runs().size(), 1u);
    EXPECT_EQ(history.store().runs().front().runId, run);
    EXPECT_TRUE(history.drain(0.0));
    EXPECT_TRUE(QFile::exists(options.location));
}

TEST(TerminalHistory, APlantDatabaseThatCannotBeReachedLeavesTheRunsInTheJournal) {
    QTemporaryDir dir;
    TerminalHistoryOptions options;
    options.location = QStringLiteral("postgresql://terminal@127.0.0.1:%1/plant").arg(kClosedPort);
    options.machine = QStringLiteral("L7");
    options.journalPath = dir.filePath(QStringLiteral("journal.sqlite"));
    TerminalHistory history(options);
    ASSERT_NE(history.forwarder(), nullptr);
    ASSERT_NE(history.journal(), nullptr);
    history.store().beginRun(aRun("L7"));
    history.startForwarding();
    QElapsedTimer waited;
    waited.start();
    while (history.forwarder()->status().link != storage::ForwarderStatus::Link::Offline &&
           waited.elapsed() < tt::test::kPatientWaitMs)
        QTest::qWait(20);
    const storage::ForwarderStatus status = history.forwarder()->status();
    EXPECT_EQ(status.link, storage::ForwarderStatus::Link::Offline);
    EXPECT_TRUE(status.reason.contains(QLatin1String("cannot connect"))) << status.reason.toStdString();
    EXPECT_FALSE(history.drain(0.0));
    EXPECT_EQ(history.store().runs().size(), 1u);
    EXPECT_TRUE(QFile::exists(options.journalPath));
}

TEST(TerminalHistory, APlantDatabaseNeedsTheLathesName) {
    TerminalHistoryOptions options;
    options.location = QStringLiteral("postgresql://terminal@127.0.0.1:5432/plant");
    options.machine = QStringLiteral("  ");
    try {
        TerminalHistory history(options);
        FAIL() << "a journal without a machine was opened";
    } catch (const TerminalHistoryError& e) {
        EXPECT_EQ(e.part(), TerminalHistoryError::Part::Journal);
        EXPECT_TRUE(QString::fromUtf8(e.what()).contains(QLatin1String("name is empty"))) << e.what();
    }
}

TEST(TerminalHistory, ABadLocationIsTheDatabasesFault) {
    TerminalHistoryOptions options;
    options.location = QStringLiteral("postgresql://");
    options.machine = QStringLiteral("L7");
    try {
        TerminalHistory history(options);
        FAIL() << "a URL without a host was taken";
    } catch (const TerminalHistoryError& e) {
        EXPECT_EQ(e.part(), TerminalHistoryError::Part::Database);
    }
}

TEST(TerminalHistory, TellsAPlantDatabaseFromAFile) {
    EXPECT_TRUE(isPlantDatabase(QStringLiteral("postgresql://a@b/c")));
    EXPECT_TRUE(isPlantDatabase(QStringLiteral(" postgres://a@b/c")));
    EXPECT_FALSE(isPlantDatabase(QStringLiteral("/var/lib/trueturn/history.sqlite")));
    EXPECT_FALSE(isPlantDatabase(QString()));
}

}  // namespace
}  // namespace tt::runtime
