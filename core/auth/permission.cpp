#include "core/auth/permission.h"

namespace tt::core::auth {

bool mayDo(Role role, Permission permission) {
    if (role == Role::Administrator) return true;  // the administrator may do everything
    switch (permission) {
        case Permission::RunMachine:
            return role == Role::Operator || role == Role::Engineer;
        case Permission::EditTools:
        case Permission::EditCalibration:
        case Permission::EditControllerTuning:
        case Permission::EditSettings:
            return role == Role::Engineer;
        case Permission::ManageUsers:
            return false;
        case Permission::ViewAudit:
            return role == Role::Engineer || role == Role::Quality;
    }
    return false;
}

std::vector<Role> rolesAllowed(Permission permission) {
    std::vector<Role> out;
    for (Role role : kAllRoles)
        if (mayDo(role, permission)) out.push_back(role);
    return out;
}

std::string describe(Permission permission) {
    switch (permission) {
        case Permission::RunMachine:
            return "run the machine";
        case Permission::EditTools:
            return "change the tool table (tool stiffness)";
        case Permission::EditCalibration:
            return "change a calibration";
        case Permission::EditControllerTuning:
            return "change the controller tuning";
        case Permission::EditSettings:
            return "change the terminal settings";
        case Permission::ManageUsers:
            return "manage users";
        case Permission::ViewAudit:
            return "view the audit trail";
    }
    return "do this";
}

}  // namespace tt::core::auth
