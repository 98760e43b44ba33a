#include "core/storage/user_store.h"

#include <QDateTime>
#include <QSqlQuery>
#include <stdexcept>

#include "core/auth/idle_logout.h"

namespace tt::storage {

namespace {

using core::auth::Permission;
using core::auth::Role;
using core::auth::SecretKind;

QString roleText(Role role) {
    return QString::fromStdString(core::auth::roleKey(role));
}

QString kindKey(SecretKind kind) {
    return kind == SecretKind::Pin ? QStringLiteral("pin") : QStringLiteral("password");
}

QString checkedName(const QString& name) {
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty()) throw std::invalid_argument("the user needs a name");
    if (trimmed.size() > kMaxUserNameChars)
        throw std::invalid_argument("a user name has at most " + std::to_string(kMaxUserNameChars) + " characters");
    return trimmed;
}

QString utcOf(std::int64_t unixS) {
    return QDateTime::fromSecsSinceEpoch(unixS, Qt::UTC).toString(Qt::ISODate);
}

const char* kPolicyKeys[] = {"max_failures", "lock_seconds", "idle_minutes"};

}  // namespace

SchemaModule userSchema() {
    SchemaModule module{QStringLiteral("users"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("users, roles, Argon2id hashes, lock-out; log-in policies"), [](Database& db) {
             db.exec(QStringLiteral(
                 "CREATE TABLE users (name TEXT PRIMARY KEY, role TEXT NOT NULL, secret_kind TEXT NOT NULL,"
                 " secret_hash TEXT NOT NULL, created_at TEXT NOT NULL, created_by TEXT NOT NULL,"
                 " failures INTEGER NOT NULL, locked_until {bigint} NOT NULL)"));
             db.exec(
                 QStringLiteral("CREATE TABLE login_policy (policy_key TEXT PRIMARY KEY, value {bigint} NOT NULL)"));
             const LoginPolicy defaults;
             const qint64 values[] = {defaults.lockout.maxFailures, defaults.lockout.lockSeconds, defaults.idleMinutes};
             for (int i = 0; i < 3; ++i)
                 db.exec(QStringLiteral("INSERT INTO login_policy (policy_key, value) VALUES (?, ?)"),
                         {QString::fromLatin1(kPolicyKeys[i]), values[i]});
         }});
    return module;
}

UserStore::UserStore(Database& database, AuditStore& audit) : m_db(database), m_audit(audit) {
    m_db.migrate(userSchema());
}

const core::auth::Identity* UserStore::requireManager() const {
    return m_access ? &m_access->require(Permission::ManageUsers) : nullptr;
}

QString UserStore::actorName(const QString& fallback) const {
    return m_access && m_access->identity() ? QString::fromStdString(m_access->identity()->name) : fallback;
}

void UserStore::audit(const QString& subject, const QString& field, const QString& before, const QString& after,
                      const QString& who, const QString& role) {
    const QString actorRole = m_access && m_access->identity() ? roleText(m_access->identity()->role) : role;
    m_audit.record({audit_category::kUser, subject, field, before, after}, who, actorRole);
}

bool UserStore::hasUsers() {
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT COUNT(*) FROM users"));
    return q.next() && q.value(0).toLongLong() > 0;
}

std::vector<UserRecord> UserStore::users() {
    std::vector<UserRecord> out;
    QSqlQuery q = m_db.exec(
        QStringLiteral("SELECT name, role, secret_kind, created_at, failures, locked_until FROM users ORDER BY name"));
    while (q.next())
        out.push_back({q.value(0).toString(),
                       core::auth::roleFromKey(q.value(1).toString().toStdString()),
                       q.value(2).toString() == QStringLiteral("pin") ? SecretKind::Pin : SecretKind::Password,
                       q.value(3).toString(),
                       {q.value(4).toInt(), q.value(5).toLongLong()}});
    return out;
}

std::optional<UserRecord> UserStore::find(const QString& name) {
    for (UserRecord& u : users())
        if (u.name == name) return std::move(u);
    return std::nullopt;
}

int UserStore::administrators() {
    QSqlQuery q =
        m_db.exec(QStringLiteral("SELECT COUNT(*) FROM users WHERE role = ?"), {roleText(Role::Administrator)});
    return q.next() ? q.value(0).toInt() : 0;
}

void UserStore::insert(const QString& name, Role role, const std::string& secret, SecretKind kind,
                       const QString& createdBy, const QString& creatorRole) {
    core::auth::checkSecret(secret, kind);
    if (find(name)) throw std::invalid_argument("a user named '" + name.toStdString() + "' exists already");
    const QString hash = QString::fromStdString(core::auth::hashSecret(secret));
    m_db.exec(QStringLiteral("INSERT INTO users (name, role, secret_kind, secret_hash, created_at, created_by,"
                             " failures, locked_until) VALUES (?, ?, ?, ?, ?, ?, 0, 0)"),
              {name, roleText(role), kindKey(kind), hash, utcNowText(), createdBy});
    audit(QStringLiteral("user ") + name, QStringLiteral("role"), QString(), roleText(role), createdBy, creatorRole);
    audit(QStringLiteral("user ") + name, QStringLiteral("secret"), QString(), kindKey(kind) + QStringLiteral(" set"),
          createdBy, creatorRole);
}

core::auth::Identity UserStore::createFirstAdministrator(const QString& name, const std::string& secret,
                                                         SecretKind kind) {
    const QString user = checkedName(name);
    m_db.transaction([&] {
        if (hasUsers()) throw std::logic_error("the administrator exists already; log in");
        insert(user, Role::Administrator, secret, kind, user, roleText(Role::Administrator));
    });
    return {user.toStdString(), Role::Administrator};
}

void UserStore::addUser(const QString& name, Role role, const std::string& secret, SecretKind kind) {
    requireManager();
    const QString user = checkedName(name);
    m_db.transaction([&] { insert(user, role, secret, kind, actorName(QStringLiteral("administrator")), QString()); });
}

void UserStore::setRole(const QString& name, Role role) {
    requireManager();
    m_db.transaction([&] {
        const std::optional<UserRecord> user = find(name);
        if (!user) throw std::invalid_argument("there is no user '" + name.toStdString() + "'");
        if (user->role == role) return;
        if (user->role == Role::Administrator && administrators() == 1)
            throw std::invalid_argument("'" + name.toStdString() + "' is the last administrator and stays one");
        m_db.exec(QStringLiteral("UPDATE users SET role = ? WHERE name = ?"), {roleText(role), name});
        audit(QStringLiteral("user ") + name, QStringLiteral("role"), roleText(user->role), roleText(role),
              actorName(QStringLiteral("administrator")));
    });
}

void UserStore::setSecret(const QString& name, const std::string& secret, SecretKind kind) {
    const bool self = m_access && m_access->identity() && QString::fromStdString(m_access->identity()->name) == name;
    if (!self) requireManager();
    core::auth::checkSecret(secret, kind);
    m_db.transaction([&] {
        const std::optional<UserRecord> user = find(name);
        if (!user) throw std::invalid_argument("there is no user '" + name.toStdString() + "'");
        m_db.exec(QStringLiteral("UPDATE users SET secret_kind = ?, secret_hash = ?, failures = 0, locked_until = 0"
                                 " WHERE name = ?"),
                  {kindKey(kind), QString::fromStdString(core::auth::hashSecret(secret)), name});
        audit(QStringLiteral("user ") + name, QStringLiteral("secret"), kindKey(user->secretKind),
              kindKey(kind) + QStringLiteral(" changed"), actorName(QStringLiteral("administrator")));
    });
}

void UserStore::unlock(const QString& name) {
    requireManager();
    m_db.transaction([&] {
        const std::optional<UserRecord> user = find(name);
        if (!user) throw std::invalid_argument("there is no user '" + name.toStdString() + "'");
        m_db.exec(QStringLiteral("UPDATE users SET failures = 0, locked_until = 0 WHERE name = ?"), {name});
        audit(QStringLiteral("user ") + name, QStringLiteral("lockout"),
              user->lockout.lockedUntilS > 0 ? QStringLiteral("locked until ") + utcOf(user->lockout.lockedUntilS)
                                             : QStringLiteral("%1 failed log-ins").arg(user->lockout.failures),
              QStringLiteral("unlocked"), actorName(QStringLiteral("administrator")));
    });
}

void UserStore::removeUser(const QString& name) {
    const core::auth::Identity* actor = requireManager();
    if (actor && QString::fromStdString(actor->name) == name)
        throw std::invalid_argument("you cannot remove yourself while logged in");
    m_db.transaction([&] {
        const std::optional<UserRecord> user = find(name);
        if (!user) throw std::invalid_argument("there is no user '" + name.toStdString() + "'");
        if (user->role == Role::Administrator && administrators() == 1)
            throw std::invalid_argument("'" + name.toStdString() + "' is the last administrator");
        m_db.exec(QStringLiteral("DELETE FROM users WHERE name = ?"), {name});
        audit(QStringLiteral("user ") + name, QStringLiteral("role"), roleText(user->role), QString(),
              actorName(QStringLiteral("administrator")));
    });
}

LoginOutcome UserStore::logIn(const QString& name, const std::string& secret, std::int64_t nowS) {
    const LoginPolicy rules = policy();
    LoginOutcome outcome;
    m_db.transaction([&] {
        QSqlQuery q = m_db.exec(
            QStringLiteral("SELECT role, secret_hash, failures, locked_until FROM users WHERE name = ?"), {name});
        if (!q.next()) {
            outcome.attemptsLeft = rules.lockout.maxFailures;
            return;
        }
        const Role role = core::auth::roleFromKey(q.value(0).toString().toStdString());
        const std::string hash = q.value(1).toString().toStdString();
        core::auth::LockoutState state{q.value(2).toInt(), q.value(3).toLongLong()};
        if (core::auth::isLocked(state, nowS)) {
            outcome.result = LoginOutcome::Result::Locked;
            outcome.lockedUntilS = state.lockedUntilS;
            return;
        }
        if (core::auth::verifySecret(hash, secret)) {
            state = core::auth::afterSuccess();
            outcome.result = LoginOutcome::Result::LoggedIn;
            outcome.identity = core::auth::Identity{name.toStdString(), role};
            m_audit.record({audit_category::kSession, QStringLiteral("user ") + name, QStringLiteral("log-in"),
                            QString(), QStringLiteral("logged in")},
                           name, roleText(role));
        } else {
            state = core::auth::afterFailure(state, rules.lockout, nowS);
            outcome.attemptsLeft = core::auth::attemptsLeft(state, rules.lockout, nowS);
            if (core::auth::isLocked(state, nowS)) {
                outcome.result = LoginOutcome::Result::Locked;
                outcome.lockedUntilS = state.lockedUntilS;
                m_audit.record(
                    {audit_category::kSession, QStringLiteral("user ") + name, QStringLiteral("lockout"), QString(),
                     QStringLiteral("locked until %1 after %2 failed log-ins")
                         .arg(utcOf(state.lockedUntilS))
                         .arg(rules.lockout.maxFailures)},
                    name, roleText(role));
            }
        }
        m_db.exec(QStringLiteral("UPDATE users SET failures = ?, locked_until = ? WHERE name = ?"),
                  {state.failures, static_cast<qint64>(state.lockedUntilS), name});
    });
    return outcome;
}

LoginPolicy UserStore::policy() {
    LoginPolicy p;
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT policy_key, value FROM login_policy"));
    while (q.next()) {
        const QString key = q.value(0).toString();
        const qint64 value = q.value(1).toLongLong();
        if (key == QLatin1String(kPolicyKeys[0])) p.lockout.maxFailures = static_cast<int>(value);
        if (key == QLatin1String(kPolicyKeys[1])) p.lockout.lockSeconds = value;
        if (key == QLatin1String(kPolicyKeys[2])) p.idleMinutes = static_cast<int>(value);
    }
    return p;
}

void UserStore::setPolicy(const LoginPolicy& next) {
    requireManager();
    core::auth::checkPolicy(next.lockout);
    core::auth::IdleLogout check(next.idleMinutes);  // throws out of limits
    const LoginPolicy before = policy();
    const qint64 olds[] = {before.lockout.maxFailures, before.lockout.lockSeconds, before.idleMinutes};
    const qint64 news[] = {next.lockout.maxFailures, next.lockout.lockSeconds, next.idleMinutes};
    m_db.transaction([&] {
        for (int i = 0; i < 3; ++i) {
            if (olds[i] == news[i]) continue;
            m_db.exec(QStringLiteral("UPDATE login_policy SET value = ? WHERE policy_key = ?"),
                      {news[i], QString::fromLatin1(kPolicyKeys[i])});
            const QString role = m_access && m_access->identity() ? roleText(m_access->identity()->role) : QString();
            m_audit.record({audit_category::kSetting, QStringLiteral("log-in policy"),
                            QString::fromLatin1(kPolicyKeys[i]), QString::number(olds[i]), QString::number(news[i])},
                           actorName(QStringLiteral("administrator")), role);
        }
    });
}

}  // namespace tt::storage
