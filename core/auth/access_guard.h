#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "core/auth/permission.h"

namespace tt::core::auth {

/// The user logged in at the terminal: name and role.
struct Identity {
    std::string name;
    Role role = Role::Operator;
};

/// A change refused because the logged-in user's role lacks the permission; the message says which
/// role is needed ("Ivan (operator) may not change the tool table (tool stiffness): it needs the engineer
/// role"). Nothing was changed.
class PermissionDenied : public std::runtime_error {
public:
    PermissionDenied(Permission permission, const std::string& message)
        : std::runtime_error(message), m_permission(permission) {}
    /// What was refused.
    Permission permission() const { return m_permission; }

private:
    Permission m_permission;
};

/// What every store asks before it changes anything: who is logged in, and may they? The application
/// owns one guard per terminal and hands it to the stores; a store without a guard (the headless
/// command line, engine tests) is not access-controlled.
class AccessGuard {
public:
    /// Logs `identity` in (replacing whoever was); throws std::invalid_argument for an empty name.
    void logIn(Identity identity);
    /// Nobody is logged in afterwards: every require() throws.
    void logOut();
    /// Who is logged in, if anyone.
    const std::optional<Identity>& identity() const { return m_identity; }
    /// Whether the logged-in user may do `permission` (false when nobody is logged in).
    bool may(Permission permission) const;
    /// Returns the logged-in identity when it may do `permission`; throws PermissionDenied otherwise.
    const Identity& require(Permission permission) const;

private:
    std::optional<Identity> m_identity;
};

/// The sentence PermissionDenied carries for `permission` refused to `who` (nobody when empty).
std::string deniedMessage(Permission permission, const std::optional<Identity>& who);

}  // namespace tt::core::auth
