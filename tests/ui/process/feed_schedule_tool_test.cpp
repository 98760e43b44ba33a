// The Feed schedule tab of the Process page offscreen (paper 004): the model from the simulator's
// experiments with its statistics, the family of curves with Yc and the staircase of feeds, Yc dragged
// and the schedule and the time saved following it, the check on the simulator, the program with line
// numbers saved to a file, a model loaded from a file and a CSV fitted, refusals shown in words, the
// long work cancelled. Screenshots: screenshots/feed_schedule_*.png.
#include "ui/process/feed_schedule_tool.h"

#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QJsonDocument>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>

#include "config/deformation_csv.h"
#include "config/preset_library.h"
#include "core/sim/shaft/deformation_experiment.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "plot/chart.h"
#include "ui/process/deformation_model_panel.h"
#include "ui/process/feed_model_task.h"
#include "ui/process/gcode_view.h"

namespace tt::ui {
namespace {

/// The size a Process page tab gets in a 1280 x 800 main window (navigation rail, header, tab bar and
/// status bar taken off).
constexpr int kWidth = 1110;
constexpr int kHeight = 640;

/// Runs the event loop until `spy` has seen its signal, with no wall-clock limit of its own: on a loaded
/// machine the worker takes what it takes, and a task that never ends is stopped by CTest's timeout.
void waitFor(QSignalSpy& spy) {
    while (spy.count() == 0)
        spy.wait(1000);
}

class FeedScheduleToolTest : public ::testing::Test {
protected:
    /// Waits for the task the tool started in its constructor (the built-in set-up's experiments): its
    /// end is reported through the event loop, which has not run since.
    static void waitForTask(FeedScheduleTool& tool) {
        QSignalSpy done(&tool, &FeedScheduleTool::taskFinished);
        waitFor(done);
    }
    /// Starts a task with `start` and waits for its end (however fast the worker is).
    template <typename Start>
    static void runTask(FeedScheduleTool& tool, Start start) {
        QSignalSpy done(&tool, &FeedScheduleTool::taskFinished);
        start();
        waitFor(done);
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(FeedScheduleToolTest, ShowsTheModelTheCurvesTheStaircaseAndTheProgram) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    EXPECT_TRUE(tool.busy());  // the built-in set-up's experiments start at once, in the worker
    test::saveScreenshot(tool, QStringLiteral("feed_schedule_0_starting"));  // progress bar, if still running
    waitForTask(tool);
    ASSERT_TRUE(tool.model().has_value()) << tool.problem().toStdString();
    ASSERT_TRUE(tool.schedule().has_value()) << tool.problem().toStdString();
    // The preset's model: 1216 measurements, stepwise cubic-z (tests/core/model: R² about 0.998).
    EXPECT_EQ(tool.model()->statistics.pointCount, 1216);
    EXPECT_GT(tool.model()->statistics.r2, 0.99);
    // Four curves Y(z) for fmin .. fmax, the Yc line, the scheduled Y; the staircase has two points per segment.
    for (int k = 0; k < 4; ++k)
        EXPECT_GT(tool.curvesChart()->pointCount(QStringLiteral("family%1").arg(k)), 10) << k;
    EXPECT_EQ(tool.curvesChart()->pointCount(QStringLiteral("level")), 2);
    EXPECT_GT(tool.curvesChart()->pointCount(QStringLiteral("scheduled")), 10);
    EXPECT_EQ(tool.feedChart()->pointCount(QStringLiteral("feed")),
              2 * static_cast<int>(tool.schedule()->segments.size()));
    // The program of the schedule: Fanuc-style first, one G1 per segment plus the approach.
    const QString program = tool.programText();
    EXPECT_TRUE(program.startsWith(QStringLiteral("%\nO4004"))) << program.left(80).toStdString();
    EXPECT_EQ(program.count(QStringLiteral("\nG1 Z")), static_cast<int>(tool.schedule()->segments.size()) + 1);
    EXPECT_EQ(tool.programView()->toPlainText(), program);
    EXPECT_GT(tool.programView()->numberAreaWidth(), 20);
    // Times: the schedule against constant fmin (preset: about 61 % saved).
    ASSERT_TRUE(tool.times().has_value());
    EXPECT_GT(tool.times()->savedVsFeedMinPct(), 30.0);
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("saved")))
        << tool.resultLabel()->text().toStdString();
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_1_curves")));

    tool.views()->setCurrentIndex(1);
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_2_program")));
    tool.views()->setCurrentIndex(2);
    EXPECT_EQ(tool.modelPanel()->table()->rowCount(), tool.model()->statistics.termCount);
    EXPECT_TRUE(tool.modelPanel()->summary()->text().contains(QStringLiteral("F(0.95;")));
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_3_statistics")));
    tool.views()->setCurrentIndex(0);

    tool.dialectBox()->setCurrentIndex(1);  // LinuxCNC
    EXPECT_TRUE(tool.programText().contains(QStringLiteral("G18 G21 G40 G90 G95 G7")));
    EXPECT_FALSE(tool.programText().contains(QStringLiteral("O4004 (")));
}

TEST_F(FeedScheduleToolTest, DraggingYcMovesTheScheduleAndTheTimeSaved) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    ASSERT_TRUE(tool.schedule().has_value());
    const double y1 = tool.schedule()->y1Um;
    const double y2 = tool.schedule()->y2Um;
    tool.setLevelFraction(0.0);  // Yc = Y1: quality, the slowest schedule
    ASSERT_TRUE(tool.schedule().has_value());
    EXPECT_NEAR(tool.schedule()->levelUm, y1, 1e-9);
    const double slow = tool.times()->scheduleS;
    const QString slowText = tool.resultLabel()->text();
    // Dragging the slider (what the operator does) to Y2: productivity.
    tool.levelSlider()->setSliderPosition(tool.levelSlider()->maximum());
    ASSERT_TRUE(tool.schedule().has_value());
    EXPECT_NEAR(tool.schedule()->levelUm, y2, 1e-9);
    EXPECT_LT(tool.times()->scheduleS, slow);
    EXPECT_NE(tool.resultLabel()->text(), slowText);
    EXPECT_EQ(tool.curvesChart()->pointCount(QStringLiteral("level")), 2);
    tool.setLevelFraction(0.3);
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_4_level_dragged")));
}

TEST_F(FeedScheduleToolTest, ChecksOnTheSimulatorAndSavesTheProgram) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    runTask(tool, [&] { tool.checkOnSimulator(); });
    ASSERT_TRUE(tool.check().has_value()) << tool.resultLabel()->text().toStdString();
    EXPECT_LT(tool.check()->maxDeviationPct, 10.0);  // paper 004 on the simulator (tests/core: about 5 %)
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("Simulator")));
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_5_checked")));
    // A new level makes the check stale: it is cleared, not shown for another schedule.
    tool.setLevelFraction(0.8);
    EXPECT_FALSE(tool.check().has_value());

    const QString file = dir.filePath(QStringLiteral("O4004.nc"));
    prompt.fileNames.push_back(file);
    ASSERT_TRUE(tool.saveProgram());
    QFile saved(file);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_EQ(QString::fromLatin1(saved.readAll()), tool.programText());
    EXPECT_TRUE(prompt.log.contains(QStringLiteral("save: Save the CNC program")));
    EXPECT_FALSE(tool.saveProgram());  // no file name given: nothing written
}

TEST_F(FeedScheduleToolTest, ShowsWhyARequestCannotBeScheduled) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    // A depth of 0.5 mm with the preset's pass: Y1 > Y2 is impossible here, but a feed step larger than the
    // whole range still works; a minimum length beyond the pass leaves one segment.
    tool.minLengthBox()->setValue(400.0);
    ASSERT_TRUE(tool.schedule().has_value());
    EXPECT_EQ(tool.schedule()->segments.size(), 1U);
    tool.minLengthBox()->setValue(5.0);
    // z_start = z_end: refused in words, no program to save.
    auto* zEnd = tool.findChildren<QDoubleSpinBox*>().at(5);
    zEnd->setValue(380.0);
    EXPECT_FALSE(tool.schedule().has_value());
    EXPECT_TRUE(tool.problem().contains(QStringLiteral("z_start and z_end are both 380 mm")))
        << tool.problem().toStdString();
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("380 mm")));
    EXPECT_TRUE(tool.programText().isEmpty());
    EXPECT_FALSE(tool.saveProgram());
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_6_refused")));
}

TEST_F(FeedScheduleToolTest, LoadsAModelFileAndFitsACsv) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    ASSERT_TRUE(tool.model().has_value());
    // The model written as fit-deformation writes it, loaded back.
    const QString modelFile = dir.filePath(QStringLiteral("model.json"));
    {
        QFile out(modelFile);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(config::deformationModelToJson(*tool.model())).toJson());
    }
    const double level = tool.schedule()->levelUm;
    prompt.fileNames.push_back(modelFile);
    tool.loadModelFile();
    ASSERT_TRUE(tool.schedule().has_value());
    EXPECT_NEAR(tool.schedule()->levelUm, level, 1e-9);
    // A file that is no model: a warning in words, the model kept.
    const QString wrong = dir.filePath(QStringLiteral("wrong.json"));
    {
        QFile out(wrong);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("{\"kind\": \"profile\"}");
    }
    prompt.fileNames.push_back(wrong);
    tool.loadModelFile();
    EXPECT_TRUE(prompt.log.contains(QStringLiteral("warn: Model file")));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("not a force-deformation model file")));
    EXPECT_TRUE(tool.model().has_value());

    // A measured CSV (here the simulator's, every second bar) fitted with the quadratic terms.
    const config::FeedSchedulingSetup setup =
        config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(QStringLiteral("feed-scheduling")));
    config::DeformationCsv csv;
    core::DeformationExperimentPlan plan = setup.experiment;
    plan.feedsMmPerRev = {0.05, 0.15, 0.25, 0.4};
    csv.samples = core::runDeformationExperiment(setup.lathe, plan);
    csv.preset = QStringLiteral("feed-scheduling");
    const QString csvFile = dir.filePath(QStringLiteral("measured.csv"));
    {
        QFile out(csvFile);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(config::deformationCsvText(csv));
    }
    tool.modelPanel()->termSetBox()->setCurrentIndex(1);  // full quadratic
    prompt.fileNames.push_back(csvFile);
    runTask(tool, [&] { tool.fitCsvFile(); });
    ASSERT_TRUE(tool.model().has_value());
    EXPECT_EQ(tool.model()->statistics.pointCount, 4 * 4 * 38);
    EXPECT_EQ(tool.model()->statistics.termSet, "quadratic");
    EXPECT_EQ(tool.model()->sourceFile, QStringLiteral("measured.csv"));
    EXPECT_TRUE(tool.model()->job.has_value());  // the '# preset:' line names the set-up and its job
}

TEST_F(FeedScheduleToolTest, RefinesTheModelWhenTheCheckMisses) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    // a = 0.5 mm at Y1: a level of about 6.5 µm, next to the model's error of about 1.2 µm there.
    tool.depthBox()->setValue(0.5);
    tool.setLevelFraction(0.0);
    EXPECT_FALSE(tool.refineButton()->isEnabled());  // nothing checked yet
    runTask(tool, [&] { tool.checkOnSimulator(); });
    ASSERT_TRUE(tool.check().has_value());
    ASSERT_GT(tool.check()->maxDeviationPct, 10.0) << "the model alone held the band: nothing to refine";
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("outside ±10 %")))
        << tool.resultLabel()->text().toStdString();
    EXPECT_TRUE(tool.refineButton()->isEnabled());
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_7_missed")));
    const double missed = tool.check()->maxDeviationPct;

    runTask(tool, [&] { tool.refineModel(); });
    ASSERT_TRUE(tool.refinement().has_value()) << tool.resultLabel()->text().toStdString();
    ASSERT_TRUE(tool.check().has_value());
    EXPECT_LE(tool.check()->maxDeviationPct, 10.0);
    EXPECT_NEAR(tool.refinement()->initialCheck.maxDeviationPct, missed, 1e-9);
    EXPECT_GE(tool.refinement()->barCount(), 1);
    ASSERT_NE(tool.activeModel(), nullptr);
    EXPECT_NE(tool.activeModel(), &*tool.model());  // the schedule rests on the refined model now
    EXPECT_EQ(tool.activeModel()->statistics.termSet, "cubic-fz");
    EXPECT_FALSE(tool.refineButton()->isEnabled());
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("Refined in")))
        << tool.resultLabel()->text().toStdString();
    EXPECT_TRUE(tool.programText().contains(QStringLiteral("CUBIC-FZ")));  // the program names its model
    EXPECT_TRUE(test::saveScreenshot(tool, QStringLiteral("feed_schedule_8_refined")));
    // Another depth is outside the refined model: the fitted model takes over; back at 0.5 mm the refined one.
    tool.depthBox()->setValue(1.5);
    EXPECT_EQ(tool.activeModel(), &*tool.model());
    tool.depthBox()->setValue(0.5);
    EXPECT_NE(tool.activeModel(), &*tool.model());
}

TEST_F(FeedScheduleToolTest, ARefinementCanBeCancelled) {
    FeedScheduleTool tool(context);
    tool.resize(kWidth, kHeight);
    tool.show();
    waitForTask(tool);
    tool.depthBox()->setValue(0.5);
    tool.setLevelFraction(0.0);
    runTask(tool, [&] { tool.checkOnSimulator(); });
    ASSERT_TRUE(tool.refineButton()->isEnabled());
    QSignalSpy done(&tool, &FeedScheduleTool::taskFinished);
    tool.refineModel();
    EXPECT_TRUE(tool.busy());
    EXPECT_FALSE(tool.refineButton()->isEnabled());
    tool.findChild<QPushButton*>(QStringLiteral("feedCancel"))->click();
    waitFor(done);
    EXPECT_FALSE(tool.refinement().has_value());
    EXPECT_TRUE(tool.resultLabel()->text().contains(QStringLiteral("Stopped.")));
    EXPECT_EQ(tool.activeModel(), &*tool.model());
}

TEST(FeedModelTask, CancelStopsTheExperiments) {
    // A large grid (2500 bars) so the task is certainly still running when it is cancelled.
    config::FeedSchedulingSetup setup =
        config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(QStringLiteral("feed-scheduling")));
    setup.experiment.depthsMm.clear();
    setup.experiment.feedsMmPerRev.clear();
    for (int i = 0; i < 50; ++i) {
        setup.experiment.depthsMm.push_back(0.5 + 0.03 * i);
        setup.experiment.feedsMmPerRev.push_back(0.05 + 0.007 * i);
    }
    FeedModelTask task;
    QSignalSpy finished(&task, &FeedModelTask::finished);
    task.simulateAndFit(setup, QStringLiteral("feed-scheduling"), core::DeformationTermSet::Quadratic, false);
    EXPECT_TRUE(task.busy());
    task.cancel();
    waitFor(finished);
    EXPECT_TRUE(finished.at(0).at(1).toBool());  // reported as cancelled
    EXPECT_FALSE(task.busy());
}

}  // namespace
}  // namespace tt::ui
