// Roles and audit offscreen: the first start creates the administrator, who adds an operator and an
// engineer; the log-in on the keypad with attempts left and the lock-out (clock injected); the operator
// is refused a tool change through the Tools page and the audit view; the engineer's change lands in
// the audit trail with old and new values, filtered and exported as CSV; the idle log-out (clock
// injected). Screenshots in English and Russian.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "core/storage/user_store.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/auth/audit_dialog.h"
#include "ui/auth/first_start_dialog.h"
#include "ui/auth/login_dialog.h"
#include "ui/auth/user_session.h"
#include "ui/auth/users_dialog.h"
#include "ui/language.h"
#include "ui/pages/settings_page.h"
#include "ui/pages/tools_page.h"
#include "ui/tools/tool_table_model.h"

namespace tt::ui {
namespace {

using core::auth::Role;

class AuthFlowTest : public ::testing::TestWithParam<QString> {
protected:
    void SetUp() override {
        ASSERT_TRUE(language.apply(GetParam()));
        context.databasePath = dir.filePath(QStringLiteral("history.sqlite"));
        context.session = &session;
        context.access = &session.guard();
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }
    QString shot(const QString& name) const { return QStringLiteral("auth_%1_%2").arg(name, GetParam()); }
    storage::UserStore& users() { return *context.data().users(); }

    /// Types `pin` on the dialog's keypad (keys 0..8 are 1..9, key 10 is 0).
    static void typeOnKeypad(LoginDialog& dialog, const QString& pin) {
        for (QChar c : pin) {
            const int digit = c.digitValue();
            auto* key = dialog.findChild<QPushButton*>(QStringLiteral("key_%1").arg(digit == 0 ? 10 : digit - 1));
            ASSERT_NE(key, nullptr);
            QTest::mouseClick(key, Qt::LeftButton);
        }
    }
    static void selectUser(UsersDialog& dialog, const QString& name) {
        for (int row = 0; row < dialog.table()->rowCount(); ++row)
            if (dialog.table()->item(row, 0)->text() == name) dialog.table()->selectRow(row);
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    UserSession session{&state};
    AppContext context{&prompt, &state, &language, QString()};
    std::int64_t nowS = 1'800'000'000;  // the log-in dialog's clock, Unix s
};

TEST_P(AuthFlowTest, FirstStartLogInRefusalAndAuditTrail) {
    // First start: no user; the dialog creates the administrator and logs them in.
    ASSERT_FALSE(users().hasUsers());
    {
        FirstStartDialog first(users(), session);
        first.nameEdit()->setText(QStringLiteral("Anna"));
        QTest::keyClicks(first.passwordEdit(), QStringLiteral("correct horse"));
        QTest::keyClicks(first.repeatEdit(), QStringLiteral("correct hose"));
        first.show();
        EXPECT_FALSE(first.create());
        EXPECT_FALSE(first.problemText().isEmpty());
        EXPECT_FALSE(users().hasUsers());
        QTest::keyClicks(first.repeatEdit(), QStringLiteral("correct horse"));
        EXPECT_TRUE(test::saveScreenshot(first, shot(QStringLiteral("first_start"))));
        EXPECT_LE(first.width(), 1280);
        EXPECT_LE(first.height(), 800);
        ASSERT_TRUE(first.create()) << first.problemText().toStdString();
    }
    ASSERT_TRUE(session.identity());
    EXPECT_EQ(session.identity()->role, Role::Administrator);
    EXPECT_EQ(state.operatorName(), QStringLiteral("Anna"));

    // The administrator adds an operator with a PIN and an engineer with a password.
    {
        UsersDialog admin(users());
        admin.nameEdit()->setText(QStringLiteral("Ivan"));
        admin.roleCombo()->setCurrentIndex(admin.roleCombo()->findData(static_cast<int>(Role::Operator)));
        admin.kindCombo()->setCurrentIndex(0);  // PIN
        admin.secretEdit()->setText(QStringLiteral("4711"));
        ASSERT_TRUE(admin.addUser()) << admin.statusText().toStdString();
        admin.nameEdit()->setText(QStringLiteral("Olga"));
        admin.secretEdit()->setText(QStringLiteral("2580"));
        ASSERT_TRUE(admin.addUser()) << admin.statusText().toStdString();
        selectUser(admin, QStringLiteral("Olga"));
        admin.roleCombo()->setCurrentIndex(admin.roleCombo()->findData(static_cast<int>(Role::Engineer)));
        ASSERT_TRUE(admin.setRole()) << admin.statusText().toStdString();
        admin.show();
        EXPECT_TRUE(test::saveScreenshot(admin, shot(QStringLiteral("users"))));
        EXPECT_LE(admin.width(), 1280);
        EXPECT_LE(admin.height(), 800);
        EXPECT_EQ(admin.table()->rowCount(), 3);
    }

    // The operator logs in on the keypad; a wrong PIN first says how many attempts are left.
    session.logOut();
    {
        LoginDialog login(users(), session, LoginDialog::Leave::Quit);
        login.setClock([this] { return nowS; });
        login.userCombo()->setCurrentIndex(login.userCombo()->findText(QStringLiteral("Ivan")));
        login.show();
        typeOnKeypad(login, QStringLiteral("1234"));
        EXPECT_FALSE(login.attempt());
        EXPECT_TRUE(login.messageText().contains(QStringLiteral("4"))) << login.messageText().toStdString();
        EXPECT_TRUE(test::saveScreenshot(login, shot(QStringLiteral("login"))));
        EXPECT_LE(login.width(), 1280);
        typeOnKeypad(login, QStringLiteral("4711"));
        ASSERT_TRUE(login.attempt()) << login.messageText().toStdString();
    }
    ASSERT_EQ(session.identity()->role, Role::Operator);

    // Through the Tools page the operator cannot change a tool: the store refuses, nothing is stored.
    {
        ToolsPage tools(context);
        tools.addTool();
        EXPECT_FALSE(tools.applyChanges());
        EXPECT_TRUE(tools.statusText().contains(QStringLiteral("needs the engineer role")))
            << tools.statusText().toStdString();
        EXPECT_TRUE(context.data().tools()->tools().empty());
    }
    {
        AuditDialog audit(context);
        EXPECT_EQ(audit.table()->rowCount(), 0);
        EXPECT_TRUE(audit.statusText().contains(QStringLiteral("needs the engineer role")))
            << audit.statusText().toStdString();
    }

    // The engineer may; the change is in the audit trail with who, old and new.
    session.logOut();
    {
        LoginDialog login(users(), session, LoginDialog::Leave::Never);
        login.userCombo()->setCurrentIndex(login.userCombo()->findText(QStringLiteral("Olga")));
        typeOnKeypad(login, QStringLiteral("2580"));
        ASSERT_TRUE(login.attempt()) << login.messageText().toStdString();
    }
    {
        ToolsPage tools(context);
        tools.addTool();
        ASSERT_TRUE(tools.applyChanges()) << tools.statusText().toStdString();
        tools.toolModel()->setData(tools.toolModel()->index(0, ToolTableModel::Overhang), QStringLiteral("250"),
                                   Qt::EditRole);
        ASSERT_TRUE(tools.applyChanges()) << tools.statusText().toStdString();
    }
    SettingsPage settings(context);
    EXPECT_EQ(settings.findChild<QLabel*>(QStringLiteral("sessionUser"))->text(),
              QStringLiteral("Olga (%1)").arg(UserSession::roleName(Role::Engineer)));
    EXPECT_TRUE(settings.findChild<QPushButton*>(QStringLiteral("auditButton"))->isEnabled());
    EXPECT_FALSE(settings.findChild<QPushButton*>(QStringLiteral("usersButton"))->isEnabled());
    settings.resize(1100, 640);
    settings.show();
    EXPECT_TRUE(test::saveScreenshot(settings, shot(QStringLiteral("settings"))));

    AuditDialog audit(context);
    audit.show();
    EXPECT_GE(audit.table()->rowCount(), 8);  // users added and their role, log-ins, the tool's fields
    audit.categoryCombo()->setCurrentIndex(audit.categoryCombo()->findData(storage::audit_category::kTool));
    QTest::keyClicks(audit.textFilter(), QStringLiteral("overhang"));
    ASSERT_EQ(audit.table()->rowCount(), 2);
    EXPECT_EQ(audit.table()->item(0, 1)->text(), QStringLiteral("Olga"));
    EXPECT_EQ(audit.table()->item(0, 6)->text(), QStringLiteral("200"));  // the new tool's default overhang
    EXPECT_EQ(audit.table()->item(0, 7)->text(), QStringLiteral("250"));
    audit.textFilter()->clear();
    audit.categoryCombo()->setCurrentIndex(audit.categoryCombo()->findData(storage::audit_category::kUser));
    EXPECT_GE(audit.table()->rowCount(), 5);
    audit.categoryCombo()->setCurrentIndex(0);
    EXPECT_TRUE(test::saveScreenshot(audit, shot(QStringLiteral("audit"))));
    EXPECT_LE(audit.width(), 1280);
    EXPECT_LE(audit.height(), 800);

    const QString csvPath = dir.filePath(QStringLiteral("audit.csv"));
    prompt.fileNames.push_back(csvPath);
    ASSERT_TRUE(audit.exportCsv()) << audit.statusText().toStdString();
    QFile csv(csvPath);
    ASSERT_TRUE(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), audit.table()->rowCount() + 1);
    EXPECT_EQ(lines[0], QStringLiteral("when_utc,who,role,category,subject,field,old_value,new_value"));
    EXPECT_TRUE(lines.filter(QStringLiteral(",Anna,administrator,user,user Olga,role,operator,engineer")).size() == 1)
        << lines.join(QLatin1Char('\n')).toStdString();

    // A setting changed on the Settings page is audited too: the language, old and new.
    auto* languages = settings.findChild<QComboBox*>(QStringLiteral("languageCombo"));
    const QString other = GetParam() == QLatin1String("en") ? QStringLiteral("ru") : QStringLiteral("en");
    const int index = languages->findData(other);
    languages->setCurrentIndex(index);
    emit languages->activated(index);
    EXPECT_EQ(language.current(), other);
    storage::AuditFilter settingsOnly;
    settingsOnly.category = storage::audit_category::kSetting;
    const std::vector<storage::AuditRecord> changes = context.data().audit()->query(settingsOnly);
    ASSERT_EQ(changes.size(), 1u);
    EXPECT_EQ(changes[0].change.field.toStdString(), "language");
    EXPECT_EQ(changes[0].change.before, GetParam());
    EXPECT_EQ(changes[0].change.after, other);
    EXPECT_EQ(changes[0].changedBy.toStdString(), "Olga");
    EXPECT_EQ(changes[0].role.toStdString(), "engineer");
}

TEST_P(AuthFlowTest, LockOutAfterFiveFailuresAndReleaseAfterFiveMinutes) {
    users().createFirstAdministrator(QStringLiteral("Anna"), "correct horse", core::auth::SecretKind::Password);
    LoginDialog login(users(), session, LoginDialog::Leave::Quit);
    login.setClock([this] { return nowS; });
    login.show();
    // The default rules: 5 failed log-ins lock for 300 s (storage::LoginPolicy).
    for (int i = 0; i < 5; ++i) {
        QTest::keyClicks(login.secretEdit(), QStringLiteral("wrong horse"));
        EXPECT_FALSE(login.attempt());
    }
    EXPECT_FALSE(login.messageText().isEmpty());
    QTest::keyClicks(login.secretEdit(), QStringLiteral("correct horse"));
    EXPECT_FALSE(login.attempt());  // locked even with the right password
    EXPECT_TRUE(test::saveScreenshot(login, shot(QStringLiteral("locked"))));
    nowS += 299;
    QTest::keyClicks(login.secretEdit(), QStringLiteral("correct horse"));
    EXPECT_FALSE(login.attempt());
    nowS += 1;
    QTest::keyClicks(login.secretEdit(), QStringLiteral("correct horse"));
    EXPECT_TRUE(login.attempt()) << login.messageText().toStdString();
}

TEST_P(AuthFlowTest, IdleLogOutAfterTheSetTime) {
    std::int64_t nowMs = 0;
    session.setClock([&nowMs] { return nowMs; });
    bool idleLogOut = false;
    QObject::connect(&session, &UserSession::loggedOut, [&](bool idle) { idleLogOut = idle; });
    session.logIn({"Ivan", Role::Operator}, 2);
    nowMs = 119'999;
    session.checkIdle();
    EXPECT_TRUE(session.identity());
    session.touch();  // activity at 119.999 s: two more minutes from now
    nowMs = 239'998;
    session.checkIdle();
    EXPECT_TRUE(session.identity());
    nowMs = 239'999;
    session.checkIdle();
    EXPECT_FALSE(session.identity());
    EXPECT_TRUE(idleLogOut);
    EXPECT_TRUE(state.operatorName().isEmpty());
    EXPECT_FALSE(session.guard().may(core::auth::Permission::RunMachine));
}

INSTANTIATE_TEST_SUITE_P(Languages, AuthFlowTest, ::testing::Values(QStringLiteral("en"), QStringLiteral("ru")),
                         [](const auto& info) { return info.param.toStdString(); });

}  // namespace
}  // namespace tt::ui
