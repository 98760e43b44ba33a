#include "core/storage/database.h"

#include "core/storage/sqlite_identity.h"
#include "core/storage/sqlite_lock_holder.h"
#include "core/storage/storage_log.h"

#include <QDateTime>
#include <QFileInfo>
#include <QSqlError>
#include <QStringList>
#include <QUrl>
#include <QUuid>
#include <chrono>
#include <thread>

namespace tt::storage {

namespace {

/// Whether SQLite gave up waiting for another connection's lock (SQLITE_BUSY or SQLITE_LOCKED).
bool isBusy(const QSqlError& error) {
    return error.nativeErrorCode() == u"5" || error.nativeErrorCode() == u"6" ||
           error.databaseText().contains(QLatin1String("database is locked"));
}

/// The error's text; for an SQLite file (`sqlitePath` not empty) that another writer kept locked past the
/// busy timeout, also who holds the lock (sqliteLockHolder).
QString sqlError(const QSqlError& error, const QString& sqlitePath = QString()) {
    const QString text = (error.databaseText().isEmpty() ? error.text() : error.databaseText()).trimmed();
    if (sqlitePath.isEmpty() || !isBusy(error)) return text;
    const std::string holder = sqliteLockHolder(sqlitePath.toStdString());
    return QStringLiteral("%1: another program kept the file locked for more than %2 s (%3)")
        .arg(text)
        .arg(kSqliteBusyTimeoutMs / 1000)
        .arg(holder.empty() ? QStringLiteral("its process could not be found out")
                            : QStringLiteral("held by %1").arg(QString::fromStdString(holder)));
}

/// Runs `statement`, trying again while SQLite reports the file busy, up to the busy timeout. Switching a new file to
/// WAL takes an exclusive lock, and SQLite answers "database is locked" at once, without its busy handler, when two
/// processes open the same new file together (each holds the shared lock the other needs to give up).
bool execWaitingForLocks(QSqlQuery& query, const QString& statement) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kSqliteBusyTimeoutMs);
    while (!query.exec(statement)) {
        if (!isBusy(query.lastError()) || std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

}  // namespace

DatabaseConfig DatabaseConfig::sqlite(const QString& path) {
    DatabaseConfig c;
    c.kind = Kind::Sqlite;
    c.sqlitePath = path;
    return c;
}

DatabaseConfig DatabaseConfig::postgresUrl(const QString& url) {
    const QUrl u(url, QUrl::StrictMode);
    if (!u.isValid() || (u.scheme() != u"postgresql" && u.scheme() != u"postgres") || u.path().size() < 2)
        throw StorageError("'" + url.toStdString() + "' is not a PostgreSQL address like postgresql://user@host/db");
    DatabaseConfig c;
    c.kind = Kind::Postgres;
    c.host = u.host();
    c.port = u.port(5432);
    c.databaseName = u.path().mid(1);
    c.user = u.userName();
    c.password = u.password();
    return c;
}

QString DatabaseConfig::describe() const {
    if (kind == Kind::Sqlite) return QStringLiteral("SQLite %1").arg(sqlitePath);
    return QStringLiteral("PostgreSQL %1@%2:%3/%4").arg(user, host).arg(port).arg(databaseName);
}

Database::Database(const DatabaseConfig& config)
    : m_config(config), m_connectionName(QStringLiteral("trueturn-") + QUuid::createUuid().toString()) {
    const bool sqlite = config.kind == DatabaseConfig::Kind::Sqlite;
    const std::optional<SqliteSideFiles> sideFiles =
        sqlite ? std::optional<SqliteSideFiles>(SqliteSideFiles(config.sqlitePath)) : std::nullopt;
    try {
        if (sqlite)
            openSqlite();
        else
            openPostgres();
        ensureVersionTable();
    } catch (...) {
        // The destructor does not run for a constructor that throws: close here, or the connection stays
        // open until the process ends and SQLite never removes the side files it made beside a refused file.
        closeConnection();
        if (sideFiles) sideFiles->removeCreated();
        throw;
    }
    qCInfo(lcStorage).noquote() << "opened" << config.describe();
}

Database::~Database() {
    closeConnection();
}

void Database::closeConnection() {
    {
        QSqlDatabase db = QSqlDatabase::database(m_connectionName, false);
        if (db.isOpen()) db.close();
    }
    QSqlDatabase::removeDatabase(m_connectionName);
}

QSqlDatabase Database::connection() const {
    return QSqlDatabase::database(m_connectionName, false);
}

void Database::openSqlite() {
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QSQLITE")))
        throw StorageError("the SQLite driver of Qt is not installed (package libqt6sql6-sqlite)");
    const QFileInfo file(m_config.sqlitePath);
    if (file.exists() && !file.isWritable())
        throw StorageError("the history file '" + m_config.sqlitePath.toStdString() + "' is read-only");
    requireTrueTurnSqliteFile(m_config.sqlitePath);
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_connectionName);
    db.setDatabaseName(m_config.sqlitePath);
    // A writer waits for another (several lathes or processes on one file) instead of failing at once
    // with "database is locked"; set before the first statement, which may already need a lock.
    db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(kSqliteBusyTimeoutMs));
    if (!db.open())
        throw StorageError("cannot open the history file '" + m_config.sqlitePath.toStdString() +
                           "': " + sqlError(db.lastError(), m_config.sqlitePath).toStdString());
    configureSqlite();
}

void Database::configureSqlite() {
    // The first statement reads the file header and the schema: a damaged or foreign file fails here, before
    // anything is written to it. Not PRAGMA quick_check: it reads every page (1.4 s of CPU at each open of a
    // history of a million parts); a page damaged further in fails the statement that reads it, and a failed
    // statement changes nothing (docs/DECISIONS.md).
    QSqlQuery check(connection());
    if (!check.exec(QStringLiteral("SELECT COUNT(*) FROM sqlite_master")) && isBusy(check.lastError()))
        throw StorageError("the history file '" + m_config.sqlitePath.toStdString() +
                           "' is busy: " + sqlError(check.lastError(), m_config.sqlitePath).toStdString());
    if (!check.isActive() || !check.next()) {
        const QString why = sqlError(check.lastError(), m_config.sqlitePath);
        throw StorageError("the history file '" + m_config.sqlitePath.toStdString() +
                           "' is damaged or not a TrueTurn database (" + why.toStdString() +
                           "); it was left untouched");
    }
    check.finish();  // an active statement holds a read transaction; WAL cannot be switched on inside one
    QStringList pragmas;
    if (m_config.readOnly)
        pragmas << QStringLiteral("PRAGMA query_only=ON");
    else
        pragmas << QStringLiteral("PRAGMA journal_mode=WAL") << QStringLiteral("PRAGMA foreign_keys=ON")
                << (m_config.durable ? QStringLiteral("PRAGMA synchronous=FULL")
                                     : QStringLiteral("PRAGMA synchronous=NORMAL"));
    for (const QString& pragma : pragmas) {
        QSqlQuery q(connection());
        if (!execWaitingForLocks(q, pragma))
            throw StorageError("cannot configure the history file: " +
                               sqlError(q.lastError(), m_config.sqlitePath).toStdString());
    }
}

void Database::openPostgres() {
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QPSQL")))
        throw StorageError("the PostgreSQL driver of Qt is not installed (package libqt6sql6-psql)");
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), m_connectionName);
    db.setHostName(m_config.host);
    db.setPort(m_config.port);
    db.setDatabaseName(m_config.databaseName);
    db.setUserName(m_config.user);
    db.setPassword(m_config.password);
    db.setConnectOptions(QStringLiteral("connect_timeout=5"));
    if (!db.open())
        throw StorageError("cannot connect to " + m_config.describe().toStdString() + ": " +
                           sqlError(db.lastError()).toStdString());
    // A report's connection: every transaction read-only, so it runs on a hot standby and can change nothing.
    if (m_config.readOnly) exec(QStringLiteral("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY"));
}

bool Database::hasTable(const QString& table) {
    QSqlQuery q = isPostgres() ? exec(QStringLiteral("SELECT to_regclass(?) IS NOT NULL"), {table})
                               : exec(QStringLiteral("SELECT COUNT(*) FROM sqlite_master WHERE type = 'table' AND "
                                                     "name = ?"),
                                      {table});
    return q.next() && q.value(0).toBool();
}

void Database::ensureVersionTable() {
    // A role that may not create tables (a terminal's, the quality engineer's) or a hot standby opens a
    // database whose version table exists without trying to create it.
    if (hasTable(QStringLiteral("schema_versions"))) return;
    if (m_config.readOnly)
        throw StorageError(m_config.describe().toStdString() +
                           " holds no TrueTurn history (no schema_versions table); it was opened read-only");
    withSchemaLock([this] {
        exec(
            QStringLiteral("CREATE TABLE IF NOT EXISTS schema_versions ("
                           " module TEXT NOT NULL, version INTEGER NOT NULL, description TEXT NOT NULL,"
                           " applied_at TEXT NOT NULL, PRIMARY KEY (module, version))"));
    });
}

void Database::withSchemaLock(const std::function<void()>& work) {
    if (isPostgres()) {
        // A session-level advisory lock: clients connecting at the same moment create and migrate the
        // schema one after the other (CREATE TABLE IF NOT EXISTS alone races on the catalogue).
        exec(QStringLiteral("SELECT pg_advisory_lock(%1)").arg(kSchemaLockKey));
        try {
            work();
        } catch (...) {
            exec(QStringLiteral("SELECT pg_advisory_unlock(%1)").arg(kSchemaLockKey));
            throw;
        }
        exec(QStringLiteral("SELECT pg_advisory_unlock(%1)").arg(kSchemaLockKey));
        return;
    }
    // SQLite: one write transaction taken at once (BEGIN IMMEDIATE) around reading the version and
    // applying what is missing; DDL is transactional there.
    transaction(work);
}

QString Database::dialectSql(const QString& sql) const {
    QString out = sql;
    if (isPostgres()) {
        out.replace(QStringLiteral("{pk}"), QStringLiteral("BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"));
        out.replace(QStringLiteral("{real}"), QStringLiteral("DOUBLE PRECISION"));
        out.replace(QStringLiteral("{blob}"), QStringLiteral("BYTEA"));
    } else {
        out.replace(QStringLiteral("{pk}"), QStringLiteral("INTEGER PRIMARY KEY AUTOINCREMENT"));
        out.replace(QStringLiteral("{real}"), QStringLiteral("REAL"));
        out.replace(QStringLiteral("{blob}"), QStringLiteral("BLOB"));
    }
    out.replace(QStringLiteral("{bigint}"), QStringLiteral("BIGINT"));
    return out;
}

QSqlQuery Database::exec(const QString& sql, const QVariantList& bindings) {
    QSqlQuery query(connection());
    const QString statement = dialectSql(sql);
    // PostgreSQL cannot PREPARE DDL: statements without bindings run directly.
    bool ok = false;
    if (bindings.isEmpty()) {
        ok = query.exec(statement);
    } else if (query.prepare(statement)) {
        for (const QVariant& value : bindings)
            query.addBindValue(value);
        ok = query.exec();
    }
    if (!ok)
        throw StorageError(
            "database statement failed: " + sqlError(query.lastError(), m_config.sqlitePath).toStdString() + " [" +
            statement.left(80).toStdString() + "]");
    return query;
}

qint64 Database::lastInsertId(QSqlQuery& query) {
    if (isPostgres()) {
        QSqlQuery q = exec(QStringLiteral("SELECT lastval()"));
        if (q.next()) return q.value(0).toLongLong();
        throw StorageError("the database did not report the new row's id");
    }
    const QVariant id = query.lastInsertId();
    if (!id.isValid()) throw StorageError("the database did not report the new row's id");
    return id.toLongLong();
}

void Database::transaction(const std::function<void()>& work) {
    if (m_transactionDepth > 0) {
        work();
        return;
    }
    QSqlDatabase db = connection();
    if (isPostgres()) {
        if (!db.transaction())
            throw StorageError("cannot start a transaction: " +
                               sqlError(db.lastError(), m_config.sqlitePath).toStdString());
    } else {
        // SQLite: take the write lock at the start (waiting up to the busy timeout), so a transaction that
        // reads before it writes is never refused because another writer committed in between (WAL).
        QSqlQuery begin(db);
        if (!begin.exec(QStringLiteral("BEGIN IMMEDIATE")))
            throw StorageError("cannot start a transaction: " +
                               sqlError(begin.lastError(), m_config.sqlitePath).toStdString());
    }
    ++m_transactionDepth;
    try {
        work();
    } catch (...) {
        --m_transactionDepth;
        db.rollback();
        throw;
    }
    --m_transactionDepth;
    if (!db.commit()) {
        const QString why = sqlError(db.lastError(), m_config.sqlitePath);
        db.rollback();
        throw StorageError("cannot save to the database: " + why.toStdString());
    }
}

int Database::schemaVersion(const QString& module) {
    QSqlQuery q = exec(QStringLiteral("SELECT MAX(version) FROM schema_versions WHERE module = ?"), {module});
    return q.next() && !q.value(0).isNull() ? q.value(0).toInt() : 0;
}

void Database::migrate(const SchemaModule& module) {
    const int known = module.migrations.empty() ? 0 : module.migrations.back().version;
    const auto checkNotNewer = [&](int current) {
        if (current > known)
            throw StorageError("the database holds '" + module.name.toStdString() + "' schema version " +
                               std::to_string(current) + ", newer than this TrueTurn knows (" + std::to_string(known) +
                               "); update TrueTurn — the data was left untouched");
    };
    const int seen = schemaVersion(module.name);
    checkNotNewer(seen);
    if (seen == known) return;
    if (m_config.readOnly)
        throw StorageError(m_config.describe().toStdString() + " holds '" + module.name.toStdString() +
                           "' schema version " + std::to_string(seen) + ", older than this TrueTurn's (" +
                           std::to_string(known) +
                           "); it was opened read-only: open it once with write access (a terminal, or `trueturn "
                           "plant --db` as its owner) to bring it up to date");
    // Another client may be migrating at this moment: under the schema lock, read the version again.
    withSchemaLock([&] {
        const int current = schemaVersion(module.name);
        checkNotNewer(current);
        for (const Migration& m : module.migrations) {
            if (m.version <= current) continue;
            transaction([&] {
                qCInfo(lcStorage).noquote()
                    << "migrating" << module.name << "to version" << m.version << "-" << m.description;
                m.apply(*this);
                exec(QStringLiteral("INSERT INTO schema_versions (module, version, description, applied_at) "
                                    "VALUES (?, ?, ?, ?)"),
                     {module.name, m.version, m.description, utcNowText()});
            });
        }
    });
}

QString utcNowText() {
    return QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
}

}  // namespace tt::storage
