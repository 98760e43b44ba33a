// The Calibration page with the devices of the Devices page (AppContext::devices): it offers their
// probe mandrels and drive read-outs, the simulator's like any other, and follows changes; the k_p
// wizard measures through the simulator plugin's drive read-out (DeviceKpDrive) with the load
// applied by hand (no stand); the probe wizard calibrates the emulated 16-bit mandrel on a
// pseudo-terminal through the probe-mandrel plugin (no stand: the test bends the bar), and uploads
// the 16-bit table over probe protocol 2 with the read-back of its CRC-32C.
#include <gtest/gtest.h>

#include <atomic>

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "core/calibration/linearisation_image.h"
#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "devices/api/simulated_instrument.h"
#include "runtime/devices/device_hub.h"
#include "devices/simulator/simulated_drive.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/devices/support/mandrel_on_pty.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/calibration/device_calibration_probe.h"
#include "ui/calibration/kp_fit_page.h"
#include "ui/calibration/kp_loads_page.h"
#include "ui/calibration/kp_save_page.h"
#include "ui/calibration/kp_setup_page.h"
#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_accept_page.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_fit_page.h"
#include "ui/calibration/probe_save_page.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/pages/calibration_page.h"

namespace tt::ui {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");

class CalibrationDevicesTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        state.setOperatorName(QStringLiteral("Anna Test"));
        context.databasePath = dir.filePath(QStringLiteral("history.sqlite"));
        context.devices = &manager;
    }
    QString add(devices::DeviceKind kind, const QString& name, const QVariantMap& settings = {},
                const QString& plugin = QStringLiteral("simulator")) {
        return manager.addDevice(plugin, kind, name, settings);
    }
    static QStringList names(const std::vector<DeviceCalibrationProbe*>& probes) {
        QStringList out;
        for (const DeviceCalibrationProbe* p : probes)
            out << p->name();
        return out;
    }
    static QStringList names(const std::vector<DeviceKpDrive*>& drives) {
        QStringList out;
        for (DeviceKpDrive* d : drives)
            out << d->name();
        return out;
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    runtime::DeviceHub manager;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(CalibrationDevicesTest, OffersTheDevicesProbesAndDrivesAndFollowsTheirChanges) {
    const QString probe = add(devices::DeviceKind::Probe, QStringLiteral("Mandrel A"));
    add(devices::DeviceKind::DriveCurrent, QStringLiteral("Cross feed X"));
    manager.openAll();
    CalibrationPage page(context);
    EXPECT_EQ(names(page.offeredProbes()), (QStringList{QStringLiteral("Mandrel A")}));
    EXPECT_EQ(names(page.offeredDrives()), (QStringList{QStringLiteral("Cross feed X")}));
    // The simulator's mandrel says it has a 16-bit ADC (DEVICE_INFO of probe protocol 2).
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return page.offeredProbes()[0]->adcBits().has_value(); }, tt::test::kPatientWaitMs));
    EXPECT_EQ(page.offeredProbes()[0]->adcBits(), 16);
    EXPECT_TRUE(page.offeredProbes()[0]->hasJack());  // the simulator's stand
    EXPECT_TRUE(page.offeredDrives()[0]->hasJack());

    page.startProbeCalibration();
    ASSERT_FALSE(page.overviewShown());
    page.probeSession().procedure.typePoint(10.0, 3300.0);
    // A gauge or a CNC output changing leaves the open wizard alone.
    add(devices::DeviceKind::Gauge, QStringLiteral("Micrometer"));
    EXPECT_FALSE(page.overviewShown());
    // Another probe: the lists follow; the open wizard is closed (it might use a removed device), the points stay.
    add(devices::DeviceKind::Probe, QStringLiteral("Mandrel B"));
    EXPECT_TRUE(page.overviewShown());
    EXPECT_FALSE(page.deviceNotice().isEmpty());
    EXPECT_EQ(page.probeSession().procedure.points().size(), 1u);
    EXPECT_EQ(page.offeredProbes().size(), 2u);
    manager.removeDevice(probe);
    EXPECT_EQ(names(page.offeredProbes()), (QStringList{QStringLiteral("Mandrel B")}));
    page.startProbeCalibration();
    EXPECT_TRUE(page.deviceNotice().isEmpty());
    EXPECT_EQ(page.probeWizard()->findChild<QComboBox*>(QStringLiteral("probeCombo"))->count(), 1);
}

TEST_F(CalibrationDevicesTest, KpWizardMeasuresThroughTheSimulatorPluginsDriveReadout) {
    {
        const auto db = std::make_unique<storage::Database>(storage::DatabaseConfig::sqlite(context.databasePath));
        core::ToolRecord bar = core::defaultTool("T3");
        bar.name = "Boring bar D60";
        storage::ToolStore(*db).apply({{std::nullopt, bar}}, QStringLiteral("Setup"));
    }
    // A fast dither (0.2 s, polled every 10 ms) so each load is measured in a few seconds; the
    // machine's cross feed: friction current ±2 A, the load adds load / 150 N/A (true k_p 150 N/A).
    // Not on a stand: the operator applies the loads.
    const QString id =
        add(devices::DeviceKind::DriveCurrent, QStringLiteral("Cross feed X"),
            {{QStringLiteral("pollMs"), 10}, {QStringLiteral("periodS"), 0.2}, {QStringLiteral("stand"), false}});
    std::atomic<double> loadN{0.0};  // set here, read by the drive in the device thread
    manager.withDevice(id, [&loadN](devices::Device& d) {
        devices::simulatedInstrument(d)->simulationInputs().setDriveSource(
            [&loadN](double t) { return devices::oscillatingCrossFeed(t, 0.02, 0.2, 2.0, loadN.load() / 150.0); });
    });
    manager.openAll();
    CalibrationPage page(context);
    page.resize(1280, 760);
    page.show();
    page.startKpCalibration();
    KpCalibrationWizard* w = page.kpWizard();
    auto* drive = w->findChild<QComboBox*>(QStringLiteral("driveCombo"));
    ASSERT_NE(drive, nullptr);
    ASSERT_EQ(drive->count(), 1);
    EXPECT_EQ(drive->currentText(), QStringLiteral("Cross feed X"));
    w->setupPage()->setToolChecked(QStringLiteral("T3"), true);
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::LoadsPage);
    KpLoadsPage* loads = w->loadsPage();
    for (double load : {0.0, 300.0, 600.0}) {
        loadN = load;           // the operator loads the slide
        loads->setLoadN(load);  // and measures: the procedure lets it settle for a second, then
        ASSERT_TRUE(loads->startMeasurement()) << loads->message().toStdString();  // averages 12 strokes
        // The read-out runs in real time; the page's timer takes its samples.
        ASSERT_TRUE(QTest::qWaitFor([&] { return !loads->measuring(); }, tt::test::kPatientWaitMs));
        ASSERT_TRUE(loads->message().contains(QStringLiteral("stroke pairs"))) << loads->message().toStdString();
    }
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_devices_kp_loads")));
    w->next();
    ASSERT_TRUE(page.kpSession().procedure.fitOutcome().fit.has_value());
    // The injected current gives ΔI = load / 150 exactly; the read-out rounds the current to 0.01 A.
    EXPECT_NEAR(page.kpSession().procedure.fitOutcome().fit->kpNPerA, 150.0, 1.5);
    w->next();
    ASSERT_TRUE(w->savePage()->save());
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    EXPECT_EQ(storage::CalibrationStore(db).kpCalibrations().front().drive, QStringLiteral("Cross feed X"));
}

TEST_F(CalibrationDevicesTest, ProbeWizardCalibratesAndUploadsASixteenBitTableToTheMandrelOnAPty) {
    ASSERT_EQ(manager.loadPlugins(kBuildPlugins), 5) << manager.pluginErrors().join(QStringLiteral("; ")).toStdString();
    devices::test::MandrelOnPty end(QStringLiteral("ttyMANDREL"));
    double jackMm = 0.0;  // the bar is loaded on the stand; the dial indicator reads it
    end.mandrel.setDeflectionSource([&jackMm](double) { return std::array<double, 2>{jackMm, 0.0}; });
    add(devices::DeviceKind::Probe, QStringLiteral("Mandrel on COM3"),
        {{QStringLiteral("port"), end.pty.portName()}, {QStringLiteral("baud"), 115200}},
        QStringLiteral("probe-mandrel"));
    manager.openAll();
    CalibrationPage page(context);
    page.resize(1280, 760);
    page.show();
    ASSERT_EQ(page.offeredProbes().size(), 1u);
    DeviceCalibrationProbe* mandrel = page.offeredProbes()[0];
    EXPECT_FALSE(mandrel->hasJack());  // a mandrel on a machine: the operator loads the bar
    ASSERT_TRUE(QTest::qWaitFor([&] { return mandrel->port().health().ready() && mandrel->adcBits(); },
                                tt::test::kPatientWaitMs));
    EXPECT_EQ(mandrel->adcBits(), 16);
    EXPECT_EQ(mandrel->imageFormat(), core::kTableImageFormat);

    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    EXPECT_FALSE(w->findChild<QSpinBox*>(QStringLiteral("adcBitsSpin"))->isEnabled());  // the mandrel said 16
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_devices_probe_1_choose")));
    w->next();
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::CapturePage);
    ProbeCapturePage* cp = w->capturePage();
    for (int i = 0; i <= 10; ++i) {
        const double um = -250.0 + 50.0 * i;
        jackMm = um / 1000.0;
        QTest::qWait(200);  // the operator reads the dial indicator
        cp->setReferenceUm(um);
        ASSERT_TRUE(cp->capturePoint()) << cp->message().toStdString();
        // Hold still, then 50 samples at 200 samples/s; the page's timer takes them.
        ASSERT_TRUE(QTest::qWaitFor([&] { return !cp->capturing(); }, tt::test::kPatientWaitMs));
        ASSERT_TRUE(cp->message().startsWith(QStringLiteral("Point"))) << cp->message().toStdString();
    }
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_devices_probe_2_capture")));
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::FitPage);
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("Monotonic over the whole ADC range")))
        << w->fitPage()->explanation().toStdString();
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    w->next();
    ProbeSavePage* sp = w->savePage();
    ASSERT_TRUE(sp->save());
    ASSERT_EQ(page.probeSession().saved->image.size(), 131104);  // format 2, 2^16 entries
    ASSERT_TRUE(sp->upload());
    auto* result = sp->findChild<QLabel*>(QStringLiteral("saveResult"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return sp->isComplete() || result->text().contains(QStringLiteral("failed")); },
                                tt::test::kPatientWaitMs))
        << result->text().toStdString();
    EXPECT_TRUE(result->text().contains(QStringLiteral("Verified"))) << result->text().toStdString();
    EXPECT_TRUE(result->text().contains(QStringLiteral("CRC-32C"))) << result->text().toStdString();
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_devices_probe_3_uploaded")));
    // The mandrel holds the image saved, and the record says so.
    const QByteArray saved = page.probeSession().saved->image;
    EXPECT_EQ(end.mandrel.tableImage(), std::vector<std::uint8_t>(saved.begin(), saved.end()));
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    const storage::ProbeTableRecord record = storage::CalibrationStore(db).tables().front();
    EXPECT_TRUE(record.verified);
    ASSERT_TRUE(record.readbackCrc.has_value());
    EXPECT_EQ(*record.readbackCrc, record.uploadCrc);
    EXPECT_EQ(record.uploadCrc, static_cast<qint64>(core::tableUploadCrc(end.mandrel.tableImage())));
}

}  // namespace
}  // namespace tt::ui
