// The Devices page under roles: an operator's Apply of a device is refused with the role needed and
// nothing is added; the engineer's is applied and audited value by value (old empty, new set).
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>

#include "runtime/devices/device_hub.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/auth/user_session.h"
#include "ui/pages/devices_page.h"

namespace tt::ui {
namespace {

TEST(DevicesUnderRoles, AnOperatorCannotAddADeviceAndTheEngineersIsAudited) {
    QSettings().clear();
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    UserSession session(&state);
    runtime::DeviceHub manager;  // the built-in simulator only
    AppContext context{&prompt, &state, nullptr, dir.filePath(QStringLiteral("history.sqlite")), &manager};
    context.session = &session;
    context.access = &session.guard();
    DevicesPage page(context);
    page.show();
    auto* types = page.findChild<QComboBox*>(QStringLiteral("newDeviceType"));
    ASSERT_NE(types, nullptr);
    ASSERT_GT(types->count(), 0);
    types->setCurrentIndex(0);

    session.logIn({"Ivan", core::auth::Role::Operator}, 10);
    page.findChild<QPushButton*>(QStringLiteral("addDevice"))->click();
    page.findChild<QPushButton*>(QStringLiteral("applyDevice"))->click();
    const QString refusal = page.findChild<QLabel*>(QStringLiteral("FormProblems"))->text();
    EXPECT_TRUE(
        refusal.contains(QStringLiteral("Ivan (operator) may not change the terminal settings: it needs the "
                                        "engineer role")))
        << refusal.toStdString();
    EXPECT_TRUE(manager.deviceIds().isEmpty());

    session.logIn({"Olga", core::auth::Role::Engineer}, 10);
    page.findChild<QPushButton*>(QStringLiteral("applyDevice"))->click();
    ASSERT_EQ(manager.deviceIds().size(), 1);
    storage::AuditFilter filter;
    filter.category = storage::audit_category::kSetting;
    const std::vector<storage::AuditRecord> records = context.data().audit()->query(filter);
    ASSERT_FALSE(records.empty());
    bool named = false;
    for (const storage::AuditRecord& r : records) {
        EXPECT_EQ(r.changedBy.toStdString(), "Olga");
        EXPECT_EQ(r.change.subject, QStringLiteral("device ") + manager.deviceIds().front());
        EXPECT_TRUE(r.change.before.isEmpty());  // a new device: every value is new
        if (r.change.field == QLatin1String("name")) named = !r.change.after.isEmpty();
    }
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace tt::ui
