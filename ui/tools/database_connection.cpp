#include "ui/tools/database_connection.h"

#include <stdexcept>

namespace tt::ui {

std::unique_ptr<storage::Database> openContextDatabase(const QString& pathOrUrl) {
    if (pathOrUrl.trimmed().isEmpty()) throw std::invalid_argument("no database is configured");
    const storage::DatabaseConfig config =
        pathOrUrl.startsWith(QStringLiteral("postgresql://")) || pathOrUrl.startsWith(QStringLiteral("postgres://"))
            ? storage::DatabaseConfig::postgresUrl(pathOrUrl)
            : storage::DatabaseConfig::sqlite(pathOrUrl);
    return std::make_unique<storage::Database>(config);
}

}  // namespace tt::ui
