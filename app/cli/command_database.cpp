#include "app/cli/command_database.h"

#include "app/cli/command.h"

namespace tt::cli {

bool isPostgresOption(const QString& value) {
    return value.startsWith(QLatin1String("postgresql://")) || value.startsWith(QLatin1String("postgres://"));
}

storage::DatabaseConfig databaseConfigFromOption(const QString& value) {
    if (!isPostgresOption(value)) return storage::DatabaseConfig::sqlite(value);
    try {
        return storage::DatabaseConfig::postgresUrl(value);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
}

}  // namespace tt::cli
