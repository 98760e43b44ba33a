// The Calibration page offscreen (issue 6, item 5): both wizards walked to the end, with Back and
// Cancel keeping the captured points, the refusals shown, the table saved and uploaded with
// read-back of its CRC; the upload also through the devices' simulated mandrel.
#include "ui/pages/calibration_page.h"

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "core/calibration/linearisation_image.h"
#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "devices/api/steady_clock.h"
#include "devices/simulator/simulator_plugin.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/calibration/device_calibration_probe.h"
#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_fit_page.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/calibration/simulated_calibration_probe.h"

namespace tt::ui {
namespace {

class CalibrationPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        state.setOperatorName(QStringLiteral("Anna Test"));
        context.databasePath = dir.filePath(QStringLiteral("history.sqlite"));
    }
    static bool nextEnabled(QWizard* w) { return w->button(QWizard::NextButton)->isEnabled(); }
    static void capture(ProbeCapturePage* page, double um) {
        page->setJack(um);
        page->pollProbe(0.6);  // 60 samples at 100 Hz; the average keeps the last 50
        ASSERT_TRUE(page->capturePoint()) << page->message().toStdString();
    }
    /// Types 21 points of code = 2047.5 + 3 d + k3 d³ over ±450 µm.
    static void typePoints(ProbeCapturePage* page, double k3) {
        for (int i = 0; i <= 20; ++i) {
            const double um = -450.0 + 45.0 * i;
            page->setReferenceUm(um);
            page->setTypedCode(2047.5 + 3.0 * um + k3 * um * um * um);
            page->addTypedPoint();
        }
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(CalibrationPageTest, ProbeWizardCapturesFitsSavesAndUploadsWithBackAndCancel) {
    CalibrationPage page(context);
    page.resize(1400, 900);
    page.show();
    ASSERT_TRUE(page.overviewShown());
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ChoosePage);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_1_choose")));
    w->next();
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ReferencePage);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_2_reference")));
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::CapturePage);
    ProbeCapturePage* cp = w->capturePage();
    EXPECT_FALSE(nextEnabled(w));  // fewer than 5 points
    for (int i = 0; i < 3; ++i)
        capture(cp, -450.0 + 45.0 * i);

    // Back keeps the points.
    w->back();
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ReferencePage);
    EXPECT_EQ(page.probeSession().points.size(), 3u);
    w->next();
    EXPECT_EQ(w->capturePage()->findChild<QTableWidget*>(QStringLiteral("capturedPoints"))->rowCount(), 3);

    // Cancel keeps them too; the page offers to continue.
    w->reject();
    ASSERT_TRUE(page.overviewShown());
    EXPECT_EQ(page.probeSession().points.size(), 3u);
    EXPECT_TRUE(page.findChild<QAbstractButton*>(QStringLiteral("startProbeWizard"))
                    ->text()
                    .contains(QStringLiteral("3 points kept")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_overview_points_kept")));
    page.startProbeCalibration();
    w->next();
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::CapturePage);
    for (int i = 3; i <= 20; ++i)
        capture(cp, -450.0 + 45.0 * i);
    EXPECT_EQ(page.probeSession().points.size(), 21u);
    EXPECT_TRUE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_3_capture")));

    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::FitPage);
    // The simulated bridge is an odd cubic in the gap: cross-validation picks degree 3.
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("degree 3: leave-one-out")))
        << w->fitPage()->explanation().toStdString();
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("Monotonic over the whole ADC range")));
    EXPECT_TRUE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_4_fit")));

    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::AcceptPage);
    EXPECT_FALSE(nextEnabled(w));
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    EXPECT_TRUE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_5_accept")));

    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::SavePage);
    ProbeSavePage* sp = w->savePage();
    EXPECT_FALSE(sp->isComplete());
    ASSERT_TRUE(sp->save());
    ASSERT_TRUE(page.probeSession().saved.has_value());
    EXPECT_EQ(page.probeSession().saved->version, 1);
    EXPECT_EQ(page.probeSession().saved->createdBy, QStringLiteral("Anna Test"));
    EXPECT_FALSE(sp->isComplete());  // uploaded and read back first
    ASSERT_TRUE(sp->upload());
    for (int i = 0; i < 1000 && !sp->isComplete(); ++i)
        sp->pollUpload();
    ASSERT_TRUE(sp->isComplete());
    EXPECT_TRUE(sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().contains(QStringLiteral("Verified")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_6_saved_uploaded")));

    // The mandrel now linearises: its samples carry the deflection the jack holds.
    CalibrationProbe* probe = page.simulatedProbe();
    probe->setJackDeflectionMm(0, 0.2);
    probe->poll(0.5);
    std::optional<core::ProbeSample> last;
    while (auto s = probe->port().takeSample())
        last = s;
    ASSERT_TRUE(last && last->linearised);
    EXPECT_NEAR(last->deflectionMm[0], 0.2, 0.003);

    w->accept();  // Finish
    ASSERT_TRUE(page.overviewShown());
    EXPECT_TRUE(page.probeSession().points.empty());
    QTableWidget* tables = page.tablesView();
    ASSERT_EQ(tables->rowCount(), 1);
    EXPECT_EQ(tables->item(0, 2)->text(), QStringLiteral("1"));
    EXPECT_TRUE(tables->item(0, 7)->text().startsWith(QStringLiteral("verified")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_overview_saved")));
}

TEST_F(CalibrationPageTest, ANonMonotonicSetIsRefusedOnTheFitPage) {
    CalibrationPage page(context);
    page.resize(1400, 900);
    page.show();
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    w->next();
    w->next();
    typePoints(w->capturePage(), -1.2e-5);  // turns at ±288.7 µm
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::FitPage);
    w->fitPage()->setDegree(3);
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("Refused")));
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("not monotonic")));
    EXPECT_FALSE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_fit_refused")));
    w->back();  // remove the points and type a good set
    page.probeSession().points.clear();
    typePoints(w->capturePage(), 3.0e-6);
    w->next();
    EXPECT_TRUE(nextEnabled(w));
}

TEST_F(CalibrationPageTest, AFaultyFlashIsCaughtByTheReadBack) {
    CalibrationPage page(context);
    page.show();
    static_cast<SimulatedCalibrationProbe*>(page.simulatedProbe())->setFaultyFlash(true);
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    w->next();
    w->next();
    typePoints(w->capturePage(), 3.0e-6);
    w->next();
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    w->next();
    ProbeSavePage* sp = w->savePage();
    ASSERT_TRUE(sp->save());
    ASSERT_TRUE(sp->upload());
    for (int i = 0;
         i < 1000 && sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().contains(QStringLiteral("chunk"));
         ++i)
        sp->pollUpload();
    for (int i = 0; i < 50; ++i)
        sp->pollUpload();
    EXPECT_TRUE(
        sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().contains(QStringLiteral("does not match")));
    EXPECT_FALSE(sp->isComplete());
    EXPECT_FALSE(w->button(QWizard::FinishButton)->isEnabled());
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    storage::CalibrationStore store(db);
    ASSERT_EQ(store.tables().size(), 1u);
    EXPECT_FALSE(store.tables()[0].verified);
}

TEST_F(CalibrationPageTest, SavingNeedsTheOperatorsName) {
    state.setOperatorName(QString());
    CalibrationPage page(context);
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    w->next();
    w->next();
    typePoints(w->capturePage(), 3.0e-6);
    w->next();
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    w->next();
    EXPECT_FALSE(w->savePage()->save());
    EXPECT_TRUE(prompt.log.contains(QStringLiteral("warn: Save the table")));
    EXPECT_FALSE(page.probeSession().saved.has_value());
    EXPECT_EQ(page.probeSession().points.size(), 21u);  // nothing lost
}

TEST_F(CalibrationPageTest, KpWizardMeasuresKnownLoadsAndWritesKpIntoTheTool) {
    {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        storage::ToolStore tools(db);
        core::ToolRecord bar = core::defaultTool("T12");
        bar.name = "Boring bar D80 L800";
        bar.currentToForceGainNPerA = 100.0;
        tools.apply({{std::nullopt, bar}}, QStringLiteral("Setup"));
    }
    CalibrationPage page(context);
    page.resize(1400, 900);
    page.show();
    page.startKpCalibration();
    KpCalibrationWizard* w = page.kpWizard();
    ASSERT_NE(w, nullptr);
    w->setupPage()->setToolChecked(QStringLiteral("T12"), true);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_1_setup")));
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::LoadsPage);
    KpLoadsPage* loads = w->loadsPage();
    for (double load : {0.0, 200.0}) {
        loads->setLoadN(load);
        ASSERT_TRUE(loads->measureNow()) << loads->message().toStdString();
    }
    w->back();
    w->next();
    EXPECT_EQ(page.kpSession().points.size(), 2u);
    w->reject();
    ASSERT_TRUE(page.overviewShown());
    page.startKpCalibration();
    w->next();
    EXPECT_EQ(page.kpSession().points.size(), 2u);  // kept across Cancel
    for (double load : {400.0, 600.0}) {
        loads->setLoadN(load);
        ASSERT_TRUE(loads->measureNow()) << loads->message().toStdString();
    }
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_2_loads")));
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::FitPage);
    ASSERT_TRUE(page.kpSession().fit.has_value());
    // The simulated drive's true k_p is 150 N/A.
    EXPECT_NEAR(page.kpSession().fit->kpNPerA, 150.0, 4.5);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_3_fit")));
    w->next();
    ASSERT_TRUE(w->savePage()->save());
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_4_saved")));
    w->accept();
    ASSERT_TRUE(page.overviewShown());
    EXPECT_EQ(page.kpView()->rowCount(), 1);
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    storage::ToolStore tools(db);
    EXPECT_NEAR(tools.tools()[0].currentToForceGainNPerA, 150.0, 4.5);
    EXPECT_EQ(tools.audit().front().field, QStringLiteral("kp_n_per_a"));
    EXPECT_EQ(tools.audit().front().changedBy, QStringLiteral("Anna Test"));
}

TEST_F(CalibrationPageTest, KpWizardRefusesLoadsThatDoNotFit) {
    CalibrationPage page(context);
    page.startKpCalibration();
    KpCalibrationWizard* w = page.kpWizard();
    w->next();
    KpLoadsPage* loads = w->loadsPage();
    for (auto [load, di] : {std::pair{0.0, 1.0}, std::pair{100.0, 0.5}, std::pair{200.0, 0.0}}) {
        loads->setLoadN(load);
        loads->setTypedCurrentDifference(di);
        loads->addTypedPoint();
    }
    w->next();
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("falls as the load grows")));
    EXPECT_FALSE(nextEnabled(w));
}

TEST(DeviceCalibrationProbe, UploadsThroughTheDevicesSimulatedMandrelAndReadsBackItsCrc) {
    devices::SteadyClock clock;
    devices::SimulatorPlugin plugin;
    std::unique_ptr<devices::Device> device =
        plugin.create(devices::DeviceKind::Probe, {}, devices::DeviceContext{&clock});
    device->open();
    ASSERT_TRUE(QTest::qWaitFor([&] { return device->health().ready(); }, 3000)) << device->health().message;
    DeviceCalibrationProbe probe(*device, QStringLiteral("Mandrel on the simulator"), 12);
    ASSERT_TRUE(probe.canUpload());
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.port().takeSample().has_value(); }, 3000));
    // A 12-bit table (8 226 bytes), opaque to the device.
    std::vector<core::CalibrationPoint> points;
    for (int i = 0; i <= 20; ++i) {
        const double um = -450.0 + 45.0 * i;
        points.push_back({um, 2047.5 + 3.0 * um + 3.0e-6 * um * um * um, 0});
    }
    const core::Linearisation lin = core::linearise(points, 12, 3);
    core::TableImageInfo info;
    info.version = 4;
    const std::vector<std::uint8_t> image = core::encodeTableImage(lin.table, info);
    const std::uint32_t crc = core::tableUploadCrc(image);
    probe.startUpload(image, 4, crc);
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.uploadStatus().phase == ProbeUploadStatus::Phase::Done; }, 10000))
        << probe.uploadStatus().message.toStdString();
    probe.requestReadback();
    ASSERT_TRUE(probe.readback().has_value());
    EXPECT_EQ(probe.readback()->version, 4);
    EXPECT_EQ(probe.readback()->crc32c, crc);  // probe protocol 2 reads back the CRC-32C
    EXPECT_TRUE(probe.readback()->valid);
    EXPECT_TRUE(probe.readback()->matches(4, image));
    EXPECT_THROW(probe.startUpload(image, 5, crc ^ 1), std::invalid_argument);
}

}  // namespace
}  // namespace tt::ui
