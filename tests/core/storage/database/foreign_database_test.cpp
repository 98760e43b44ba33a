#include <gtest/gtest.h>

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileDevice>
#include <QProcess>
#include <QTemporaryDir>
#include <string>

#include "core/storage/database.h"

// Someone else's SQLite file passed as the history (issue 17, item 4): it must be identified read-only
// and left byte for byte as it was; a read-only folder is reported as read-only, not as damaged.

namespace tt::storage {
namespace {

/// Runs sqlite3 (Debian package sqlite3) on `path` with `sql`; fails the test when it does not work.
void sqlite3(const QString& path, const QString& sql) {
    QProcess p;
    p.start(QStringLiteral("sqlite3"), {path, sql});
    ASSERT_TRUE(p.waitForFinished(30000));
    ASSERT_EQ(p.exitCode(), 0) << p.readAllStandardError().constData();
}

QByteArray sha256(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256).toHex();
}

std::string openError(const QString& path) {
    try {
        Database db(DatabaseConfig::sqlite(path));
    } catch (const StorageError& e) {
        return e.what();
    }
    return "opened";
}

TEST(ForeignDatabase, IsRefusedAndLeftByteForByte) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("accounts.db"));
    sqlite3(path, QStringLiteral("CREATE TABLE invoices (id INTEGER PRIMARY KEY, total REAL);"
                                 "INSERT INTO invoices (total) VALUES (12.5);"));
    const QByteArray before = sha256(path);
    const std::string error = openError(path);
    EXPECT_NE(error.find("not a TrueTurn database"), std::string::npos) << error;
    EXPECT_NE(error.find("invoices"), std::string::npos) << error;
    EXPECT_EQ(sha256(path).toStdString(), before.toStdString());
    EXPECT_FALSE(QFile::exists(path + QStringLiteral("-wal")));
    EXPECT_FALSE(QFile::exists(path + QStringLiteral("-shm")));
}

TEST(ForeignDatabase, AnEmptyFileAndATrueTurnFileStillOpen) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.db"));
    EXPECT_EQ(openError(path), "opened");  // created
    EXPECT_EQ(openError(path), "opened");  // TrueTurn's own file, opened again
}

TEST(ForeignDatabase, AReadOnlyFolderIsReportedAsReadOnly) {
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("locked"));
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString path = folder + QStringLiteral("/history.db");
    ASSERT_EQ(openError(path), "opened");
    ASSERT_TRUE(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
    if (QFileInfo(folder).isWritable()) GTEST_SKIP() << "running as root: a folder cannot be made read-only";
    const std::string existing = openError(path);
    const std::string fresh = openError(folder + QStringLiteral("/new.db"));
    QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    EXPECT_NE(existing.find("read-only"), std::string::npos) << existing;
    EXPECT_EQ(existing.find("damaged"), std::string::npos) << existing;
    EXPECT_NE(fresh.find("read-only"), std::string::npos) << fresh;
}

}  // namespace
}  // namespace tt::storage
