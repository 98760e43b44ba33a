#include "core/storage/numeric_rows.h"

#include <sqlite3.h>

#include <QSqlDriver>
#include <QSqlError>
#include <string>

namespace tt::storage {

namespace {

StorageError readFailed(const QString& sql, const std::string& why) {
    return StorageError("reading the history failed: " + why + " [" + sql.left(80).toStdString() + "]");
}

/// The sqlite3 handle under a QSQLITE connection (Qt's documented QSqlDriver::handle()).
sqlite3* sqliteHandle(Database& db) {
    const QVariant handle = db.connection().driver()->handle();
    if (!handle.isValid() || qstrcmp(handle.typeName(), "sqlite3*") != 0) return nullptr;
    return *static_cast<sqlite3* const*>(handle.constData());
}

}  // namespace

NumericRows::NumericRows(Database& db, const QString& sql, const QVariantList& bindings) : m_sql(sql) {
    if (!db.isPostgres()) {
        prepareSqlite(db, sql, bindings);
        return;
    }
    m_query = QSqlQuery(db.connection());
    bool ok = m_query.prepare(db.dialectSql(sql));
    if (ok) {
        for (const QVariant& value : bindings)
            m_query.addBindValue(value);
        ok = m_query.exec();
    }
    if (!ok) throw readFailed(sql, m_query.lastError().text().trimmed().toStdString());
}

NumericRows::~NumericRows() {
    if (m_statement) sqlite3_finalize(m_statement);
}

void NumericRows::prepareSqlite(Database& db, const QString& sql, const QVariantList& bindings) {
    sqlite3* handle = sqliteHandle(db);
    if (!handle) throw readFailed(sql, "the SQLite connection is not open");
    const QByteArray text = db.dialectSql(sql).toUtf8();
    if (sqlite3_prepare_v2(handle, text.constData(), static_cast<int>(text.size()), &m_statement, nullptr) != SQLITE_OK)
        throw readFailed(sql, sqlite3_errmsg(handle));
    bindSqlite(bindings);
}

void NumericRows::bindSqlite(const QVariantList& bindings) {
    for (int i = 0; i < bindings.size(); ++i) {
        const QVariant& v = bindings[i];
        int rc = SQLITE_OK;
        if (v.isNull()) {
            rc = sqlite3_bind_null(m_statement, i + 1);
        } else if (v.typeId() == QMetaType::Double || v.typeId() == QMetaType::Float) {
            rc = sqlite3_bind_double(m_statement, i + 1, v.toDouble());
        } else if (v.typeId() == QMetaType::QString || v.typeId() == QMetaType::QByteArray) {
            const QByteArray utf8 = v.toString().toUtf8();
            rc = sqlite3_bind_text(m_statement, i + 1, utf8.constData(), static_cast<int>(utf8.size()),
                                   SQLITE_TRANSIENT);
        } else {
            rc = sqlite3_bind_int64(m_statement, i + 1, v.toLongLong());
        }
        if (rc != SQLITE_OK) throw readFailed(m_sql, "binding value " + std::to_string(i + 1) + " failed");
    }
}

bool NumericRows::next() {
    if (!m_statement) return m_query.next();
    const int rc = sqlite3_step(m_statement);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw readFailed(m_sql, sqlite3_errmsg(sqlite3_db_handle(m_statement)));
}

std::int64_t NumericRows::integer(int column) const {
    if (m_statement) return sqlite3_column_int64(m_statement, column);
    return m_query.value(column).toLongLong();
}

double NumericRows::real(int column) const {
    if (m_statement) return sqlite3_column_double(m_statement, column);
    return m_query.value(column).toDouble();
}

}  // namespace tt::storage
