#include "core/storage/data_stores.h"

#include <stdexcept>

#include "core/storage/schemas.h"
#include "core/storage/storage_log.h"

namespace tt::storage {

DataStores::DataStores(QString pathOrUrl) : m_location(std::move(pathOrUrl)) {}

DataStores::~DataStores() = default;

DatabaseConfig DataStores::config() const {
    if (m_location.trimmed().isEmpty()) throw std::invalid_argument("no database is configured");
    return m_location.startsWith(QStringLiteral("postgresql://")) ||
                   m_location.startsWith(QStringLiteral("postgres://"))
               ? DatabaseConfig::postgresUrl(m_location)
               : DatabaseConfig::sqlite(m_location);
}

bool DataStores::open() {
    if (m_database) return true;
    try {
        auto database = std::make_unique<Database>(config());
        migrateAll(*database);
        m_history = std::make_unique<SqlHistoryStore>(*database);
        m_tools = std::make_unique<ToolStore>(*database);
        m_calibration = std::make_unique<CalibrationStore>(*database);
        m_audit = std::make_unique<AuditStore>(*database);
        m_users = std::make_unique<UserStore>(*database, *m_audit);
        m_database = std::move(database);
        setAccess(m_access);
        m_problem.clear();
        return true;
    } catch (const std::exception& e) {
        m_users.reset();
        m_audit.reset();
        m_calibration.reset();
        m_tools.reset();
        m_history.reset();
        m_problem = QString::fromStdString(e.what());
        qCWarning(lcStorage).noquote() << "the database" << m_location << "cannot be used:" << m_problem;
        return false;
    }
}

Database* DataStores::database() {
    return open() ? m_database.get() : nullptr;
}

SqlHistoryStore* DataStores::history() {
    return open() ? m_history.get() : nullptr;
}

ToolStore* DataStores::tools() {
    return open() ? m_tools.get() : nullptr;
}

CalibrationStore* DataStores::calibration() {
    return open() ? m_calibration.get() : nullptr;
}

}  // namespace tt::storage

namespace tt::storage {

AuditStore* DataStores::audit() {
    return open() ? m_audit.get() : nullptr;
}

UserStore* DataStores::users() {
    return open() ? m_users.get() : nullptr;
}

void DataStores::setAccess(const core::auth::AccessGuard* access) {
    m_access = access;
    if (m_tools) m_tools->setAccess(access);
    if (m_calibration) m_calibration->setAccess(access);
    if (m_audit) m_audit->setAccess(access);
    if (m_users) m_users->setAccess(access);
}

}  // namespace tt::storage
