#pragma once

#include <QSqlQuery>
#include <QString>
#include <QVariantList>
#include <cstdint>

#include "core/storage/database.h"

struct sqlite3_stmt;

namespace tt::storage {

/// The rows of a read whose columns are all numbers, taken once, front to back (the million readings of a
/// report). On SQLite they are read through SQLite's own interface on the connection QtSql opened: QtSql builds
/// and converts a QVariant per value, which was 40 % of reading a million readings (docs/BENCHMARKS.md, "The
/// plant-wide history"). On PostgreSQL through a QSqlQuery. A NULL reads as 0, as QVariant converts it.
class NumericRows {
public:
    /// Prepares and runs `sql` (positional `?` bindings: integers, reals, texts); throws StorageError.
    NumericRows(Database& db, const QString& sql, const QVariantList& bindings);
    ~NumericRows();
    NumericRows(const NumericRows&) = delete;
    NumericRows& operator=(const NumericRows&) = delete;

    /// Moves to the next row; false after the last. Throws StorageError when the read fails.
    bool next();
    std::int64_t integer(int column) const;
    double real(int column) const;

private:
    void prepareSqlite(Database& db, const QString& sql, const QVariantList& bindings);
    void bindSqlite(const QVariantList& bindings);

    QString m_sql;
    sqlite3_stmt* m_statement = nullptr;  ///< SQLite: the statement; null on PostgreSQL
    QSqlQuery m_query;                    ///< PostgreSQL
};

}  // namespace tt::storage
