#include "core/auth/role.h"

#include <stdexcept>

namespace tt::core::auth {

std::string roleKey(Role role) {
    switch (role) {
        case Role::Operator:
            return "operator";
        case Role::Engineer:
            return "engineer";
        case Role::Quality:
            return "quality";
        case Role::Administrator:
            return "administrator";
    }
    return "operator";
}

Role roleFromKey(const std::string& key) {
    for (Role role : kAllRoles)
        if (roleKey(role) == key) return role;
    throw std::invalid_argument("unknown role '" + key + "' (known: operator, engineer, quality, administrator)");
}

}  // namespace tt::core::auth
