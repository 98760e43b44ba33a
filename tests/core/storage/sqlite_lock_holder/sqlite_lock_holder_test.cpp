// Who holds an SQLite file's write lock, from /proc/locks (core/storage/sqlite_lock_holder.h).
#include <gtest/gtest.h>

#include <QByteArray>
#include <QProcess>
#include <QTemporaryDir>

#include "core/storage/sqlite_lock_holder.h"

namespace tt::storage {
namespace {

TEST(SqliteLockHolder, ParsesGrantedPosixLocksAndLeavesOutWaitersAndOtherKinds) {
    // Lines as Linux writes them (fs/locks.c, lock_get_status): id, kind, mode, access, pid,
    // major:minor:inode (hex:hex:decimal), start, end (or EOF); waiters carry "->".
    const char* text =
        "1: POSIX  ADVISORY  WRITE 31416 fe:00:10961077 120 120\n"
        "2: POSIX  ADVISORY  READ 31416 fe:00:10961077 128 128\n"
        "2: -> POSIX  ADVISORY  WRITE 2000 fe:00:10961077 120 120\n"
        "3: FLOCK  ADVISORY  WRITE 77 08:01:5 0 EOF\n"
        "4: POSIX  ADVISORY  WRITE 88 08:1f:6 1073741825 EOF\n"
        "5: POSIX  ADVISORY  WRITE notapid 08:01:6 0 1\n";
    const std::vector<FileLock> locks = parseProcLocks(text);
    ASSERT_EQ(locks.size(), 3u);
    EXPECT_EQ(locks[0].pid, 31416);
    EXPECT_TRUE(locks[0].write);
    EXPECT_EQ(locks[0].major, 0xfeu);
    EXPECT_EQ(locks[0].minor, 0u);
    EXPECT_EQ(locks[0].inode, 10961077u);
    EXPECT_EQ(locks[0].start, 120u);
    EXPECT_EQ(locks[0].end, 120u);
    EXPECT_FALSE(locks[1].write);
    EXPECT_EQ(locks[2].pid, 88);
    EXPECT_EQ(locks[2].minor, 0x1fu);
    EXPECT_EQ(locks[2].end, ~0ULL);
}

TEST(SqliteLockHolder, NamesTheProcessThatHoldsTheWalWriteLock) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("held.sqlite"));
    QProcess shell;
    shell.start(QStringLiteral("sqlite3"), {db});
    ASSERT_TRUE(shell.waitForStarted());
    shell.write("PRAGMA journal_mode=WAL;\nCREATE TABLE t (x);\nBEGIN IMMEDIATE;\nSELECT 'held';\n");
    QByteArray answer;
    while (!answer.contains("held") && shell.waitForReadyRead(10000))
        answer += shell.readAllStandardOutput();
    ASSERT_TRUE(answer.contains("held"));
    EXPECT_EQ(sqliteLockHolder(db.toStdString()), "process " + std::to_string(shell.processId()) + " (sqlite3)");
    shell.write("COMMIT;\n");
    shell.write("SELECT 'free';\n");
    answer.clear();
    while (!answer.contains("free") && shell.waitForReadyRead(10000))
        answer += shell.readAllStandardOutput();
    EXPECT_EQ(sqliteLockHolder(db.toStdString()), "");  // nobody writes now
    shell.closeWriteChannel();
    shell.waitForFinished(10000);
}

}  // namespace
}  // namespace tt::storage
