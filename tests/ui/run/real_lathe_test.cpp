// The Run page on the real lathe, offscreen: the devices configured on the Devices page drive the closed
// loop. A serial gauge micrometer (emulated on a real pseudo-terminal) and a G-code file output (in a
// temporary folder) are configured; the operator chooses "Real lathe", starts, machines each part from the
// G-code file the loop wrote (the test's lathe turns the diameters that file commands), presses Part finished
// and measures the part with the micrometer's DATA button. Checked: the G-code files, the history (parts,
// measurements, corrections), the loop pausing with the correction held when the gauge is unplugged and
// continuing when it is plugged in again, and Start refused with the reason when a device is not ready.
#include <gtest/gtest.h>

#include <QDateTime>
#include <QFileInfo>
#include <chrono>
#include <thread>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <functional>
#include <map>
#include <ostream>

#include "config/loop_scenario.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "runtime/devices/device_hub.h"
#include "devices/simulator/micrometer_emulator.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/devices/support/pty_pair.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"
#include "runtime/run/machine_catalog.h"
#include "runtime/run/stored_runs.h"
#include "ui/run/lathe_panel.h"
#include "runtime/run/run_session.h"
#include "ui/run/shaft_run_panel.h"

// Readable QString values in failure messages.
inline void PrintTo(const QString& text, std::ostream* os) {
    *os << '"' << text.toStdString() << '"';
}

namespace tt::ui {
namespace {

const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");
constexpr double kNominalMm = 27.0;   // paper-2012-group1 (and the G-code output's default)
constexpr double kToolSetMm = 0.030;  // the test lathe's tool is set 0.030 mm large on diameter
const std::vector<double> kPointsMm{0.0, 27.5, 162.5, 262.5, 325.0};  // the preset's control points

bool waitFor(const std::function<bool()>& done, int timeoutMs = tt::test::kPatientWaitMs) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs) return false;
        QTest::qWait(10);
    }
    return true;
}

/// The radial corrections of the path in a G-code file at the control points: "(SEG n X162.500 DX-0.012)".
std::map<double, double> pathCorrections(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QString text = QString::fromLatin1(f.readAll());
    std::map<double, double> out;
    static const QRegularExpression re(QStringLiteral("\\((?:START|SEG \\d+) X([0-9.]+) DX(-?[0-9.]+)\\)"));
    for (auto it = re.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        out[m.captured(1).toDouble()] = m.captured(2).toDouble();
    }
    return out;
}

/// The applied per-point corrections a G-code file states: "(CONTROL POINTS: X0.000=-0.012 ...)".
std::vector<double> pointCorrections(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QString text = QString::fromLatin1(f.readAll());
    std::vector<double> out;
    static const QRegularExpression line(QStringLiteral("\\(CONTROL POINTS:([^)]*)\\)"));
    static const QRegularExpression pair(QStringLiteral("X[0-9.]+=(-?[0-9.]+)"));
    const auto m = line.match(text);
    for (auto it = pair.globalMatch(m.captured(1)); it.hasNext();)
        out.push_back(it.next().captured(1).toDouble());
    return out;
}

class RealLatheTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        ASSERT_EQ(manager.loadPlugins(kBuildPlugins), 5)
            << manager.pluginErrors().join(QStringLiteral("; ")).toStdString();
        ASSERT_TRUE(QDir().mkpath(dncFolder()));
        micrometer.setSource([] { return kNominalMm; });
        gaugeId =
            manager.addDevice(QStringLiteral("gauge-serial"), devices::DeviceKind::Gauge,
                              QStringLiteral("Micrometer at the lathe"), {{QStringLiteral("port"), pty.portName()}});
        outputId = manager.addDevice(QStringLiteral("cnc-gcode"), devices::DeviceKind::CorrectionOutput,
                                     QStringLiteral("DNC folder"), {{QStringLiteral("folder"), dncFolder()}});
        manager.openAll();
        ASSERT_TRUE(waitFor([&] { return manager.view(gaugeId)->health.ready(); }))
            << manager.view(gaugeId)->health.message;
        pty.releaseSlave();
        context.devices = &manager;
        scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"), 1);
    }

    QString dncFolder() const { return dir.filePath(QStringLiteral("dnc")); }
    QString gcodeFile(qint64 part) const { return QDir(dncFolder()).filePath(QStringLiteral("part-%1.nc").arg(part)); }
    int gcodeFiles() const { return static_cast<int>(QDir(dncFolder()).entryList(QDir::Files).size()); }
    int readingsAccepted() { return manager.view(gaugeId)->statistics.front().value.toInt(); }

    /// The diameters the test lathe turns from the path in the part's G-code file: the lathe's own error
    /// (the preset's systematic barrel d(x), which the loop's feed-forward knows, plus the tool set
    /// kToolSetMm large, which it does not) plus twice the radial correction commanded at each point.
    std::vector<double> machine(qint64 part) {
        const std::map<double, double> path = pathCorrections(gcodeFile(part));
        std::vector<double> d;
        for (double x : kPointsMm) {
            const auto it = path.find(x);
            EXPECT_NE(it, path.end()) << "no path point at x = " << x << " in part " << part;
            const double correction = it == path.end() ? 0.0 : it->second;
            d.push_back(kNominalMm + scenario.systematicModel->value(x) + kToolSetMm + 2.0 * correction);
        }
        return d;
    }

    /// The operator measures the part at the points in order with the micrometer's DATA button.
    void measure(const std::vector<double>& diameters) {
        for (double d : diameters) {
            const int before = readingsAccepted();
            micrometer.setSource([d] { return d; });
            pty.send(micrometer.pressDataButton());
            ASSERT_TRUE(waitFor([&] { return readingsAccepted() == before + 1; }));
        }
    }

    RunPage& openRunPage(MainWindow& window) {
        window.resize(1280, 800);
        window.show();
        window.showPage(PageId::Run);
        return *static_cast<RunPage*>(window.page(PageId::Run));
    }

    void chooseRealLathe(QWidget& page) {
        auto* machineCombo = page.findChild<QComboBox*>(QStringLiteral("machineCombo"));
        machineCombo->setCurrentIndex(machineCombo->findData(runtime::kDevicesLatheKey));
        auto* output = page.findChild<QComboBox*>(QStringLiteral("cncOutputCombo"));
        output->setCurrentIndex(output->findData(outputId));
        auto* gauge = page.findChild<QComboBox*>(QStringLiteral("gaugeCombo"));
        gauge->setCurrentIndex(gauge->findData(gaugeId));
    }

    QTemporaryDir dir;
    devices::test::PtyPair pty{QStringLiteral("ttyLATHEGAUGE")};
    devices::MicrometerEmulator micrometer{devices::MicrometerEmulator::Format::Ascii};
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub manager;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite"))};
    QString gaugeId;
    QString outputId;
    config::LoopScenario scenario;
};

TEST_F(RealLatheTest, DevicesDriveTheLoopAndAnUnpluggedGaugePausesItWithTheCorrectionHeld) {
    MainWindow window(context);
    RunPage& page = openRunPage(window);
    ShaftRunPanel& shaft = page.shaft();
    EXPECT_EQ(state.deviceTone(), AppState::Tone::Ok) << "the badge follows the configured devices";

    chooseRealLathe(page);
    page.findChild<QSpinBox*>(QStringLiteral("delaySpin"))->setValue(1);
    const auto* deviceText = page.findChild<QLabel*>(QStringLiteral("deviceText"));
    EXPECT_TRUE(deviceText->text().contains(QStringLiteral("CNC: “DNC folder” — ready")))
        << deviceText->text().toStdString();
    EXPECT_TRUE(deviceText->text().contains(QStringLiteral("Gauge: “Micrometer at the lathe” — ready")))
        << deviceText->text().toStdString();
    EXPECT_FALSE(page.findChild<QComboBox*>(QStringLiteral("speedCombo"))->isVisible()) << "real time";
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_real_lathe_idle")));

    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    QPushButton* finished = shaft.lathePanel()->finishedButton();
    const runtime::RunSession& session = shaft.session();
    std::vector<std::vector<double>> turned;  // diameters of parts 1.. as the test lathe turned them
    // Part `part` is on the machine and the operator can say it is finished.
    auto onMachine = [&](qint64 part) {
        return waitFor([&] {
            return session.snapshot().partOnMachine == part && finished->isEnabled() &&
                   finished->text() == QStringLiteral("Part %1 finished").arg(part);
        });
    };
    for (qint64 part = 1; part <= 3; ++part) {
        ASSERT_TRUE(onMachine(part)) << core::describe(session.snapshot().status);
        ASSERT_TRUE(QFile::exists(gcodeFile(part))) << "the corrections are on the CNC before the part is machined";
        EXPECT_EQ(gcodeFiles(), part);
        turned.push_back(machine(part));
        finished->click();
        EXPECT_FALSE(finished->isEnabled()) << "one press per part";
        ASSERT_TRUE(waitFor([&] { return session.snapshot().awaitingPart == part; }));
        if (part == 2) {
            auto* detail = shaft.lathePanel()->findChild<QLabel*>(QStringLiteral("latheMeasureDetail"));
            EXPECT_EQ(shaft.lathePanel()->measureText(), QStringLiteral("Measure part 2 at x = 0.0 mm"));
            EXPECT_EQ(detail->text(), QStringLiteral("Point 1 of 5 · last reading %1 mm")
                                          .arg(std::round(turned[0][4] * 1000.0) / 1000.0, 0, 'f', 3));
            measure({turned[1][0], turned[1][1]});
            ASSERT_TRUE(waitFor([&] { return session.snapshot().nextPoint == 2; }));
            EXPECT_EQ(shaft.lathePanel()->measureText(), QStringLiteral("Measure part 2 at x = 162.5 mm"));
            EXPECT_TRUE(detail->text().startsWith(QStringLiteral("Point 3 of 5 · last reading ")));
            EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_real_lathe_measuring")));
            measure({turned[1][2], turned[1][3], turned[1][4]});
        } else {
            measure(turned.back());
        }
    }

    // Part 4 is on the machine when the gauge's cable comes out; it is finished but cannot be measured.
    ASSERT_TRUE(onMachine(4)) << core::describe(session.snapshot().status);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_real_lathe_part_on_machine")));
    turned.push_back(machine(4));
    const std::vector<double> held = pointCorrections(gcodeFile(4));
    pty.unplug();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().gauge.state == core::DeviceState::Error; }))
        << "the gauge's health crosses to the loop";
    finished->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().state == core::LoopState::Paused; }))
        << core::describe(session.snapshot().status);
    EXPECT_EQ(session.snapshot().status.kind, core::NoticeKind::GaugeNotReady)
        << core::describe(session.snapshot().status);
    EXPECT_EQ(state.loop(), AppState::Loop::Paused);
    // The badge follows the device thread's snapshot of the gauge, which may come a flush after the loop's.
    EXPECT_TRUE(waitFor([&] { return state.deviceTone() == AppState::Tone::Fault; }))
        << "the badge shows the unplugged gauge";
    QTest::qWait(300);  // fifteen ticks of the loop: still nothing new
    EXPECT_EQ(session.snapshot().state, core::LoopState::Paused);
    EXPECT_EQ(gcodeFiles(), 4) << "no new part, no new corrections";
    EXPECT_FALSE(session.snapshot().partOnMachine);
    EXPECT_FALSE(finished->isEnabled());
    EXPECT_FALSE(shaft.lathePanel()->readingButton()->isEnabled()) << "nothing to ask while unplugged";
    EXPECT_TRUE(deviceText->text().contains(QStringLiteral("Gauge: “Micrometer at the lathe” — error")))
        << deviceText->text().toStdString();
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_real_lathe_gauge_unplugged")));

    // Plugged in again: the loop continues by itself, takes part 4's diameters and writes part 5.
    pty.plug();
    ASSERT_TRUE(waitFor([&] { return manager.view(gaugeId)->health.ready(); }, tt::test::kPatientWaitMs))
        << manager.view(gaugeId)->health.message;
    pty.releaseSlave();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().state == core::LoopState::Running; }))
        << core::describe(session.snapshot().status);
    measure(turned.back());
    ASSERT_TRUE(onMachine(5)) << core::describe(session.snapshot().status);
    turned.push_back(machine(5));
    finished->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().awaitingPart == 5; }));
    measure(turned.back());
    ASSERT_TRUE(onMachine(6));
    page.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().state == core::LoopState::Idle; }));
    EXPECT_FALSE(manager.latheConnected()) << "the run is over: the devices are let go";

    // The history: parts 1..5 with the corrections written into their G-code files and the diameters the
    // micrometer sent (0.001 mm resolution), all accepted.
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    storage::SqlHistoryStore history(db);
    const std::vector<core::RunSummary> runs = history.runs();
    ASSERT_EQ(runs.size(), 1u);
    const runtime::RunRequest stored = runtime::requestOfStoredRun(runs.front());
    EXPECT_EQ(stored.machine, runtime::kDevicesLatheKey);
    EXPECT_EQ(stored.cncOutput, outputId);
    EXPECT_EQ(stored.gauge, gaugeId);
    const std::vector<core::StoredPart> parts = history.parts(runs.front().runId);
    ASSERT_EQ(parts.size(), 5u) << "part 6 was on the machine when the run was stopped";
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const core::StoredPart& part = parts[p];
        EXPECT_EQ(part.partNumber, static_cast<std::int64_t>(p + 1));
        const std::vector<double> inFile = pointCorrections(gcodeFile(part.partNumber));
        ASSERT_EQ(part.corrections.size(), 5u);
        ASSERT_EQ(inFile.size(), 5u);
        for (std::size_t i = 0; i < 5; ++i)  // the file states them to 0.001 mm
            EXPECT_NEAR(part.corrections[i].appliedMm, inFile[i], 0.0005) << "part " << p + 1 << " point " << i;
        ASSERT_TRUE(part.measurement) << "part " << p + 1;
        for (std::size_t i = 0; i < 5; ++i) {
            const core::PointMeasurementRecord& m = part.measurement->points[i];
            ASSERT_TRUE(m.measuredMm);
            EXPECT_NEAR(*m.measuredMm, std::round(turned[p][i] * 1000.0) / 1000.0, 1e-9);
            EXPECT_TRUE(m.accepted) << m.reason;
        }
    }
    // Part 4's corrections were held while paused: part 5 is the first with new ones.
    EXPECT_EQ(pointCorrections(gcodeFile(4)), held);
    // The loop works against the oversize: part 1 is 0.030 mm large everywhere (the feed-forward takes out
    // the barrel), the corrections of the later parts turn the diameter down at every point.
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(turned[0][i] - kNominalMm, kToolSetMm, 0.0015) << "point " << i;
        EXPECT_LT(parts[4].corrections[i].appliedMm, -0.002) << "point " << i;
        EXPECT_LT(std::fabs(turned[4][i] - kNominalMm), kToolSetMm) << "point " << i;
    }
}

TEST_F(RealLatheTest, StartIsRefusedWithTheReasonWhenAChosenDeviceIsNotReady) {
    MainWindow window(context);
    RunPage& page = openRunPage(window);
    chooseRealLathe(page);

    // The DNC folder is gone (network share down): the output reports it and Start says so.
    ASSERT_TRUE(QDir(dncFolder()).removeRecursively());
    manager.open(outputId);
    ASSERT_EQ(manager.view(outputId)->health.state, core::DeviceState::Error);
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_EQ(prompt.log.size(), 1);
    EXPECT_EQ(prompt.log.front(), QStringLiteral("warn: The run cannot start"));
    EXPECT_EQ(prompt.lastText, QStringLiteral("The CNC output “DNC folder” is in error: the folder %1 does not exist. "
                                              "Check it on the Devices page.")
                                   .arg(dncFolder()));
    EXPECT_TRUE(page.alarms()->item(0)->text().contains(QStringLiteral("Not started: The CNC output")));
    EXPECT_EQ(page.session().snapshot().state, core::LoopState::Idle);
    EXPECT_TRUE(page.findChild<QPushButton*>(QStringLiteral("startButton"))->isEnabled());
    EXPECT_FALSE(manager.latheConnected());
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_real_lathe_refused")));

    // The folder is back, but the gauge's cable is out.
    ASSERT_TRUE(QDir().mkpath(dncFolder()));
    manager.open(outputId);
    pty.unplug();
    ASSERT_TRUE(waitFor([&] { return manager.view(gaugeId)->health.state == core::DeviceState::Error; }));
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_EQ(prompt.log.size(), 2);
    EXPECT_TRUE(prompt.lastText.startsWith(QStringLiteral("The gauge “Micrometer at the lathe” is in error: ")))
        << prompt.lastText.toStdString();
    EXPECT_TRUE(prompt.lastText.endsWith(
        QStringLiteral("Check it on the Devices page, or choose to type the diameters by hand.")));

    // Typed in by hand instead: the run starts with the G-code output alone.
    auto* gauge = page.findChild<QComboBox*>(QStringLiteral("gaugeCombo"));
    gauge->setCurrentIndex(gauge->findData(QString()));
    EXPECT_TRUE(page.findChild<QCheckBox*>(QStringLiteral("manualEntryCheck"))->isChecked());
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page.session().snapshot().partOnMachine == 1; }))
        << core::describe(page.session().snapshot().status);
    EXPECT_EQ(prompt.log.size(), 2);
    EXPECT_TRUE(QFile::exists(gcodeFile(1)));
    EXPECT_TRUE(page.findChild<QLabel*>(QStringLiteral("deviceText"))
                    ->text()
                    .contains(QStringLiteral("Diameters: typed in by hand")));
    page.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page.session().snapshot().state == core::LoopState::Idle; }));
}

TEST_F(RealLatheTest, AGCodeOutputForAnotherDiameterIsRefusedAtStart) {
    manager.updateDevice(outputId, QStringLiteral("DNC folder"),
                         {{QStringLiteral("folder"), dncFolder()}, {QStringLiteral("nominalDiameterMm"), 26.5}});
    manager.open(outputId);
    MainWindow window(context);
    RunPage& page = openRunPage(window);
    chooseRealLathe(page);
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page.alarms()->count() > 0; }));
    const QString alarm = page.alarms()->item(0)->text();
    EXPECT_TRUE(
        alarm.contains(QStringLiteral("the CNC output “DNC folder” writes programs for a diameter of "
                                      "26.500 mm, the set-up paper-2012-group1 turns 27.000 mm")))
        << alarm.toStdString();
    EXPECT_EQ(gcodeFiles(), 0);
    EXPECT_FALSE(manager.latheConnected());
    EXPECT_TRUE(page.findChild<QPushButton*>(QStringLiteral("startButton"))->isEnabled());
}

TEST_F(RealLatheTest, ABusyWindowLosesNoGaugeReadingAndDelaysNoCorrection) {
    // The devices live in their own thread: with the window blocked for 2 s (a busy-wait: the GUI thread
    // processes nothing), the micrometer's five readings of part 1 still reach the loop and the loop still
    // writes part 2's corrections to the CNC during the block.
    MainWindow window(context);
    RunPage& page = openRunPage(window);
    chooseRealLathe(page);
    page.findChild<QSpinBox*>(QStringLiteral("delaySpin"))->setValue(1);
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    const runtime::RunSession& session = page.session();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().partOnMachine == 1; }));
    const std::vector<double> turned = machine(1);
    page.shaft().lathePanel()->finishedButton()->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().awaitingPart == 1; }));
    std::vector<std::vector<std::uint8_t>> frames;  // the DATA button's frames of the five readings
    for (double d : turned) {
        micrometer.setSource([d] { return d; });
        frames.push_back(micrometer.pressDataButton());
    }
    const int before = readingsAccepted();
    const QDateTime blockStart = QDateTime::currentDateTime();
    std::thread operatorHand([&] {
        for (const std::vector<std::uint8_t>& frame : frames) {
            pty.send(frame);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    });
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(2)) {
        // busy: no event of the GUI thread is processed
    }
    const QDateTime blockEnd = QDateTime::currentDateTime();
    operatorHand.join();
    ASSERT_TRUE(QFile::exists(gcodeFile(2))) << "part 2's corrections were written while the window was busy";
    const QDateTime written = QFileInfo(gcodeFile(2)).lastModified();
    EXPECT_GE(written, blockStart.addMSecs(-1000));  // file times may have a coarse resolution
    EXPECT_LE(written, blockEnd) << "written during the block, not after it";
    ASSERT_TRUE(waitFor([&] { return readingsAccepted() == before + 5; }));  // none lost
    ASSERT_TRUE(waitFor([&] { return session.snapshot().partOnMachine == 2; }));
    page.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(waitFor([&] { return session.snapshot().state == core::LoopState::Idle; }));
    const std::vector<core::StoredPart> parts = [&] {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        return storage::SqlHistoryStore(db).parts(1);
    }();
    ASSERT_FALSE(parts.empty());
    ASSERT_TRUE(parts.front().measurement.has_value());
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_NEAR(*parts.front().measurement->points[i].measuredMm, std::round(turned[i] * 1000.0) / 1000.0, 1e-9);
}

}  // namespace
}  // namespace tt::ui
