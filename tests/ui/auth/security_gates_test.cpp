// The security gates with a logged-in session, offscreen: the Controller page's Apply refuses an operator
// (the reason shown, the tuning unchanged, nothing in the audit trail) and writes one audit row per changed
// value, with old and new, for an engineer; in kiosk mode an operator's quit asks for an engineer's log-in,
// a wrong password (or Cancel) keeps the terminal running and the engineer's right password lets it quit.
// The audit rows written are part of an intact hash chain.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <functional>

#include "core/storage/audit_store.h"
#include "core/storage/database.h"
#include "core/storage/user_store.h"
#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/auth/audit_dialog.h"
#include "ui/auth/login_dialog.h"
#include "ui/auth/user_session.h"
#include "ui/controller/tuning_worker.h"
#include "ui/controller/weight_row.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/controller_page.h"

namespace tt::ui {
namespace {

using core::auth::Role;
using core::auth::SecretKind;

class SecurityGatesTest : public ::testing::Test {
protected:
    void SetUp() override {
        // The terminal's users, written as the administrator's Users dialog writes them.
        storage::Database db(storage::DatabaseConfig::sqlite(databasePath()));
        storage::AuditStore audit(db);
        storage::UserStore users(db, audit);
        users.createFirstAdministrator(QStringLiteral("Anna"), "correct horse", SecretKind::Password);
        users.addUser(QStringLiteral("Ivan"), Role::Operator, "4711", SecretKind::Pin);
        users.addUser(QStringLiteral("Olga"), Role::Engineer, "engineer's secret", SecretKind::Password);
        context.session = &session;
        context.access = &session.guard();
    }

    QString databasePath() const { return dir.filePath(QStringLiteral("history.sqlite")); }

    /// The Controller page shown in a 1280 x 800 window, with its first preview in.
    ControllerPage* showController(MainWindow& window) {
        window.resize(1280, 800);
        window.show();
        window.showPage(PageId::Controller);
        auto* page = qobject_cast<ControllerPage*>(window.page(PageId::Controller));
        if (page && !waitForNewest(*page)) return nullptr;
        return page;
    }
    static bool waitForNewest(ControllerPage& page) {
        return QTest::qWaitFor(
            [&] {
                const TuningResult* shown = page.shownResult();
                return shown && shown->generation == page.worker().latestGeneration();
            },
            tt::test::kPatientWaitMs);
    }

    /// The controller's audit rows, read as the quality engineer's report would (a store of its own).
    std::vector<storage::AuditRecord> controllerRecords() {
        storage::Database db(storage::DatabaseConfig::sqlite(databasePath()));
        storage::AuditStore audit(db);
        storage::AuditFilter filter;
        filter.category = storage::audit_category::kController;
        return audit.query(filter);
    }
    bool chainIntact() {
        storage::Database db(storage::DatabaseConfig::sqlite(databasePath()));
        return storage::AuditStore(db).verifyChain().intact();
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    UserSession session{&state};
    AppContext context{&prompt, &state, &language, databasePath(), &devices};
};

TEST_F(SecurityGatesTest, AnOperatorIsRefusedApplyWithTheReasonAndNothingIsRecorded) {
    session.logIn({"Ivan", Role::Operator}, 10);
    MainWindow window(context);
    ControllerPage* page = showController(window);
    ASSERT_NE(page, nullptr);
    const double appliedR2 = page->appliedSetup().weights.R2(0, 0);
    page->r2(0).field()->setValue(1.0);
    ASSERT_TRUE(waitForNewest(*page));
    prompt.answers.push_back(Prompt::Answer::Yes);  // would confirm, if the page asked
    window.findChild<QPushButton*>(QStringLiteral("applyTuning"))->click();
    ASSERT_FALSE(prompt.log.isEmpty());
    EXPECT_EQ(prompt.log.back(), QStringLiteral("warn: Apply tuning")) << "refused before the question";
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("engineer"))) << prompt.lastText.toStdString();
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("Ivan"))) << prompt.lastText.toStdString();
    EXPECT_EQ(prompt.answers.size(), 1u) << "the confirmation was never asked";
    EXPECT_DOUBLE_EQ(page->appliedSetup().weights.R2(0, 0), appliedR2);
    EXPECT_TRUE(page->lastRecord().isEmpty());
    EXPECT_TRUE(controllerRecords().empty());
}

TEST_F(SecurityGatesTest, AnEngineersApplyWritesOneAuditRowPerChangedValueWithOldAndNew) {
    session.logIn({"Olga", Role::Engineer}, 10);
    MainWindow window(context);
    ControllerPage* page = showController(window);
    ASSERT_NE(page, nullptr);
    const double r2Before = page->appliedSetup().weights.R2(0, 0);
    const double r1Before = page->appliedSetup().weights.R1(1, 1);
    page->r2(0).field()->setValue(1.0);
    page->r1(1).field()->setValue(0.5);
    ASSERT_TRUE(waitForNewest(*page));
    prompt.answers.push_back(Prompt::Answer::Yes);
    window.findChild<QPushButton*>(QStringLiteral("applyTuning"))->click();
    EXPECT_EQ(prompt.log.back(), QStringLiteral("ask: Apply tuning"));
    EXPECT_DOUBLE_EQ(page->appliedSetup().weights.R2(0, 0), 1.0);

    std::vector<storage::AuditRecord> rows = controllerRecords();
    ASSERT_EQ(rows.size(), 2u) << "one row per changed value";
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.change.field < b.change.field; });
    EXPECT_EQ(rows[0].change.field, QStringLiteral("point 1 R2"));
    EXPECT_EQ(rows[0].change.before, QString::number(r2Before, 'g', 6));
    EXPECT_EQ(rows[0].change.after, QStringLiteral("1"));
    EXPECT_EQ(rows[1].change.field, QStringLiteral("point 2 R1"));
    EXPECT_EQ(rows[1].change.before, QString::number(r1Before, 'g', 6));
    EXPECT_EQ(rows[1].change.after, QStringLiteral("0.5"));
    for (const storage::AuditRecord& r : rows) {
        EXPECT_EQ(r.changedBy, QStringLiteral("Olga"));
        EXPECT_EQ(r.role, QStringLiteral("engineer"));
        EXPECT_EQ(r.change.subject, QStringLiteral("controller"));
    }
    EXPECT_TRUE(chainIntact());

    // The Audit dialog shows the chain's state: intact, then the row someone edited with a database tool.
    {
        AuditDialog dialog(context);
        EXPECT_TRUE(dialog.chainIntact()) << dialog.chainText().toStdString();
        EXPECT_TRUE(dialog.chainText().startsWith(QStringLiteral("Hash chain intact")))
            << dialog.chainText().toStdString();
    }
    const qint64 edited = rows[1].id;
    {
        storage::Database db(storage::DatabaseConfig::sqlite(databasePath()));
        db.exec(QStringLiteral("UPDATE audit SET new_value = '5' WHERE id = ?"), {edited});
    }
    AuditDialog dialog(context);
    dialog.show();
    EXPECT_FALSE(dialog.chainIntact());
    EXPECT_TRUE(dialog.chainText().contains(QStringLiteral("row %1 edited").arg(edited)))
        << dialog.chainText().toStdString();
    EXPECT_TRUE(test::saveScreenshot(dialog, QStringLiteral("audit_chain_broken_en")));
    language.apply(QStringLiteral("ru"));
    AuditDialog russian(context);
    russian.show();
    EXPECT_TRUE(russian.chainText().contains(QStringLiteral("строка %1 изменена").arg(edited)))
        << russian.chainText().toStdString();
    EXPECT_TRUE(test::saveScreenshot(russian, QStringLiteral("audit_chain_broken_ru")));
    language.apply(QStringLiteral("en"));
}

/// Runs `handle` on the log-in dialog once it is shown modally (LoginDialog::exec), from the event loop; the
/// poll belongs to `owner` (the window), so it cannot outlive the test.
void whenLogInShows(QObject* owner, const std::function<void(LoginDialog&)>& handle, bool& seen) {
    auto* poll = new QTimer(owner);
    poll->setInterval(20);
    QObject::connect(poll, &QTimer::timeout, poll, [poll, handle, &seen] {
        auto* dialog = qobject_cast<LoginDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        poll->stop();
        poll->deleteLater();
        seen = true;
        handle(*dialog);
    });
    poll->start();
}

TEST_F(SecurityGatesTest, KioskQuitByAnOperatorAsksForAnEngineerAndAWrongPasswordDoesNotQuit) {
    session.logIn({"Ivan", Role::Operator}, 10);
    auto window = std::make_unique<MainWindow>(context);
    window->resize(1280, 800);
    window->show();
    window->setKiosk(true);

    // A wrong password: refused with the attempts left, then Cancel (not "Quit": leaving this log-in goes
    // back to the terminal): the terminal keeps running.
    bool seen = false;
    QString message;
    QString leaveText;
    whenLogInShows(
        window.get(),
        [&](LoginDialog& d) {
            d.userCombo()->setCurrentIndex(d.userCombo()->findText(QStringLiteral("Olga")));
            d.secretEdit()->setText(QStringLiteral("not the secret"));
            EXPECT_FALSE(d.attempt());
            message = d.messageText();
            auto* leave = d.findChild<QPushButton*>(QStringLiteral("leaveButton"));
            ASSERT_NE(leave, nullptr);
            leaveText = leave->text();
            EXPECT_TRUE(test::saveScreenshot(d, QStringLiteral("kiosk_engineer_log_in")));
            leave->click();
        },
        seen);
    EXPECT_FALSE(window->close());
    EXPECT_TRUE(seen) << "the log-in was asked for";
    EXPECT_EQ(leaveText, QStringLiteral("Cancel"));
    EXPECT_TRUE(window->isVisible());
    EXPECT_TRUE(message.contains(QStringLiteral("Wrong name or password"))) << message.toStdString();
    ASSERT_TRUE(session.identity());
    EXPECT_EQ(session.identity()->name, "Ivan") << "the operator stays logged in";
    EXPECT_TRUE(prompt.log.isEmpty()) << "no confirmation instead of the log-in";

    // The operator's own PIN is not an engineer's: still no quitting.
    seen = false;
    whenLogInShows(
        window.get(),
        [&](LoginDialog& d) {
            d.userCombo()->setCurrentIndex(d.userCombo()->findText(QStringLiteral("Ivan")));
            d.secretEdit()->setText(QStringLiteral("4711"));
            EXPECT_TRUE(d.attempt());
        },
        seen);
    EXPECT_FALSE(window->close());
    EXPECT_TRUE(seen);
    EXPECT_TRUE(window->isVisible());

    // The engineer's password: the terminal quits.
    seen = false;
    whenLogInShows(
        window.get(),
        [&](LoginDialog& d) {
            d.userCombo()->setCurrentIndex(d.userCombo()->findText(QStringLiteral("Olga")));
            d.secretEdit()->setText(QStringLiteral("engineer's secret"));
            EXPECT_TRUE(d.attempt());
        },
        seen);
    EXPECT_TRUE(window->close());
    EXPECT_TRUE(seen);
    EXPECT_FALSE(window->isVisible());
    EXPECT_EQ(session.identity()->name, "Olga");
}

}  // namespace
}  // namespace tt::ui
