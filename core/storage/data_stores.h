#pragma once

#include <QString>
#include <memory>

#include "core/storage/audit_store.h"
#include "core/storage/calibration_store.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "core/storage/tool_store.h"
#include "core/storage/user_store.h"

namespace tt::storage {

/// The data access object of one database for the thread that owns it (the GUI's): opens the
/// connection once, migrates every schema module (schemas.h) and hands out the stores (run history,
/// tool table, calibration records, audit trail, users). The application makes one and gives it to the pages
/// (ui::AppContext::data()), so no page opens connections itself. A worker thread opens its own
/// connection from config() (a QtSql connection belongs to the thread that made it).
class DataStores {
public:
    /// `pathOrUrl`: an SQLite file or a `postgresql://` URL; nothing is opened yet.
    explicit DataStores(QString pathOrUrl);
    ~DataStores();
    DataStores(const DataStores&) = delete;
    DataStores& operator=(const DataStores&) = delete;

    /// The file or URL as given.
    const QString& location() const { return m_location; }
    /// How to connect; throws std::invalid_argument when no database is configured.
    DatabaseConfig config() const;

    /// Opens and migrates the database the first time; afterwards says whether that worked. A failure
    /// is kept (problem()) and tried again on the next call.
    bool open();
    /// Why the database cannot be used, in the storage's words; empty when it is open.
    const QString& problem() const { return m_problem; }

    /// The connection and the stores, or null when the database cannot be opened (see problem()).
    Database* database();
    SqlHistoryStore* history();
    ToolStore* tools();
    CalibrationStore* calibration();
    AuditStore* audit();
    UserStore* users();

    /// The terminal's access guard, given to every store (now and when opened later): with it, a change
    /// the logged-in user's role may not make is refused by the store (core::auth::PermissionDenied).
    /// Null = not access-controlled. The guard must outlive this object.
    void setAccess(const core::auth::AccessGuard* access);

private:
    QString m_location;
    QString m_problem;
    std::unique_ptr<Database> m_database;
    std::unique_ptr<SqlHistoryStore> m_history;
    std::unique_ptr<ToolStore> m_tools;
    std::unique_ptr<CalibrationStore> m_calibration;
    std::unique_ptr<AuditStore> m_audit;
    std::unique_ptr<UserStore> m_users;
    const core::auth::AccessGuard* m_access = nullptr;
};

}  // namespace tt::storage
