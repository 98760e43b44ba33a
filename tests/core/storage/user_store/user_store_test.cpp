// Users over SQL, on SQLite and PostgreSQL: the first administrator, log-in with lock-out and its
// release (Unix time injected), user changes audited with old and new values, and the access guard
// enforced by the stores the pages use (an operator cannot change tool stiffness or a calibration).
#include "core/storage/user_store.h"

#include <gtest/gtest.h>

#include <QSqlQuery>

#include "audit_filter_of.h"
#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/data_stores.h"
#include "core/storage/tool_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

using core::auth::AccessGuard;
using core::auth::PermissionDenied;
using core::auth::Role;
using core::auth::SecretKind;

constexpr std::int64_t kT0 = 1'800'000'000;  // an arbitrary Unix time, s

using test::filterOf;

class UserStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(UserStoreTest, FirstStartCreatesTheAdministratorOnceAndLogsIn) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    UserStore users(db, audit);
    EXPECT_FALSE(users.hasUsers());
    const core::auth::Identity admin =
        users.createFirstAdministrator(QStringLiteral(" Anna "), "correct horse", SecretKind::Password);
    EXPECT_EQ(admin.name, "Anna");
    EXPECT_EQ(admin.role, Role::Administrator);
    EXPECT_TRUE(users.hasUsers());
    EXPECT_THROW(users.createFirstAdministrator(QStringLiteral("Mallory"), "12345678", SecretKind::Password),
                 std::logic_error);
    // The hash, not the password, is stored.
    QSqlQuery q = db.exec(QStringLiteral("SELECT secret_hash FROM users WHERE name = 'Anna'"));
    ASSERT_TRUE(q.next());
    EXPECT_TRUE(q.value(0).toString().startsWith(QStringLiteral("$argon2id$")));
    EXPECT_FALSE(q.value(0).toString().contains(QStringLiteral("horse")));
    const LoginOutcome ok = users.logIn(QStringLiteral("Anna"), "correct horse", kT0);
    ASSERT_EQ(ok.result, LoginOutcome::Result::LoggedIn);
    EXPECT_EQ(ok.identity->role, Role::Administrator);
    EXPECT_EQ(users.logIn(QStringLiteral("Anna"), "wrong horse", kT0).result, LoginOutcome::Result::Refused);
    EXPECT_EQ(users.logIn(QStringLiteral("Nobody"), "correct horse", kT0).result, LoginOutcome::Result::Refused);
}

TEST_P(UserStoreTest, LocksOutAfterTheStatedFailuresAndReleasesAfterTheDuration) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    UserStore users(db, audit);
    users.createFirstAdministrator(QStringLiteral("Anna"), "correct horse", SecretKind::Password);
    AccessGuard guard;
    guard.logIn({"Anna", Role::Administrator});
    users.setAccess(&guard);
    users.addUser(QStringLiteral("Ivan"), Role::Operator, "4711", SecretKind::Pin);
    users.setPolicy({{3, 120}, 5});  // 3 failures lock for 120 s; idle log-out after 5 min
    guard.logOut();
    EXPECT_EQ(users.logIn(QStringLiteral("Ivan"), "0000", kT0).attemptsLeft, 2);
    EXPECT_EQ(users.logIn(QStringLiteral("Ivan"), "0001", kT0 + 1).attemptsLeft, 1);
    const LoginOutcome third = users.logIn(QStringLiteral("Ivan"), "0002", kT0 + 2);
    ASSERT_EQ(third.result, LoginOutcome::Result::Locked);
    EXPECT_EQ(third.lockedUntilS, kT0 + 122);
    // While locked even the right PIN is refused; the lock survives a new store (it is in the database).
    UserStore again(db, audit);
    EXPECT_EQ(again.logIn(QStringLiteral("Ivan"), "4711", kT0 + 121).result, LoginOutcome::Result::Locked);
    EXPECT_EQ(again.logIn(QStringLiteral("Ivan"), "4711", kT0 + 122).result, LoginOutcome::Result::LoggedIn);
    // The lock-out is in the audit trail.
    const std::vector<AuditRecord> locks = audit.query(filterOf(audit_category::kSession, QStringLiteral("lockout")));
    ASSERT_EQ(locks.size(), 1u);
    EXPECT_EQ(locks[0].change.subject, QStringLiteral("user Ivan"));
    EXPECT_TRUE(locks[0].change.after.startsWith(QStringLiteral("locked until")))
        << locks[0].change.after.toStdString();
}

TEST_P(UserStoreTest, UserChangesAreAuditedWithOldAndNewAndNeedTheAdministrator) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    UserStore users(db, audit);
    users.createFirstAdministrator(QStringLiteral("Anna"), "correct horse", SecretKind::Password);
    AccessGuard guard;
    users.setAccess(&guard);
    guard.logIn({"Anna", Role::Administrator});
    users.addUser(QStringLiteral("Ivan"), Role::Operator, "4711", SecretKind::Pin);
    users.setRole(QStringLiteral("Ivan"), Role::Engineer);
    const std::vector<AuditRecord> roleChanges = audit.query(filterOf(audit_category::kUser, QStringLiteral("Ivan")));
    ASSERT_GE(roleChanges.size(), 3u);  // newest first: role change, secret set, role set
    EXPECT_EQ(roleChanges[0].change.field, QStringLiteral("role"));
    EXPECT_EQ(roleChanges[0].change.before, QStringLiteral("operator"));
    EXPECT_EQ(roleChanges[0].change.after, QStringLiteral("engineer"));
    EXPECT_EQ(roleChanges[0].changedBy, QStringLiteral("Anna"));
    EXPECT_EQ(roleChanges[0].role, QStringLiteral("administrator"));
    EXPECT_FALSE(roleChanges[0].changedAt.isEmpty());
    // No audit record holds the PIN.
    for (const AuditRecord& r : audit.query())
        EXPECT_FALSE(r.change.after.contains(QStringLiteral("4711")) ||
                     r.change.before.contains(QStringLiteral("4711")));
    // The last administrator stays one; an engineer cannot manage users; nothing changes then.
    EXPECT_THROW(users.setRole(QStringLiteral("Anna"), Role::Operator), std::invalid_argument);
    guard.logIn({"Ivan", Role::Engineer});
    EXPECT_THROW(users.addUser(QStringLiteral("Eve"), Role::Administrator, "12345678", SecretKind::Password),
                 PermissionDenied);
    EXPECT_THROW(users.setRole(QStringLiteral("Ivan"), Role::Administrator), PermissionDenied);
    EXPECT_EQ(users.users().size(), 2u);
    EXPECT_EQ(users.users()[1].role, Role::Engineer);
    // A user may change their own PIN.
    EXPECT_NO_THROW(users.setSecret(QStringLiteral("Ivan"), "8642", SecretKind::Pin));
    EXPECT_THROW(users.setSecret(QStringLiteral("Anna"), "8642", SecretKind::Pin), PermissionDenied);
}

core::ToolRecord bar(const std::string& id, double overhangMm, double stiffnessNPerMm) {
    core::ToolRecord t = core::defaultTool(id);
    t.section = core::HolderSection::round(40.0);
    t.overhangMm = overhangMm;
    t.measured = core::MeasuredStiffness{stiffnessNPerMm, "2026-11-20", "lab"};
    return t;
}

TEST_P(UserStoreTest, AnOperatorCannotChangeToolStiffnessOrCalibrationThroughTheStoresThePagesUse) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    // The GUI's data access object with the terminal's guard, as app/gui.cpp wires it.
    DataStores stores(scratch.config().kind == DatabaseConfig::Kind::Sqlite
                          ? scratch.config().sqlitePath
                          : QStringLiteral("postgresql://%1@%2:%3/%4")
                                .arg(scratch.config().user, scratch.config().host)
                                .arg(scratch.config().port)
                                .arg(scratch.config().databaseName));
    AccessGuard guard;
    stores.setAccess(&guard);
    ASSERT_TRUE(stores.open()) << stores.problem().toStdString();
    guard.logIn({"Olga", Role::Engineer});
    stores.tools()->apply({{std::nullopt, bar("T12", 400.0, 2300.0)}}, QStringLiteral("Olga"));

    guard.logIn({"Ivan", Role::Operator});
    try {
        stores.tools()->apply({{std::string("T12"), bar("T12", 400.0, 9999.0)}}, QStringLiteral("Olga"));
        FAIL() << "an operator changed the tool stiffness";
    } catch (const PermissionDenied& e) {
        EXPECT_STREQ(e.what(),
                     "Ivan (operator) may not change the tool table (tool stiffness): it needs the "
                     "engineer role");
    }
    EXPECT_THROW(stores.tools()->saveMaterial({"Steel", 1.0e5}, QStringLiteral("Ivan")), PermissionDenied);
    KpCalibrationRecord kp;
    kp.createdBy = QStringLiteral("Ivan");
    kp.drive = QStringLiteral("X");
    kp.kpNPerA = 150.0;
    kp.pointsCsv = QStringLiteral("load_n,current_difference_a\n100,0.667\n");
    kp.appliedTo = QStringLiteral("");
    EXPECT_THROW(stores.calibration()->saveKp(kp), PermissionDenied);
    // Nothing changed.
    ASSERT_EQ(stores.tools()->tools().size(), 1u);
    EXPECT_DOUBLE_EQ(stores.tools()->tools()[0].measured->stiffnessNPerMm, 2300.0);
    EXPECT_TRUE(stores.calibration()->kpCalibrations().empty());
    EXPECT_THROW(stores.audit()->query(), PermissionDenied);  // an operator does not read the audit either

    // An engineer may; the record names who is logged in, whatever name the page passes.
    guard.logIn({"Olga", Role::Engineer});
    const std::vector<ToolAuditEntry> written =
        stores.tools()->apply({{std::string("T12"), bar("T12", 400.0, 2500.0)}}, QStringLiteral("someone else"));
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0].changedBy, QStringLiteral("Olga"));
    EXPECT_EQ(stores.calibration()->saveKp(kp).createdBy, QStringLiteral("Olga"));
}

INSTANTIATE_TEST_SUITE_P(Backends, UserStoreTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
