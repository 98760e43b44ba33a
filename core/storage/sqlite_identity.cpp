#include "core/storage/sqlite_identity.h"

#include <QFile>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <QUuid>

#include "core/storage/database.h"
#include "core/storage/sqlite_lock_holder.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

namespace tt::storage {

namespace {

/// A StorageError with the message `text` (QString::arg placeholders filled in by the caller).
StorageError storageError(const QString& text) {
    return StorageError(text.toStdString());
}

void requireWritableFolder(const QString& path) {
    const QFileInfo folder(QFileInfo(path).absolutePath());
    if (!folder.exists())
        throw storageError(QStringLiteral("the folder '%1' of the history file does not exist").arg(folder.filePath()));
    if (!folder.isWritable())
        throw storageError(
            QStringLiteral("the folder '%1' of the history file '%2' is read-only (SQLite writes its journal beside "
                           "the file)")
                .arg(folder.filePath(), path));
}

/// Whether another process holds any POSIX lock (read or write) on `file` (/proc/locks; false when unknown).
bool lockedByOtherProcess(const QString& file) {
    struct stat st {};
    if (::stat(QFile::encodeName(file).constData(), &st) != 0) return false;
    std::ifstream in("/proc/locks");
    std::stringstream text;
    text << in.rdbuf();
    for (const FileLock& l : parseProcLocks(text.str()))
        if (l.pid != ::getpid() && l.major == ::major(st.st_dev) && l.minor == ::minor(st.st_dev) &&
            l.inode == st.st_ino)
            return true;
    return false;
}

/// The user tables of the SQLite file at `path`, read over a read-only connection; throws on a file
/// that SQLite cannot read, with the side files the connection created removed.
QStringList tablesReadOnly(const QString& path) {
    const SqliteSideFiles sideFiles(path);
    const QString name = QStringLiteral("trueturn-identify-") + QUuid::createUuid().toString();
    QStringList tables;
    QString error;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        if (!db.open()) {
            error = db.lastError().text();
        } else {
            QSqlQuery q(db);
            if (q.exec(QStringLiteral("SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE "
                                      "'sqlite_%' ORDER BY name"))) {
                while (q.next())
                    tables << q.value(0).toString();
            } else {
                error = q.lastError().text();
            }
        }
        db.close();
    }
    QSqlDatabase::removeDatabase(name);
    if (!error.isEmpty()) {
        sideFiles.removeCreated();
        throw storageError(
            QStringLiteral("the history file '%1' is damaged or not a TrueTurn database (%2); it was left untouched")
                .arg(path, error));
    }
    return tables;
}

}  // namespace

SqliteSideFiles::SqliteSideFiles(const QString& path) : m_path(path) {
    for (const char* suffix : {"-wal", "-shm", "-journal"})
        if (!QFileInfo::exists(path + QLatin1String(suffix))) m_absent << path + QLatin1String(suffix);
}

void SqliteSideFiles::removeCreated() const {
    if (lockedByOtherProcess(m_path) || lockedByOtherProcess(m_path + QStringLiteral("-shm"))) return;
    for (const QString& file : m_absent)
        QFile::remove(file);
}

void requireTrueTurnSqliteFile(const QString& path) {
    requireWritableFolder(path);
    const QFileInfo file(path);
    if (!file.exists() || file.size() == 0) return;
    if (!file.isWritable()) throw storageError(QStringLiteral("the history file '%1' is read-only").arg(path));
    const SqliteSideFiles sideFiles(path);
    const QStringList tables = tablesReadOnly(path);
    if (tables.isEmpty() || tables.contains(QStringLiteral("schema_versions"))) return;
    sideFiles.removeCreated();
    QString shown = tables.mid(0, 5).join(QStringLiteral(", "));
    if (tables.size() > 5) shown += QStringLiteral(", ...");
    throw storageError(
        QStringLiteral("the file '%1' is not a TrueTurn database (it holds the tables %2); it was left untouched")
            .arg(path, shown));
}

}  // namespace tt::storage
