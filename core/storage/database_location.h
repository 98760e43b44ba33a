#pragma once

#include <QString>

namespace tt::storage {

/// The default history database: `history.sqlite` in the user's application data folder
/// (QStandardPaths::AppDataLocation, e.g. ~/.local/share/TrueTurn). Creates the folder.
/// Throws std::runtime_error with the folder name when it cannot be created.
QString defaultDatabasePath();

}  // namespace tt::storage
