#pragma once

#include <QString>

#include "core/storage/database.h"

namespace tt::storage {

/// The group role of the lathes' terminals: may insert the history of its own machines only (row-level
/// security: the machines a login may write are the rows of `plant_terminals` with its name) and never
/// update or delete it; may update its own row of `plant_terminal_status`.
inline constexpr const char* kTerminalRole = "trueturn_terminal";
/// The group role of the quality engineers: reads every table of the history, changes nothing.
inline constexpr const char* kQualityRole = "trueturn_quality";

/// Creates (when missing) the group roles kTerminalRole and kQualityRole, the table `plant_terminals (login,
/// machine)`, and grants and row-level-security policies on the history tables. Part of the history
/// schema's migration 5 on PostgreSQL (the migrating role must own the tables and may create roles). The
/// owner of the tables keeps every right (PostgreSQL does not apply row-level security to a table's owner).
void createPlantRoles(Database& db);

}  // namespace tt::storage
