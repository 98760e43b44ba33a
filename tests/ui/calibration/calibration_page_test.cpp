// The Calibration page offscreen (issue 6, item 5): both wizards walked to the end on the built-in
// simulator's devices, which are devices like any other (the probe mandrel with the screw jack of
// its stand, the drive read-out with the hydraulic jack of the k_p stand): Back and Cancel keep the
// captured points, saturated points are flagged and refused by the fit, the refusals shown, the
// table verified at a further point, saved and uploaded with read-back of its CRC; k_p measured,
// verified and written into the tool. Simulated time is stepped by hand (core::ManualClock).
#include "ui/pages/calibration_page.h"

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "core/calibration/linearisation_image.h"
#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "devices/api/simulated_instrument.h"
#include "runtime/devices/device_hub.h"
#include "devices/api/steady_clock.h"
#include "devices/simulator/mandrel_emulator.h"
#include "devices/simulator/simulated_probe.h"
#include "devices/simulator/simulator_plugin.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "stand_devices.h"
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

namespace tt::ui {
namespace {

class CalibrationPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        state.setOperatorName(QStringLiteral("Anna Test"));
        context.databasePath = dir.filePath(QStringLiteral("history.sqlite"));
        context.devices = &stand.manager;
        ASSERT_TRUE(stand.waitReady());
    }
    void step(double seconds) { stand.step(seconds); }
    static bool nextEnabled(QWizard* w) { return w->button(QWizard::NextButton)->isEnabled(); }
    /// Bends the bar to `um` on the stand and captures: hold still, then 50 samples averaged.
    void capture(ProbeCapturePage* page, double um) {
        page->setJack(um);
        step(0.3);  // the mandrel's samples under the old load are through before the press
        ASSERT_TRUE(page->capturePoint());
        for (int i = 0; i < 200 && page->capturing(); ++i) {
            step(0.05);
            page->pollProbe();
        }
        ASSERT_FALSE(page->capturing());
        ASSERT_TRUE(page->message().startsWith(QStringLiteral("Point"))) << page->message().toStdString();
    }
    /// 21 points over ±260 µm, within the mandrel's ±294 µm (16-bit bridge of MandrelEmulator).
    void captureSweep(ProbeCapturePage* page, int from, int to) {
        for (int i = from; i <= to; ++i)
            capture(page, -260.0 + 26.0 * i);
    }
    /// Types 21 points of code = 32767.5 + 100 d + k3 d³ over ±250 µm (16-bit).
    static void typePoints(ProbeCapturePage* page, double k3) {
        for (int i = 0; i <= 20; ++i) {
            const double um = -250.0 + 25.0 * i;
            page->setReferenceUm(um);
            page->setTypedCode(32767.5 + 100.0 * um + k3 * um * um * um);
            page->addTypedPoint();
        }
    }
    /// Measures a verification load on the fit page; the result as worded.
    QString check(KpFitPage* fit, double loadN) {
        fit->setCheckLoadN(loadN);
        if (!fit->checkLoad()) return {};
        for (int i = 0; i < 2000 && fit->checking(); ++i) {
            step(0.05);
            fit->step(0.05);
        }
        return fit->checkResult();
    }
    bool measure(KpLoadsPage* loads, double loadN) {
        loads->setLoadN(loadN);
        if (!loads->startMeasurement()) return false;
        for (int i = 0; i < 2000 && loads->measuring(); ++i) {
            step(0.05);
            loads->step(0.05);
        }
        return loads->message().contains(QStringLiteral("stroke pairs"));
    }

    /// Whether the stand of device `id` has its jack engaged.
    bool jackEngaged(const QString& id) {
        bool engaged = false;
        manager.withDevice(id, [&](devices::Device& d) {
            devices::SimulatedInstrument* sim = devices::simulatedInstrument(d);
            engaged = sim && sim->calibrationStand() && sim->calibrationStand()->engaged();
        });
        return engaged;
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    test::StandDevices stand{QStringLiteral("Simulated probe mandrel"),
                             QStringLiteral("Simulated drive-current readout")};
    runtime::DeviceHub& manager = stand.manager;
    const QString& probeId = stand.probeId;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(CalibrationPageTest, ProbeWizardCapturesFitsVerifiesSavesAndUploadsWithBackAndCancel) {
    CalibrationPage page(context);
    page.resize(1280, 760);
    page.show();
    ASSERT_TRUE(page.overviewShown());
    ASSERT_EQ(page.offeredProbes().size(), 1u);
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ChoosePage);
    // The simulated mandrel says it has a 16-bit ADC (probe protocol 2's DEVICE_INFO).
    EXPECT_EQ(page.probeSession().procedure.config().adcBits, 16);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_1_choose")));
    w->next();
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ReferencePage);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_2_reference")));
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::CapturePage);
    ProbeCapturePage* cp = w->capturePage();
    EXPECT_FALSE(nextEnabled(w));  // fewer than 5 points
    captureSweep(cp, 0, 2);

    // Back keeps the points.
    w->back();
    EXPECT_EQ(w->currentId(), ProbeCalibrationWizard::ReferencePage);
    EXPECT_EQ(page.probeSession().procedure.points().size(), 3u);
    w->next();
    EXPECT_EQ(w->capturePage()->findChild<QTableWidget*>(QStringLiteral("capturedPoints"))->rowCount(), 3);

    // Cancel keeps them too; the page offers to continue.
    w->reject();
    ASSERT_TRUE(page.overviewShown());
    EXPECT_EQ(page.probeSession().procedure.points().size(), 3u);
    EXPECT_TRUE(page.findChild<QAbstractButton*>(QStringLiteral("startProbeWizard"))
                    ->text()
                    .contains(QStringLiteral("3 points kept")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_overview_points_kept")));
    page.startProbeCalibration();
    w->next();
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::CapturePage);
    captureSweep(cp, 3, 20);
    // Point 1 read again at its load: it is replaced, not added.
    cp->selectPoint(0);
    cp->setJack(-260.0);
    step(0.3);  // the mandrel's samples under the old load are through before the press
    ASSERT_TRUE(cp->repeatPoint());
    for (int i = 0; i < 200 && cp->capturing(); ++i) {
        step(0.05);
        cp->pollProbe();
    }
    EXPECT_TRUE(cp->message().startsWith(QStringLiteral("Point 1 read again"))) << cp->message().toStdString();
    EXPECT_EQ(page.probeSession().procedure.points().size(), 21u);
    // Beyond the bridge's full scale (±294 µm at the tip) the mandrel flags its ADC over range and
    // withholds those samples: the capture says why it got none.
    cp->setJack(320.0);
    step(0.3);  // the mandrel's samples under the old load are through before the press
    ASSERT_TRUE(cp->capturePoint());
    for (int i = 0; i < 50 && cp->capturing(); ++i) {
        step(0.05);
        cp->pollProbe();
    }
    EXPECT_TRUE(cp->message().contains(QStringLiteral("over range"))) << cp->message().toStdString();
    // A point whose code is at the ADC's limit (read off the mandrel's display) is flagged in red,
    // kept, and left out of the fit.
    cp->setReferenceUm(320.0);
    cp->setTypedCode(65535.0);
    ASSERT_TRUE(cp->addTypedPoint());
    EXPECT_TRUE(cp->message().contains(QStringLiteral("The ADC saturated here"))) << cp->message().toStdString();
    auto* table = cp->findChild<QTableWidget*>(QStringLiteral("capturedPoints"));
    ASSERT_EQ(table->rowCount(), 22);
    EXPECT_TRUE(table->item(21, 2)->text().contains(QStringLiteral("ADC saturated")));
    EXPECT_TRUE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_3_capture")));

    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::FitPage);
    // The emulated bridge is an odd cubic in the gap (r = 1.15 u − 0.15 u³): cross-validation picks 3.
    const QString fit = w->fitPage()->explanation();
    EXPECT_TRUE(fit.contains(QStringLiteral("degree 3: leave-one-out"))) << fit.toStdString();
    EXPECT_TRUE(fit.contains(QStringLiteral("Degree 3 chosen by cross-validation"))) << fit.toStdString();
    EXPECT_TRUE(fit.contains(QStringLiteral("Not used in the fit: point(s) 22"))) << fit.toStdString();
    EXPECT_TRUE(fit.contains(QStringLiteral("Monotonic over the whole ADC range")));
    EXPECT_EQ(page.probeSession().procedure.fitOutcome().fit->degree, 3);
    EXPECT_TRUE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_4_fit")));

    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::AcceptPage);
    EXPECT_FALSE(nextEnabled(w));
    // Verification at 123 µm, a deflection not captured: the table reads it within its tolerance.
    ProbeAcceptPage* ap = w->acceptPage();
    ap->setJack(123.0);
    step(0.3);  // the mandrel's samples under the old load are through before the press
    ASSERT_TRUE(ap->checkPoint());
    for (int i = 0; i < 200 && page.probeSession().procedure.capturing(); ++i) {
        step(0.05);
        ap->pollProbe();
    }
    EXPECT_TRUE(ap->checkResult().contains(QStringLiteral("Passed"))) << ap->checkResult().toStdString();
    ASSERT_EQ(page.probeSession().procedure.checks().size(), 1u);
    EXPECT_NEAR(page.probeSession().procedure.checks()[0].readingUm, 123.0, 1.0);
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
    EXPECT_EQ(page.probeSession().saved->image.size(), 131104);  // format 2, 2^16 entries
    EXPECT_FALSE(sp->isComplete());                              // uploaded and read back first
    ASSERT_TRUE(sp->upload());
    for (int i = 0; i < 1000 && !sp->isComplete(); ++i) {
        step(0.05);
        sp->pollUpload();
    }
    ASSERT_TRUE(sp->isComplete());
    EXPECT_TRUE(sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().contains(QStringLiteral("Verified")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_6_saved_uploaded")));

    // The mandrel holds the image saved, and that table reads the bridge's code at 0.2 mm as
    // 0.2 mm (3 µm: the fit and the table's step).
    const QByteArray saved = page.probeSession().saved->image;
    std::vector<std::uint8_t> stored;
    manager.withDevice(probeId, [&](devices::Device& d) {
        if (const auto* mandrel = dynamic_cast<devices::SimulatedProbe*>(&d)) stored = mandrel->emulator().tableImage();
    });
    EXPECT_EQ(stored, std::vector<std::uint8_t>(saved.begin(), saved.end()));
    const core::TableImage image = core::decodeTableImage(std::vector<std::uint8_t>(saved.begin(), saved.end()));
    EXPECT_NEAR(image.table.deflectionUm(devices::MandrelEmulator::adcCode(0.2)), 200.0, 3.0);

    w->accept();  // Finish
    ASSERT_TRUE(page.overviewShown());
    EXPECT_TRUE(page.probeSession().procedure.points().empty());
    EXPECT_FALSE(jackEngaged(probeId));  // the jack is released
    QTableWidget* tables = page.tablesView();
    ASSERT_EQ(tables->rowCount(), 1);
    EXPECT_EQ(tables->item(0, 2)->text(), QStringLiteral("1"));
    EXPECT_TRUE(tables->item(0, 7)->text().startsWith(QStringLiteral("verified")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_overview_saved")));
}

TEST_F(CalibrationPageTest, ANonMonotonicSetIsRefusedOnTheFitPage) {
    CalibrationPage page(context);
    page.resize(1280, 760);
    page.show();
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    w->next();
    w->next();
    typePoints(w->capturePage(), -8.0e-4);  // turns at ±204.1 µm, inside the points
    w->next();
    ASSERT_EQ(w->currentId(), ProbeCalibrationWizard::FitPage);
    w->fitPage()->setDegree(3);
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("Refused")));
    EXPECT_TRUE(w->fitPage()->explanation().contains(QStringLiteral("not monotonic")));
    EXPECT_FALSE(nextEnabled(w));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_probe_fit_refused")));
    w->back();  // remove the points and type a good set
    while (!page.probeSession().procedure.points().empty())
        w->capturePage()->removePoint();
    typePoints(w->capturePage(), 1.0e-4);
    w->next();
    EXPECT_TRUE(nextEnabled(w));
}

TEST_F(CalibrationPageTest, AFaultyFlashIsCaughtByTheReadBack) {
    manager.withDevice(probeId, [](devices::Device& d) {
        dynamic_cast<devices::SimulatedProbe&>(d).emulator().setFaultyFlash(true);
    });
    CalibrationPage page(context);
    page.show();
    page.startProbeCalibration();
    ProbeCalibrationWizard* w = page.probeWizard();
    w->next();
    w->next();
    typePoints(w->capturePage(), 1.0e-4);
    w->next();
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    w->next();
    ProbeSavePage* sp = w->savePage();
    ASSERT_TRUE(sp->save());
    ASSERT_TRUE(sp->upload());
    for (int i = 0; i < 1000 && page.probeSession().procedure.upload().running(); ++i) {
        step(0.05);
        sp->pollUpload();
    }
    EXPECT_TRUE(sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().contains(QStringLiteral("does not match")))
        << sp->findChild<QLabel*>(QStringLiteral("saveResult"))->text().toStdString();
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
    typePoints(w->capturePage(), 1.0e-4);
    w->next();
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    w->next();
    EXPECT_FALSE(w->savePage()->save());
    EXPECT_TRUE(prompt.log.contains(QStringLiteral("warn: Save the table")));
    EXPECT_FALSE(page.probeSession().saved.has_value());
    EXPECT_EQ(page.probeSession().procedure.points().size(), 21u);  // nothing lost
}

TEST_F(CalibrationPageTest, KpWizardMeasuresKnownLoadsVerifiesAndWritesKpIntoTheTool) {
    {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        storage::ToolStore tools(db);
        core::ToolRecord bar = core::defaultTool("T12");
        bar.name = "Boring bar D80 L800";
        bar.currentToForceGainNPerA = 100.0;
        tools.apply({{std::nullopt, bar}}, QStringLiteral("Setup"));
    }
    CalibrationPage page(context);
    page.resize(1280, 760);
    page.show();
    page.startKpCalibration();
    KpCalibrationWizard* w = page.kpWizard();
    ASSERT_NE(w, nullptr);
    w->setupPage()->setToolChecked(QStringLiteral("T12"), true);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_1_setup")));
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::LoadsPage);
    KpLoadsPage* loads = w->loadsPage();
    for (double load : {0.0, 200.0})
        ASSERT_TRUE(measure(loads, load)) << loads->message().toStdString();
    w->back();
    w->next();
    EXPECT_EQ(page.kpSession().procedure.points().size(), 2u);
    w->reject();
    ASSERT_TRUE(page.overviewShown());
    EXPECT_FALSE(jackEngaged(manager.devicesOfKind(devices::DeviceKind::DriveCurrent).front()));  // Cancel released the jack
    page.startKpCalibration();
    w->next();
    EXPECT_EQ(page.kpSession().procedure.points().size(), 2u);  // kept across Cancel
    for (double load : {400.0, 600.0})
        ASSERT_TRUE(measure(loads, load)) << loads->message().toStdString();
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_2_loads")));
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::FitPage);
    ASSERT_TRUE(page.kpSession().procedure.fitOutcome().fit.has_value());
    // The stand's drive has the true k_p 150 N/A (core::KnownLoadRig, heavy-boring cross feed).
    EXPECT_NEAR(page.kpSession().procedure.fitOutcome().fit->kpNPerA, 150.0, 4.5);
    // Verification at 300 N, a load not used by the fit.
    const QString verdict = check(w->fitPage(), 300.0);
    EXPECT_TRUE(verdict.contains(QStringLiteral("Passed"))) << verdict.toStdString();
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("calibration_kp_3_fit")));
    w->next();
    ASSERT_EQ(w->currentId(), KpCalibrationWizard::SavePage);
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

TEST_F(CalibrationPageTest, KpWizardRefusesLoadsThatDoNotFitAndAFailedVerification) {
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
    // Typed loads of another drive (k_p 100 N/A): the stand's drive (150 N/A) fails the check.
    w->back();
    while (!page.kpSession().procedure.points().empty())
        loads->removePoint();
    for (double load : {0.0, 300.0, 600.0}) {
        loads->setLoadN(load);
        loads->setTypedCurrentDifference(load / 100.0);
        loads->addTypedPoint();
    }
    w->next();
    ASSERT_TRUE(nextEnabled(w));
    KpFitPage* fp = w->fitPage();
    const QString verdict = check(fp, 300.0);
    EXPECT_TRUE(verdict.contains(QStringLiteral("Failed"))) << verdict.toStdString();
    w->next();  // refused: the verification failed
    EXPECT_EQ(w->currentId(), KpCalibrationWizard::FitPage);
    EXPECT_TRUE(fp->checkResult().contains(QStringLiteral("Not accepted")));
}

TEST(DeviceCalibrationProbe, UploadsThroughTheDevicesSimulatedMandrelAndReadsBackItsCrc) {
    runtime::DeviceHub hub;
    const QString id = hub.addDevice(QStringLiteral("simulator"), devices::DeviceKind::Probe, QStringLiteral("M"), {});
    hub.openAll();
    ASSERT_TRUE(QTest::qWaitFor([&] { return hub.view(id)->health.ready(); }, tt::test::kPatientWaitMs)) << hub.view(id)->health.message;
    DeviceCalibrationProbe probe(hub, id, QStringLiteral("Mandrel on the simulator"), 12);
    ASSERT_TRUE(probe.canUpload());
    EXPECT_TRUE(probe.hasJack());
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.port().takeSample().has_value(); }, tt::test::kPatientWaitMs));
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
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.uploadStatus().phase == core::UploadLinkStatus::Phase::Done; },
                                tt::test::kPatientWaitMs))
        << probe.uploadStatus().message;
    probe.requestReadback();
    ASSERT_TRUE(QTest::qWaitFor([&] { return probe.readback() && probe.readback()->version == 4; }, 3000));
    EXPECT_EQ(probe.readback()->version, 4);
    EXPECT_EQ(probe.readback()->crc32c, crc);  // probe protocol 2 reads back the CRC-32C
    EXPECT_TRUE(probe.readback()->valid);
    EXPECT_TRUE(probe.readback()->matches(4, image));
    EXPECT_THROW(probe.startUpload(image, 5, crc ^ 1), std::invalid_argument);
    // Its stand's screw jack, released by whoever engaged it.
    auto engaged = [&] {
        bool on = false;
        hub.withDevice(id, [&](devices::Device& d) {
            on = devices::simulatedInstrument(d)->calibrationStand()->engaged();
        });
        return on;
    };
    probe.bendBar(0, 0.1);
    EXPECT_TRUE(engaged());
    probe.releaseJack();
    EXPECT_FALSE(engaged());
}

}  // namespace
}  // namespace tt::ui
