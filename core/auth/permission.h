#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/auth/role.h"

namespace tt::core::auth {

/// A kind of change (or view) the application allows only to some roles.
enum class Permission {
    RunMachine,            ///< start, pause and stop the closed loop; hand entry
    EditTools,             ///< the tool stiffness table and the materials
    EditCalibration,       ///< probe linearisation tables, uploads, k_p calibrations
    EditControllerTuning,  ///< the controller's weights and settings (the Controller page's Apply)
    EditSettings,          ///< terminal settings that change results (not the display language)
    ManageUsers,           ///< add, change, unlock and remove users; the log-in policies
    ViewAudit,             ///< read and export the audit trail
};

/// Every permission, in declaration order.
inline constexpr std::array<Permission, 7> kAllPermissions{
    Permission::RunMachine,   Permission::EditTools,   Permission::EditCalibration, Permission::EditControllerTuning,
    Permission::EditSettings, Permission::ManageUsers, Permission::ViewAudit};

/// The permission matrix (docs/DECISIONS.md "Roles"): whether `role` may do `permission`.
bool mayDo(Role role, Permission permission);
/// The roles that may do `permission`, lowest first.
std::vector<Role> rolesAllowed(Permission permission);
/// What the permission allows, in English for messages and the CLI ("change tool stiffness").
std::string describe(Permission permission);

}  // namespace tt::core::auth
