// The Run page offers the LinuxCNC lathe exactly while a LinuxCNC device is configured on the Devices page
// (runtime::MachineCatalog lists what the configured devices make possible), and choosing it puts the LinuxCNC into
// the run request (RunRequest::cnc), as `trueturn simulate --cnc` does. No LinuxCNC is needed: the device points at
// a port where nothing listens.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QSettings>
#include <QTemporaryDir>

#include "runtime/devices/device_hub.h"
#include "runtime/run/machine_catalog.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");
const QString kLinuxCncLathe = QStringLiteral("linuxcnc-lathe:127.0.0.1:1");

class LinuxCncLatheChoiceTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        ASSERT_GE(hub.loadPlugins(kBuildPlugins), 1) << hub.pluginErrors().join(QStringLiteral("; ")).toStdString();
        ASSERT_NE(hub.plugin(QStringLiteral("linuxcnc")), nullptr) << "the LinuxCNC plugin is built";
        context.devices = &hub;
    }
    // The page saves the machine chosen; leave no LinuxCNC lathe chosen for the tests after this one.
    void TearDown() override { QSettings().clear(); }

    QString addLinuxCnc() {
        return hub.addDevice(QStringLiteral("linuxcnc"), devices::DeviceKind::CorrectionOutput,
                             QStringLiteral("LinuxCNC at the lathe"),
                             {{QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                              {QStringLiteral("port"), 1},
                              {QStringLiteral("mode"), QStringLiteral("wear")}});
    }

    static QComboBox* machines(QWidget& page) { return page.findChild<QComboBox*>(QStringLiteral("machineCombo")); }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub hub;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite"))};
};

TEST_F(LinuxCncLatheChoiceTest, TheLinuxCncLatheIsOfferedWhileALinuxCncDeviceIsConfigured) {
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Run);
    auto* page = static_cast<RunPage*>(window.page(PageId::Run));
    ASSERT_NE(page, nullptr);
    EXPECT_EQ(machines(*page)->findData(kLinuxCncLathe), -1) << "no LinuxCNC device, no LinuxCNC lathe";
    EXPECT_FALSE(runtime::MachineCatalog(&hub).find(kLinuxCncLathe).has_value());

    const QString id = addLinuxCnc();
    const int index = machines(*page)->findData(kLinuxCncLathe);
    ASSERT_GE(index, 0) << "the LinuxCNC lathe of the configured device";
    EXPECT_TRUE(machines(*page)->itemText(index).contains(QStringLiteral("LinuxCNC")))
        << machines(*page)->itemText(index).toStdString();
    const auto offer = runtime::MachineCatalog(&hub).find(kLinuxCncLathe);
    ASSERT_TRUE(offer.has_value());
    EXPECT_FALSE(offer->can.adjustableSpeed) << "LinuxCNC cuts in wall time";
    EXPECT_FALSE(offer->can.usesDevices);

    machines(*page)->setCurrentIndex(index);
    const runtime::RunRequest request = page->shaft().request();
    EXPECT_EQ(request.machine, kLinuxCncLathe);
    EXPECT_EQ(request.cnc, QStringLiteral("linuxcnc://127.0.0.1:1"));
    EXPECT_EQ(request.cncMode, QStringLiteral("wear"));
    EXPECT_EQ(request.speed, 0.0);

    hub.removeDevice(id);
    EXPECT_EQ(machines(*page)->findData(kLinuxCncLathe), -1) << "the device is gone, and its lathe with it";
    EXPECT_FALSE(runtime::MachineCatalog(&hub).find(kLinuxCncLathe).has_value());
}

}  // namespace
}  // namespace tt::ui
