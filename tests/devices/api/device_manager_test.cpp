// The host side: settings schemas, the plugin folder, the manager (plugins loaded from the build
// tree's plugin folder, instances, persistence, status summary).
#include "devices/api/simulated_instrument.h"
#include "devices/api/device_manager.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "devices/api/plugin_folder.h"
#include "devices/api/settings_schema.h"

namespace tt::devices {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");

TEST(SettingsSchema, ValidatesTypesRangesChoicesAndVisibility) {
    SettingsSchema schema{
        SettingField::integer(QStringLiteral("n"), QStringLiteral("Count"), 5, 1, 10, QStringLiteral("pcs")),
        SettingField::number(QStringLiteral("x"), QStringLiteral("Diameter"), 27.0, 1.0, 100.0, QStringLiteral("mm")),
        SettingField::choice(QStringLiteral("mode"), QStringLiteral("Mode"),
                             {{QStringLiteral("a"), QStringLiteral("A")}, {QStringLiteral("b"), QStringLiteral("B")}},
                             QStringLiteral("a")),
        SettingField::text(QStringLiteral("t"), QStringLiteral("Only for b"), {})
            .visibleWhen(QStringLiteral("mode"), {QStringLiteral("b")}),
    };
    schema[3].type = SettingField::Type::Integer;  // a hidden field is not checked
    EXPECT_TRUE(validateSettings(schema, {}).isEmpty());
    const auto issues = validateSettings(schema, {{QStringLiteral("n"), QStringLiteral("11")},
                                                  {QStringLiteral("x"), QStringLiteral("abc")},
                                                  {QStringLiteral("mode"), QStringLiteral("c")}});
    ASSERT_EQ(issues.size(), 3);
    EXPECT_EQ(issues[0].message, QStringLiteral("Count: 11 is outside 1 to 10 pcs"));
    EXPECT_EQ(issues[1].message, QStringLiteral("Diameter: 'abc' is not a number"));
    EXPECT_EQ(issues[2].message, QStringLiteral("Mode: 'c' is not one of A, B"));
    EXPECT_EQ(validateSettings(schema, {{QStringLiteral("mode"), QStringLiteral("b")}}).size(), 1);
    EXPECT_EQ(withDefaults(schema, {}).value(QStringLiteral("x")).toDouble(), 27.0);
}

TEST(PluginFolder, IsRelativeToTheExecutable) {
    const QString folder = defaultPluginFolder();
    EXPECT_EQ(folder,
              QDir::cleanPath(QCoreApplication::applicationDirPath() + QStringLiteral("/../lib/trueturn/plugins")));
}

TEST(DeviceManager, LoadsThePluginModulesAndListsTheSimulatorFirst) {
    DeviceManager manager;
    EXPECT_EQ(manager.loadPlugins(kBuildPlugins), 5) << manager.pluginErrors().join(QStringLiteral("; ")).toStdString();
    EXPECT_EQ(manager.loadPlugins(kBuildPlugins), 0);  // loading twice is harmless
    QStringList ids;
    for (DevicePlugin* p : manager.plugins())
        ids << p->pluginId();
    EXPECT_EQ(ids,
              (QStringList{QStringLiteral("simulator"), QStringLiteral("cnc-gcode"), QStringLiteral("gauge-serial"),
                           QStringLiteral("linuxcnc"), QStringLiteral("modbus"), QStringLiteral("probe-mandrel")}));
    EXPECT_FALSE(manager.plugin(QStringLiteral("gauge-serial"))->settingsSchema(DeviceKind::Gauge).isEmpty());
    DeviceManager none;
    EXPECT_EQ(none.loadPlugins(QStringLiteral("/nonexistent/plugins")), 0);
    EXPECT_EQ(none.plugins().size(), 1);  // the simulator is always there
    EXPECT_FALSE(none.pluginErrors().isEmpty());
}

TEST(DeviceManager, TwoProbesFromTheLoadedPluginAtOnce) {
    DeviceManager manager;
    manager.loadPlugins(kBuildPlugins);
    QTemporaryDir dir;
    // Creation needs no port (it may be unplugged); adding checks it exists.
    EXPECT_THROW(manager.addDevice(QStringLiteral("probe-mandrel"), DeviceKind::Probe, QStringLiteral("Bar 1"),
                                   {{QStringLiteral("port"), dir.filePath(QStringLiteral("ttyX"))}}),
                 std::invalid_argument);
    const QString a = manager.addDevice(QStringLiteral("simulator"), DeviceKind::Probe, QStringLiteral("Bar 1"), {});
    const QString b = manager.addDevice(QStringLiteral("simulator"), DeviceKind::Probe, QStringLiteral("Bar 2"),
                                        {{QStringLiteral("deflection1Mm"), -0.03}});
    EXPECT_NE(a, b);
    EXPECT_EQ(manager.devicesOfKind(DeviceKind::Probe), (QStringList{a, b}));
    manager.openAll();
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.summary().tone == DeviceSummary::Tone::Ok; }, 2000));
    EXPECT_EQ(manager.summary().text, QStringLiteral("2 ready"));
    QTest::qWait(50);
    auto sa = manager.device(a)->deflectionProbe()->takeSample();
    auto sb = manager.device(b)->deflectionProbe()->takeSample();
    ASSERT_TRUE(sa && sb);
    EXPECT_NEAR(sa->deflectionMm[0], 0.020, 1e-6);
    EXPECT_NEAR(sb->deflectionMm[0], -0.030, 1e-6);
}

TEST(DeviceManager, SummaryNamesTheFirstDeviceInError) {
    DeviceManager manager;
    EXPECT_EQ(manager.summary().tone, DeviceSummary::Tone::None);
    const QString g =
        manager.addDevice(QStringLiteral("simulator"), DeviceKind::Gauge, QStringLiteral("Micrometer"), {});
    EXPECT_EQ(manager.summary().tone, DeviceSummary::Tone::Warning);  // disconnected
    int changes = 0;
    QObject::connect(&manager, &DeviceManager::deviceChanged, [&](const QString& id) { changes += id == g; });
    manager.device(g)->open();
    EXPECT_EQ(manager.summary().tone, DeviceSummary::Tone::Ok);
    tt::devices::simulatedInstrument(*manager.device(g))->faultSwitches().disconnected = true;
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.summary().tone == DeviceSummary::Tone::Fault; }, 2000));
    EXPECT_TRUE(
        manager.summary().text.startsWith(QStringLiteral("Micrometer: the simulated gauge micrometer is unplugged")))
        << manager.summary().text.toStdString();
    EXPECT_GT(changes, 0);
}

TEST(DeviceManager, PersistsAndRestoresEverythingEvenWithAPluginMissing) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("devices.ini"));
    {
        DeviceManager manager;
        manager.loadPlugins(kBuildPlugins);
        manager.addDevice(QStringLiteral("simulator"), DeviceKind::Gauge, QStringLiteral("Micrometer"),
                          {{QStringLiteral("nominalDiameterMm"), 26.5}});
        manager.addDevice(QStringLiteral("cnc-gcode"), DeviceKind::CorrectionOutput, QStringLiteral("CNC"),
                          {{QStringLiteral("folder"), dir.path()}});
        QSettings settings(file, QSettings::IniFormat);
        manager.save(settings);
    }
    {
        DeviceManager withoutPlugins;  // e.g. the plugin folder is missing on this terminal
        QSettings settings(file, QSettings::IniFormat);
        const QStringList problems = withoutPlugins.restore(settings);
        ASSERT_EQ(problems.size(), 1);
        EXPECT_TRUE(problems[0].contains(QStringLiteral("cnc-gcode is not installed"))) << problems[0].toStdString();
        EXPECT_EQ(withoutPlugins.deviceIds().size(), 1);
        withoutPlugins.save(settings);  // the CNC entry is kept, not lost
    }
    DeviceManager manager;
    manager.loadPlugins(kBuildPlugins);
    QSettings settings(file, QSettings::IniFormat);
    EXPECT_TRUE(manager.restore(settings).isEmpty());
    ASSERT_EQ(manager.deviceIds().size(), 2);
    const DeviceEntry* gauge = manager.entry(manager.devicesOfKind(DeviceKind::Gauge).front());
    EXPECT_EQ(gauge->name, QStringLiteral("Micrometer"));
    EXPECT_DOUBLE_EQ(gauge->settings.value(QStringLiteral("nominalDiameterMm")).toDouble(), 26.5);
    EXPECT_EQ(manager.entry(manager.devicesOfKind(DeviceKind::CorrectionOutput).front())->pluginId,
              QStringLiteral("cnc-gcode"));
    // New ids never collide with restored ones.
    const QString fresh = manager.addDevice(QStringLiteral("simulator"), DeviceKind::Probe, {}, {});
    EXPECT_FALSE(manager.deviceIds().count(fresh) > 1);
}

TEST(DeviceManager, UpdateReplacesTheInstanceAndKeepsTheOldOneOnBadSettings) {
    DeviceManager manager;
    const QString id = manager.addDevice(QStringLiteral("simulator"), DeviceKind::Gauge, QStringLiteral("G"), {});
    Device* before = manager.device(id);
    EXPECT_THROW(manager.updateDevice(id, QStringLiteral("G"), {{QStringLiteral("decimals"), 9}}),
                 std::invalid_argument);
    EXPECT_EQ(manager.device(id), before);
    manager.updateDevice(id, QStringLiteral("Gauge 2"), {{QStringLiteral("decimals"), 4}});
    EXPECT_EQ(manager.entry(id)->name, QStringLiteral("Gauge 2"));
    EXPECT_EQ(manager.entry(id)->settings.value(QStringLiteral("decimals")).toInt(), 4);
    manager.removeDevice(id);
    EXPECT_TRUE(manager.deviceIds().isEmpty());
}

}  // namespace
}  // namespace tt::devices
