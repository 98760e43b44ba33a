// Roles and log-in: Argon2id hashing through libsodium, the permission matrix, the access guard's
// refusal, lock-out after repeated failures and its release, the idle log-out (time injected).
#include <gtest/gtest.h>

#include "core/auth/access_guard.h"
#include "core/auth/idle_logout.h"
#include "core/auth/lockout.h"
#include "core/auth/secret_hash.h"

namespace tt::core::auth {
namespace {

TEST(SecretHash, RoundTripAcceptsTheSecretAndRefusesAnother) {
    const std::string hash = hashSecret("lathe-2026!");
    // PHC string of Argon2id (RFC 9106) as libsodium writes it.
    EXPECT_EQ(hash.rfind("$argon2id$v=19$", 0), 0u) << hash;
    EXPECT_TRUE(verifySecret(hash, "lathe-2026!"));
    EXPECT_FALSE(verifySecret(hash, "lathe-2026?"));
    EXPECT_FALSE(verifySecret(hash, ""));
    // A random salt: the same secret hashes differently, and each hash verifies it.
    const std::string again = hashSecret("lathe-2026!");
    EXPECT_NE(hash, again);
    EXPECT_TRUE(verifySecret(again, "lathe-2026!"));
}

TEST(SecretHash, PinsAndMalformedHashes) {
    const std::string pin = hashSecret("4711");
    EXPECT_TRUE(verifySecret(pin, "4711"));
    EXPECT_FALSE(verifySecret(pin, "4712"));
    EXPECT_FALSE(verifySecret("not a hash", "4711"));
    EXPECT_FALSE(verifySecret("", "4711"));
    EXPECT_FALSE(verifySecret(pin, std::string(kMaxSecretChars + 1, '4')));
}

TEST(SecretHash, ChecksTheLimitsOfPasswordsAndPins) {
    EXPECT_NO_THROW(checkSecret("12345678", SecretKind::Password));
    EXPECT_THROW(checkSecret("1234567", SecretKind::Password), std::invalid_argument);
    EXPECT_THROW(checkSecret(std::string(kMaxSecretChars + 1, 'a'), SecretKind::Password), std::invalid_argument);
    EXPECT_NO_THROW(checkSecret("0042", SecretKind::Pin));
    EXPECT_THROW(checkSecret("123", SecretKind::Pin), std::invalid_argument);
    try {
        checkSecret("12a4", SecretKind::Pin);
        FAIL() << "a PIN with a letter was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "a PIN has digits only");
    }
}

TEST(Permissions, TheMatrix) {
    // docs/DECISIONS.md "Roles": the operator runs; the engineer tunes, calibrates and edits tools;
    // quality reads the audit; the administrator may do everything.
    EXPECT_TRUE(mayDo(Role::Operator, Permission::RunMachine));
    for (Permission p : {Permission::EditTools, Permission::EditCalibration, Permission::EditControllerTuning,
                         Permission::EditSettings, Permission::ManageUsers, Permission::ViewAudit})
        EXPECT_FALSE(mayDo(Role::Operator, p)) << describe(p);
    for (Permission p : {Permission::RunMachine, Permission::EditTools, Permission::EditCalibration,
                         Permission::EditControllerTuning, Permission::EditSettings, Permission::ViewAudit})
        EXPECT_TRUE(mayDo(Role::Engineer, p)) << describe(p);
    EXPECT_FALSE(mayDo(Role::Engineer, Permission::ManageUsers));
    EXPECT_TRUE(mayDo(Role::Quality, Permission::ViewAudit));
    for (Permission p :
         {Permission::RunMachine, Permission::EditTools, Permission::EditControllerTuning, Permission::ManageUsers})
        EXPECT_FALSE(mayDo(Role::Quality, p)) << describe(p);
    for (Permission p : kAllPermissions)
        EXPECT_TRUE(mayDo(Role::Administrator, p)) << describe(p);
    EXPECT_EQ(rolesAllowed(Permission::ManageUsers), std::vector<Role>{Role::Administrator});
}

TEST(Roles, KeysRoundTripAndUnknownKeysAreRefused) {
    for (Role r : kAllRoles)
        EXPECT_EQ(roleFromKey(roleKey(r)), r);
    EXPECT_THROW(roleFromKey("root"), std::invalid_argument);
}

TEST(AccessGuard, RefusesWithTheRoleNeeded) {
    AccessGuard guard;
    try {
        guard.require(Permission::EditTools);
        FAIL() << "nobody logged in, yet allowed";
    } catch (const PermissionDenied& e) {
        EXPECT_STREQ(e.what(),
                     "nobody is logged in: to change the tool table (tool stiffness) log in with the "
                     "engineer role");
    }
    guard.logIn({"Ivan", Role::Operator});
    EXPECT_TRUE(guard.may(Permission::RunMachine));
    try {
        guard.require(Permission::EditControllerTuning);
        FAIL() << "an operator may change the controller tuning";
    } catch (const PermissionDenied& e) {
        EXPECT_EQ(e.permission(), Permission::EditControllerTuning);
        EXPECT_STREQ(e.what(), "Ivan (operator) may not change the controller tuning: it needs the engineer role");
    }
    guard.logIn({"Olga", Role::Engineer});
    EXPECT_EQ(guard.require(Permission::EditTools).name, "Olga");
    guard.logOut();
    EXPECT_FALSE(guard.may(Permission::RunMachine));
    EXPECT_THROW(guard.logIn({"", Role::Engineer}), std::invalid_argument);
}

TEST(Lockout, LocksAfterTheStatedFailuresAndReleasesAfterTheDuration) {
    const LockoutPolicy policy{3, 300};
    const std::int64_t t0 = 1'700'000'000;
    LockoutState s;
    s = afterFailure(s, policy, t0);
    s = afterFailure(s, policy, t0 + 1);
    EXPECT_FALSE(isLocked(s, t0 + 2));
    EXPECT_EQ(attemptsLeft(s, policy, t0 + 2), 1);
    s = afterFailure(s, policy, t0 + 2);  // the third failure locks for 300 s from now
    EXPECT_TRUE(isLocked(s, t0 + 2));
    EXPECT_EQ(s.lockedUntilS, t0 + 302);
    EXPECT_EQ(attemptsLeft(s, policy, t0 + 100), 0);
    // Trying while locked neither counts nor extends the lock.
    EXPECT_EQ(afterFailure(s, policy, t0 + 200).lockedUntilS, t0 + 302);
    EXPECT_TRUE(isLocked(s, t0 + 301));
    EXPECT_FALSE(isLocked(s, t0 + 302));
    EXPECT_EQ(attemptsLeft(s, policy, t0 + 302), 3);
    // A success forgets the failures.
    s = afterFailure(afterFailure(afterSuccess(), policy, t0 + 400), policy, t0 + 401);
    EXPECT_EQ(afterSuccess().failures, 0);
    EXPECT_EQ(s.failures, 2);
}

TEST(Lockout, PolicyLimits) {
    EXPECT_NO_THROW(checkPolicy({5, 300}));
    EXPECT_THROW(checkPolicy({0, 300}), std::invalid_argument);
    EXPECT_THROW(checkPolicy({kMaxFailuresLimit + 1, 300}), std::invalid_argument);
    EXPECT_THROW(checkPolicy({5, kMinLockSeconds - 1}), std::invalid_argument);
    EXPECT_THROW(checkPolicy({5, kMaxLockSeconds + 1}), std::invalid_argument);
}

TEST(IdleLogout, ExpiresAfterTheSetIdleTimeAndActivityPostponesIt) {
    IdleLogout idle(10);  // 10 min = 600 000 ms
    idle.touch(1'000);
    EXPECT_FALSE(idle.expired(600'999));
    EXPECT_EQ(idle.remainingMs(600'000), 1'000);
    EXPECT_TRUE(idle.expired(601'000));
    idle.touch(500'000);  // activity before the end: counted from there (an older time is ignored below)
    idle.touch(400'000);
    EXPECT_FALSE(idle.expired(1'099'999));
    EXPECT_TRUE(idle.expired(1'100'000));
    EXPECT_THROW(IdleLogout(0), std::invalid_argument);
    EXPECT_THROW(IdleLogout(kMaxIdleMinutes + 1), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core::auth
