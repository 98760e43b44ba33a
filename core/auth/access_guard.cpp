#include "core/auth/access_guard.h"

namespace tt::core::auth {

void AccessGuard::logIn(Identity identity) {
    if (identity.name.empty()) throw std::invalid_argument("a user name is needed to log in");
    m_identity = std::move(identity);
}

void AccessGuard::logOut() {
    m_identity.reset();
}

bool AccessGuard::may(Permission permission) const {
    return m_identity && mayDo(m_identity->role, permission);
}

const Identity& AccessGuard::require(Permission permission) const {
    if (!may(permission)) throw PermissionDenied(permission, deniedMessage(permission, m_identity));
    return *m_identity;
}

std::string deniedMessage(Permission permission, const std::optional<Identity>& who) {
    // The lowest role that may (the administrator may do everything, so it is named only when alone).
    const std::string needed = "the " + roleKey(rolesAllowed(permission).front()) + " role";
    if (!who) return "nobody is logged in: to " + describe(permission) + " log in with " + needed;
    return who->name + " (" + roleKey(who->role) + ") may not " + describe(permission) + ": it needs " + needed;
}

}  // namespace tt::core::auth
