// The Corner tool of the Process page offscreen (issue 15, item 6): a corner entered or picked is
// simulated without and with the pulse (paths with the zoom on the corner, contour error, the pulse on a
// time axis); the network is trained in a worker thread with its curve, progress and cancel; a run of
// corners whose Z velocity gain drifts by 1.5x shows the drift monitor and retrains; retraining on demand; on
// the soft drives (the other machine) a drift of the cross slide's inertia is found and retrained for.
#include "ui/process/corner_tool.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>

#include "plot/chart.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/pages/process_page.h"
#include "ui/process/corner_move_editor.h"

namespace tt::ui {
namespace {

/// The size a Process tab gets in a 1280 × 800 main window (navigation rail, header, tab bar and
/// status bar taken off).
constexpr int kWidth = 1110;
constexpr int kHeight = 600;

class CornerToolTest : public ::testing::Test {
protected:
    /// Waits for the running job to end (training 40 moves: under a second on one core).
    static bool waitForJob(CornerTool& tool, int timeoutMs = tt::test::kPatientWaitMs) {
        return QTest::qWaitFor([&] { return !tool.busy(); }, timeoutMs);
    }

    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(CornerToolTest, ACornerEnteredOrPickedIsSimulatedWithAndWithoutThePulse) {
    CornerTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    EXPECT_LE(tool.minimumSizeHint().width(), kWidth);
    EXPECT_LE(tool.minimumSizeHint().height(), kHeight);
    // On opening: the example corner with the best pulse found on the simulator (no network yet).
    EXPECT_GT(tool.pathChart()->pointCount(QStringLiteral("programmed")), 50);
    EXPECT_GT(tool.pathChart()->pointCount(QStringLiteral("without")), 50);
    EXPECT_GT(tool.pathChart()->pointCount(QStringLiteral("with")), 50);
    EXPECT_GT(tool.errorChart()->pointCount(QStringLiteral("with")), 50);
    EXPECT_GT(tool.pulseChart()->pointCount(QStringLiteral("pulse")), 50);
    EXPECT_TRUE(tool.summaryLabel()->text().contains(QStringLiteral("no network for this pulse")))
        << tool.summaryLabel()->text().toStdString();
    EXPECT_FALSE(tool.runButton()->isEnabled());  // nothing to run without a network
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_1_paths_best_pulse")));
    // Pick sample corner 3, then enter a speed by hand: the list falls back to "as entered".
    tool.editor()->pickBox()->setCurrentIndex(3);
    const core::CornerMove picked = tool.editor()->move();
    EXPECT_NE(picked.x1RadPerS, 7.0);
    tool.editor()->speedBox(3)->setValue(8.5);
    EXPECT_EQ(tool.editor()->pickBox()->currentIndex(), 0);
    EXPECT_EQ(tool.editor()->move().z2RadPerS, 8.5);
    // Limits: speeds stay in the paper's 0.5 .. 9 rad/s.
    tool.editor()->speedBox(0)->setValue(20.0);
    EXPECT_EQ(tool.editor()->move().x1RadPerS, 9.0);
    tool.zoomBox()->setChecked(false);
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_2_paths_unzoomed")));
}

TEST_F(CornerToolTest, TrainingRunsInAWorkerWithItsCurveAndCanBeCancelled) {
    CornerTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    tool.views()->setCurrentIndex(1);
    tool.trainingMovesBox()->setValue(200);
    QSignalSpy finished(&tool, &CornerTool::jobFinished);
    ASSERT_TRUE(tool.train());
    EXPECT_TRUE(tool.busy());
    EXPECT_FALSE(tool.trainButton()->isEnabled());
    EXPECT_TRUE(tool.cancelButton()->isEnabled());
    EXPECT_FALSE(tool.train());  // one job at a time
    tool.cancelButton()->click();
    ASSERT_TRUE(waitForJob(tool));
    EXPECT_EQ(finished.count(), 1);
    EXPECT_FALSE(tool.network().has_value());  // cancelled: nothing replaced
    EXPECT_TRUE(tool.statusLabel()->text().contains(QStringLiteral("Cancelled")))
        << tool.statusLabel()->text().toStdString();

    tool.trainingMovesBox()->setValue(40);
    tool.trainButton()->click();
    ASSERT_TRUE(tool.busy());
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.network().has_value());
    const core::NetTrainingRecord& r = tool.network()->net.record();
    EXPECT_EQ(tool.trainingChart()->pointCount(QStringLiteral("training")), r.epochs);
    EXPECT_EQ(tool.trainingChart()->pointCount(QStringLiteral("validation")), r.epochs);
    EXPECT_TRUE(tool.networkLabel()->text().contains(QStringLiteral("Network 4-10-1")));
    EXPECT_TRUE(tool.summaryLabel()->text().contains(QStringLiteral("Network's pulse")))
        << tool.summaryLabel()->text().toStdString();
    EXPECT_TRUE(tool.runButton()->isEnabled());
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_3_training_curve")));
    // Another pulse length has no network: the tool falls back to the best pulse for it.
    tool.editor()->durationBox()->setValue(30);
    EXPECT_TRUE(tool.summaryLabel()->text().contains(QStringLiteral("no network for this pulse")));
}

TEST_F(CornerToolTest, ARunWhoseZVelocityGainDriftsShowsTheDriftMonitorAndRetrains) {
    CornerTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    tool.trainingMovesBox()->setValue(60);
    ASSERT_TRUE(tool.train());
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.network().has_value());
    tool.views()->setCurrentIndex(2);
    EXPECT_FALSE(tool.retrainButton()->isEnabled());  // no corners recorded yet
    // The drift: what, on which drive, how much (a velocity gain drift moves the best pulse, DECISIONS).
    ASSERT_EQ(tool.driftKindBox()->count(), 3);
    EXPECT_EQ(tool.driftKindBox()->currentText(), QStringLiteral("Friction"));
    tool.driftKindBox()->setCurrentIndex(1);
    EXPECT_EQ(tool.driftKindBox()->currentText(), QStringLiteral("Velocity gain"));
    EXPECT_EQ(tool.driftAxisBox()->currentText(), QStringLiteral("Z"));
    EXPECT_EQ(tool.driftFactorBox()->minimum(), 0.5);
    EXPECT_EQ(tool.driftFactorBox()->maximum(), 3.0);
    tool.driftFactorBox()->setValue(1.5);
    tool.cornersBox()->setValue(60);
    tool.runButton()->click();
    ASSERT_TRUE(tool.busy());
    EXPECT_FALSE(tool.driftKindBox()->isEnabled());
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.lastRun().has_value());
    const core::CornerWorkResult& run = *tool.lastRun();
    EXPECT_EQ(run.moves.size(), 60u);
    EXPECT_EQ(tool.driftChart()->pointCount(QStringLiteral("difference")), 60);
    EXPECT_EQ(tool.driftChart()->pointCount(QStringLiteral("retrained")) +
                  tool.driftChart()->pointCount(QStringLiteral("refused")),
              static_cast<int>(run.retrains.size()));
    ASSERT_FALSE(run.retrains.empty()) << tool.driftLabel()->text().toStdString();
    EXPECT_GE(run.retrains.front().move, 30);  // the gain changes from the middle corner
    EXPECT_TRUE(run.retrains.front().verdict.accepted) << run.retrains.front().reason;
    EXPECT_TRUE(tool.driftLabel()->text().contains(QStringLiteral("Retrained: validation cost")))
        << tool.driftLabel()->text().toStdString();
    int accepted = 0;
    for (const core::CornerRetrainEvent& e : run.retrains)
        accepted += e.verdict.accepted ? 1 : 0;
    EXPECT_EQ(tool.network()->net.record().retrainings, accepted);  // a refused network never replaced it
    EXPECT_EQ(tool.driftChart()->pointCount(QStringLiteral("retrained")), accepted);
    EXPECT_NEAR(tool.network()->model.z.velocityGain, 1.5, 0.02);  // the controller's model knows it now
    // The Network tab shows the curve of the network in use: the last accepted retraining's.
    EXPECT_EQ(tool.trainingChart()->pointCount(QStringLiteral("training")), tool.network()->net.record().epochs);
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_4_drift_monitor")));
    // Retraining on demand on the corners recorded since: taken or refused, the tool says which.
    ASSERT_TRUE(tool.retrainButton()->isEnabled());
    const int before = tool.network()->net.record().retrainings;
    tool.retrainButton()->click();
    ASSERT_TRUE(waitForJob(tool));
    const QString status = tool.statusLabel()->text();
    if (tool.network()->net.record().retrainings == before + 1)
        EXPECT_TRUE(status.contains(QStringLiteral("Retrained on demand"))) << status.toStdString();
    else
        EXPECT_TRUE(status.contains(QStringLiteral("Retraining on demand refused"))) << status.toStdString();
    EXPECT_LE(tool.network()->net.record().retrainings, before + 1);
}

TEST_F(CornerToolTest, OnTheSoftDrivesAnInertiaDriftOfTheCrossSlideIsFoundAndRetrainedFor) {
    CornerTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    ASSERT_EQ(tool.machineBox()->count(), 2);
    EXPECT_EQ(tool.machineBox()->currentData().toString(), QStringLiteral("1v340-feed-drives"));
    tool.trainingMovesBox()->setValue(40);
    ASSERT_TRUE(tool.train());
    EXPECT_FALSE(tool.machineBox()->isEnabled());  // not while a job runs
    EXPECT_FALSE(tool.setMachine(QStringLiteral("1v340-soft-drives")));
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.network().has_value());
    // The network belongs to the machine it was trained on: another machine starts without one.
    EXPECT_FALSE(tool.setMachine(QStringLiteral("no-such-machine")));
    EXPECT_TRUE(tool.network().has_value());
    tool.machineBox()->setCurrentIndex(1);
    emit tool.machineBox()->activated(1);
    EXPECT_FALSE(tool.network().has_value());
    EXPECT_EQ(tool.trainingChart()->pointCount(QStringLiteral("training")), 0);
    EXPECT_EQ(tool.machineBox()->currentData().toString(), QStringLiteral("1v340-soft-drives"));
    tool.trainingMovesBox()->setValue(100);
    ASSERT_TRUE(tool.train());
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.network().has_value());
    EXPECT_EQ(tool.network()->pulse.leadS, 0.06);  // the soft drives' pulse
    // 1.5x the cross slide's inertia from the middle corner: found, and the network retrained for it.
    tool.views()->setCurrentIndex(2);
    tool.driftKindBox()->setCurrentIndex(2);
    EXPECT_EQ(tool.driftKindBox()->currentText(), QStringLiteral("Inertia"));
    tool.driftAxisBox()->setCurrentIndex(tool.driftAxisBox()->findData(QStringLiteral("x")));
    tool.driftFactorBox()->setValue(1.5);
    tool.cornersBox()->setValue(100);
    tool.runButton()->click();
    ASSERT_TRUE(waitForJob(tool));
    ASSERT_TRUE(tool.lastRun().has_value());
    const core::CornerWorkResult& run = *tool.lastRun();
    ASSERT_FALSE(run.retrains.empty()) << tool.driftLabel()->text().toStdString();
    EXPECT_GE(run.retrains.front().move, 50) << run.retrains.front().reason;  // nothing before the drift
    // The first identification finds the drift (measured 1.509); the later ones, from 10 corners each with
    // the machine's 5 % friction scatter, scatter around it (1.735, 1.565).
    EXPECT_NEAR(run.retrains.front().identified.factors.x.inertia, 1.5, 0.05);
    EXPECT_NEAR(tool.network()->model.x.inertia, 1.5, 0.1) << tool.driftLabel()->text().toStdString();
    EXPECT_GE(tool.network()->net.record().retrainings, 1);
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_5_soft_drives_inertia")));
    // In Russian the machine's name fits beside the tabs.
    LanguageSwitcher language;
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    tool.retranslate();
    EXPECT_EQ(tool.machineBox()->currentText(), QStringLiteral("Мягкие приводы"));
    EXPECT_EQ(tool.statusLabel()->text(), QStringLiteral("Прогон закончен."));  // the last job's outcome too
    EXPECT_LE(tool.minimumSizeHint().width(), kWidth);
    const QTabBar* tabs = tool.views()->findChild<QTabBar*>();
    ASSERT_NE(tabs, nullptr);
    EXPECT_LE(tabs->sizeHint().width(), tabs->width());  // every tab whole, no scroll buttons
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("corner_5_soft_drives_inertia_ru")));
    ASSERT_TRUE(language.apply(QStringLiteral("en")));
}

TEST_F(CornerToolTest, IsATabOfTheProcessPage) {
    ProcessPage page(context);
    page.resize(kWidth, kHeight + 50);
    page.show();
    ProcessTool* tool = page.tool(QStringLiteral("corner"));
    ASSERT_NE(tool, nullptr);
    EXPECT_EQ(tool->title(), QStringLiteral("Corner pulse"));
    page.tabs()->setCurrentWidget(tool);
    EXPECT_TRUE(tool->isVisible());
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("corner_5_process_page")));
}

}  // namespace
}  // namespace tt::ui
