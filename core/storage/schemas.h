#pragma once

#include <vector>

#include "core/storage/database.h"

namespace tt::storage {

/// Every schema module of the product's database: history, tools, calibration, audit, users.
std::vector<SchemaModule> allSchemas();

/// Brings every module of `database` to the version this program knows; throws StorageError
/// (e.g. a schema newer than this program) with nothing changed in the failing module.
void migrateAll(Database& database);

}  // namespace tt::storage
