#pragma once

#include <QString>

namespace tt::storage {

/// Checks, before the history file `path` is opened for writing, that TrueTurn may write it: its
/// folder is writable (SQLite writes its journal beside the file) and an existing file, opened
/// read-only, is empty or holds a `schema_versions` table (TrueTurn's). Changes nothing of the file.
/// Throws StorageError: "... is read-only", "... is not a TrueTurn database (it holds the tables
/// ...); it was left untouched" or "... is damaged or not a TrueTurn database (...)".
void requireTrueTurnSqliteFile(const QString& path);

}  // namespace tt::storage
