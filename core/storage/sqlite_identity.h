#pragma once

#include <QString>
#include <QStringList>

namespace tt::storage {

/// Checks, before the history file `path` is opened for writing, that TrueTurn may write it: its
/// folder is writable (SQLite writes its journal beside the file) and an existing file, opened
/// read-only, is empty or holds a `schema_versions` table (TrueTurn's). Changes nothing of the file.
/// Throws StorageError: "... is read-only", "... is not a TrueTurn database (it holds the tables
/// ...); it was left untouched" or "... is damaged or not a TrueTurn database (...)".
void requireTrueTurnSqliteFile(const QString& path);

/// The side files SQLite keeps beside a database file (`-wal`, `-shm`, `-journal`) that do not exist when
/// this is made: nothing may be left beside a file TrueTurn refuses (a read-only connection to a damaged file
/// in WAL mode creates `-wal` and `-shm` and cannot remove them when it closes).
class SqliteSideFiles {
public:
    explicit SqliteSideFiles(const QString& path);
    /// Removes those of them that exist now, unless another process holds a lock on the file or its `-shm`
    /// (it has the file open: the side files are its too). Call after this process's connection is closed.
    void removeCreated() const;

private:
    QString m_path;
    QStringList m_absent;
};

}  // namespace tt::storage
