#pragma once

#include <QString>
#include <memory>

#include "core/storage/database.h"

namespace tt::ui {

/// Opens the database named by the application context: a `postgresql://` URL or an SQLite file
/// path. Throws storage::StorageError (or std::invalid_argument for an empty name) with the reason.
std::unique_ptr<storage::Database> openContextDatabase(const QString& pathOrUrl);

}  // namespace tt::ui
