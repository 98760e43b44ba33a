#pragma once

#include <QString>

#include "core/storage/database.h"

namespace tt::cli {

/// The database of a --db option: a PostgreSQL server for "postgresql://user[:password]@host[:port]/database",
/// else an SQLite file at that path. Throws UsageError ("--db: ...") on a malformed URL.
storage::DatabaseConfig databaseConfigFromOption(const QString& value);

/// Whether the --db value names a PostgreSQL server.
bool isPostgresOption(const QString& value);

}  // namespace tt::cli
