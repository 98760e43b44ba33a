#pragma once

#include <array>
#include <string>

namespace tt::core::auth {

/// Who a user is at the terminal: runs the machine, tunes and calibrates it, reviews the quality,
/// or manages the users (the administrator may do everything).
enum class Role { Operator, Engineer, Quality, Administrator };

/// Every role, lowest to highest.
inline constexpr std::array<Role, 4> kAllRoles{Role::Operator, Role::Engineer, Role::Quality, Role::Administrator};

/// Stable key stored in the database ("operator", "engineer", "quality", "administrator").
std::string roleKey(Role role);
/// The role of a stored key; throws std::invalid_argument naming the key and the known keys.
Role roleFromKey(const std::string& key);

}  // namespace tt::core::auth
