#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/auth/access_guard.h"
#include "core/auth/lockout.h"
#include "core/auth/secret_hash.h"
#include "core/storage/audit_store.h"
#include "core/storage/database.h"

namespace tt::storage {

/// The schema module "users": the users with their role and Argon2id hash (users) and the log-in
/// policies (login_policy: failed log-ins before the lock-out, its duration, the idle log-out time).
SchemaModule userSchema();

/// A user as the administrator sees it (never the hash).
struct UserRecord {
    QString name;
    core::auth::Role role = core::auth::Role::Operator;
    core::auth::SecretKind secretKind = core::auth::SecretKind::Password;
    QString createdAt;
    core::auth::LockoutState lockout;
};

/// The log-in policies of the terminal (stored in the database, changed by the administrator).
struct LoginPolicy {
    core::auth::LockoutPolicy lockout;
    int idleMinutes = 10;  ///< automatic log-out after this idle time (core::auth::kMinIdleMinutes ..)
};

/// How a log-in went.
struct LoginOutcome {
    enum class Result { LoggedIn, Refused, Locked };
    Result result = Result::Refused;
    std::optional<core::auth::Identity> identity;  ///< when logged in
    int attemptsLeft = 0;                          ///< before the lock-out (Refused)
    std::int64_t lockedUntilS = 0;                 ///< Unix seconds (Locked)
};

/// A user name's limits: 1 .. kMaxUserNameChars characters after trimming.
inline constexpr int kMaxUserNameChars = 64;

/// The users of the terminal over SQL. Every change is audited (category "user", the hash never);
/// with an access guard every change but the first administrator and log-ins needs ManageUsers.
class UserStore {
public:
    /// Applies the "users" migrations to `database`; `audit` receives the records (both must outlive
    /// the store).
    UserStore(Database& database, AuditStore& audit);
    /// The guard that must allow ManageUsers for a change (null: not access-controlled).
    void setAccess(const core::auth::AccessGuard* access) { m_access = access; }

    /// Whether any user exists (none: the first start asks for the administrator).
    bool hasUsers();
    /// Every user, ordered by name.
    std::vector<UserRecord> users();

    /// Creates the first user, an administrator; throws std::logic_error when a user exists already,
    /// std::invalid_argument for a bad name or secret (core::auth::checkSecret).
    core::auth::Identity createFirstAdministrator(const QString& name, const std::string& secret,
                                                  core::auth::SecretKind kind);
    /// Adds a user. Throws PermissionDenied, std::invalid_argument (bad name, a name in use, bad secret).
    void addUser(const QString& name, core::auth::Role role, const std::string& secret, core::auth::SecretKind kind);
    /// Changes a user's role; the last administrator stays one.
    void setRole(const QString& name, core::auth::Role role);
    /// Sets a new password or PIN (the administrator for anyone, a user for themself).
    void setSecret(const QString& name, const std::string& secret, core::auth::SecretKind kind);
    /// Releases a lock-out.
    void unlock(const QString& name);
    /// Removes a user; neither the last administrator nor the user logged in.
    void removeUser(const QString& name);

    /// Checks `secret` at `nowS` (Unix seconds, the caller's clock): counts a failure (locking out at the
    /// policy's count, audited), or forgets the failures and returns the identity. An unknown name is
    /// refused like a wrong secret.
    LoginOutcome logIn(const QString& name, const std::string& secret, std::int64_t nowS);

    /// The stored log-in policies.
    LoginPolicy policy();
    /// Stores new policies (ManageUsers; audited per value). Throws std::invalid_argument out of limits.
    void setPolicy(const LoginPolicy& policy);

private:
    const core::auth::Identity* requireManager() const;
    QString actorName(const QString& fallback) const;
    std::optional<UserRecord> find(const QString& name);
    /// Audits a user change by `who` (the logged-in user's name and role when guarded, else `role`).
    void audit(const QString& subject, const QString& field, const QString& before, const QString& after,
               const QString& who, const QString& role = {});
    int administrators();
    void insert(const QString& name, core::auth::Role role, const std::string& secret, core::auth::SecretKind kind,
                const QString& createdBy, const QString& creatorRole);

    Database& m_db;
    AuditStore& m_audit;
    const core::auth::AccessGuard* m_access = nullptr;
};

}  // namespace tt::storage
