#pragma once

#include <gtest/gtest.h>

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QUuid>
#include <memory>
#include <string>

#include "core/storage/database.h"

namespace tt::storage::test {

/// Backends every storage test runs on: "sqlite" always, "postgres" against the server named by
/// the TRUETURN_PG_URL environment variable (scripts/start-test-postgres.sh; ./test.sh starts it).
inline std::vector<std::string> backends() {
    return {"sqlite", "postgres"};
}

/// A fresh, empty database for one test: a new SQLite file in a temporary folder, or a new
/// PostgreSQL database created on the test server and dropped afterwards.
class ScratchDatabase {
public:
    explicit ScratchDatabase(const std::string& backend) {
        if (backend == "sqlite") {
            m_config = DatabaseConfig::sqlite(m_dir.filePath(QStringLiteral("history.sqlite")));
            return;
        }
        m_config.kind = DatabaseConfig::Kind::Postgres;
        const QString url = qEnvironmentVariable("TRUETURN_PG_URL");
        if (url.isEmpty()) return;
        m_admin = DatabaseConfig::postgresUrl(url);
        m_config = m_admin;
        m_config.databaseName = QStringLiteral("tt_") + QUuid::createUuid().toString(QUuid::Id128).left(16);
        adminExec(QStringLiteral("CREATE DATABASE ") + m_config.databaseName);
    }
    ~ScratchDatabase() {
        if (m_config.kind == DatabaseConfig::Kind::Postgres && !m_config.databaseName.isEmpty())
            adminExec(QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(m_config.databaseName));
    }

    /// False when the PostgreSQL server is not configured (the test then skips or fails).
    bool available() const { return m_config.kind == DatabaseConfig::Kind::Sqlite || !m_config.databaseName.isEmpty(); }
    const DatabaseConfig& config() const { return m_config; }
    QString folder() const { return m_dir.path(); }

private:
    void adminExec(const QString& sql) {
        Database admin(m_admin);
        admin.exec(sql);
    }

    QTemporaryDir m_dir;
    DatabaseConfig m_admin;
    DatabaseConfig m_config;
};

/// Skips (PostgreSQL tests off) or fails (TRUETURN_POSTGRES_TESTS=ON but no server) when the
/// backend is not available. Use at the top of a parameterised storage test.
#define TT_REQUIRE_BACKEND(scratch)                                                                   \
    do {                                                                                              \
        if (!(scratch).available()) {                                                                 \
            if (TRUETURN_POSTGRES_REQUIRED) FAIL() << "TRUETURN_PG_URL is not set";                   \
            GTEST_SKIP() << "PostgreSQL tests need TRUETURN_PG_URL (scripts/start-test-postgres.sh)"; \
        }                                                                                             \
    } while (false)

}  // namespace tt::storage::test
