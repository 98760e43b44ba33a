// The Hydraulic feed tab of the Process page (issue 16, item 5), offscreen in the 1280 x 800 main window:
// the block diagram with editable parameters, the curves with and without the regulator, the xi sweep as
// a family of curves with its table, the stability boundary of the chip loop, export of PNG and CSV, cancel.
// Screenshots: screenshots/hydraulic_feed_*.png.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QJsonObject>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "config/hydraulic_feed_config.h"
#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/process_page.h"
#include "plot/chart.h"
#include "ui/process/feed_block_diagram.h"
#include "ui/process/feed_chart_tabs.h"
#include "ui/process/feed_parameter_form.h"
#include "ui/process/hydraulic_feed_tool.h"

namespace tt::ui {
namespace {

class HydraulicFeedToolTest : public ::testing::Test {
protected:
    void SetUp() override {
        context = AppContext{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
        window = std::make_unique<MainWindow>(context);
        window->resize(1280, 800);
        window->show();
        window->showPage(PageId::Process);
        auto* page = dynamic_cast<ProcessPage*>(window->page(PageId::Process));
        ASSERT_NE(page, nullptr);
        tool = dynamic_cast<HydraulicFeedTool*>(page->tool(QStringLiteral("hydraulic-feed")));
        ASSERT_NE(tool, nullptr);
        page->tabs()->setCurrentWidget(tool);
        QApplication::processEvents();
    }

    /// Waits for the worker thread's job (the GUI stays responsive meanwhile).
    void waitIdle() {
        ASSERT_TRUE(QTest::qWaitFor([&] { return !tool->busy(); }, tt::test::kPatientWaitMs));
    }

    void click(const char* name) {
        auto* button = tool->findChild<QPushButton*>(QLatin1String(name));
        ASSERT_NE(button, nullptr) << name;
        ASSERT_TRUE(button->isEnabled()) << name;
        QTest::mouseClick(button, Qt::LeftButton);
    }

    QDoubleSpinBox* field(const char* key) { return tool->form()->field(QLatin1String(key)); }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context;
    std::unique_ptr<MainWindow> window;
    HydraulicFeedTool* tool = nullptr;
};

// The parameters in the core struct are the preset's (the core tests use the struct's defaults).
TEST(HydraulicFeedPreset, EngineDefaultsAreThePresetHydraulicFeed) {
    const core::FeedScenario s = config::loadHydraulicFeedScenario(QStringLiteral("hydraulic-feed"));
    const core::HydraulicFeedParams defaults;
    for (const core::FeedParameterInfo& info : core::feedParameters())
        EXPECT_EQ(s.params.*(info.member), defaults.*(info.member)) << info.key;
    EXPECT_EQ(s.finalLoadN(), 3.23);
    EXPECT_EQ(s.load.lastEventS(), 0.02);
    const core::FeedScenario chip = config::loadHydraulicFeedScenario(QStringLiteral("hydraulic-feed-chip"));
    EXPECT_EQ(chip.params.feedExponent, 0.6);
    EXPECT_EQ(chip.run.durationS, 2.0);
    EXPECT_THROW(config::hydraulicFeedScenarioFromPreset(
                     QJsonObject{{QStringLiteral("spool"), QJsonObject{{QStringLiteral("damping_ratio"), 20}}}}),
                 std::invalid_argument);
}

TEST_F(HydraulicFeedToolTest, SimulatesThePaperLoadWithAndWithoutTheRegulator) {
    // Fits the page at 1280 x 800: nothing cut off.
    EXPECT_LE(tool->minimumSizeHint().width(), tool->width());
    EXPECT_LE(tool->minimumSizeHint().height(), tool->height());
    // The preset's values with their units.
    EXPECT_DOUBLE_EQ(field("cylinder.piston_diameter_m")->value(), 150.0);
    EXPECT_EQ(field("cylinder.piston_diameter_m")->suffix(), QStringLiteral(" mm"));
    EXPECT_DOUBLE_EQ(field("spool.damping_ratio")->value(), 1.2);
    EXPECT_DOUBLE_EQ(field("amplifier.gain")->value(), 137.6);
    // The paper's regulator: the feed-forward of the measured force.
    auto* regulator = tool->findChild<QComboBox*>(QStringLiteral("feedRegulator"));
    ASSERT_NE(regulator, nullptr);
    EXPECT_EQ(tool->regulator(), core::FeedRegulator::Feedback);  // the default
    regulator->setCurrentIndex(regulator->findData(static_cast<int>(core::FeedRegulator::FeedForward)));
    click("feedSimulate");
    EXPECT_TRUE(tool->busy());
    waitIdle();
    EXPECT_TRUE(
        tool->summary().contains(QStringLiteral("Steady feed 1.0000 mm/s with the feed-forward, 0.2822 mm/s without")))
        << tool->summary().toStdString();
    EXPECT_TRUE(tool->summary().contains(QStringLiteral("No gain destabilises the chain")));
    EXPECT_EQ(tool->charts()->feedChart()->pointCount(QStringLiteral("with")), 801);
    EXPECT_EQ(tool->charts()->feedChart()->pointCount(QStringLiteral("without")), 801);
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_simulated")));

    // A block of the diagram chosen with the mouse shows its parameters.
    FeedBlockDiagram* diagram = tool->diagram();
    QTest::mouseClick(diagram, Qt::LeftButton, {}, diagram->blockRect(FeedBlock::Magnet).center().toPoint());
    EXPECT_EQ(diagram->selected(), FeedBlock::Magnet);
    EXPECT_TRUE(field("magnet.resistance_ohm")->isVisible());
    EXPECT_FALSE(field("spool.damping_ratio")->isVisible());
    tool->charts()->setCurrentIndex(FeedChartTabs::RegulatorTab);
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_regulator")));
}

// The feedback of the feed (the default): its margins in the summary (scipy's figures for the same loop:
// gain margin 4.714 = 13.47 dB at 550.5 rad/s, phase margin 50.0 deg at 182.4 rad/s), and at 6 N, where the
// paper's feed-forward ends at +114 %, the set feed held without a warning.
TEST_F(HydraulicFeedToolTest, FeedbackShowsItsMarginsAndHoldsOffTheDesignLoad) {
    tool->findChild<QDoubleSpinBox*>(QStringLiteral("feedLoad"))->setValue(6.0);
    click("feedSimulate");
    waitIdle();
    EXPECT_TRUE(tool->summary().contains(QStringLiteral("Steady feed 1.0000 mm/s with the feedback")))
        << tool->summary().toStdString();
    EXPECT_TRUE(tool->summary().contains(
        QStringLiteral("Margins of the feedback loop: gain 4.71 (13.5 dB) at 550 rad/s, phase 50° at 182 rad/s; "
                       "closed loop stable.")))
        << tool->summary().toStdString();
    EXPECT_TRUE(tool->status().isEmpty()) << tool->status().toStdString();
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_feedback_6n")));
    // The feed-forward at the same load: off by 114 %, in red.
    tool->setRegulator(core::FeedRegulator::FeedForward);
    click("feedSimulate");
    waitIdle();
    EXPECT_TRUE(tool->status().contains(QStringLiteral("The feed ends 114.4 % off the set feed")))
        << tool->status().toStdString();
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_feedforward_6n")));
    // The gain sweep of the feedback: factors on K_p, unstable beyond the gain margin.
    tool->setRegulator(core::FeedRegulator::Feedback);
    click("feedSweepGain");
    waitIdle();
    QTableWidget* table = tool->charts()->sweepTable();
    ASSERT_EQ(table->rowCount(), 8);
    EXPECT_EQ(table->item(7, 0)->text(), QStringLiteral("6"));
    EXPECT_EQ(table->item(7, 5)->text(), QStringLiteral("no: unstable"));
    EXPECT_EQ(table->item(6, 5)->text(), QStringLiteral("yes"));
}

TEST_F(HydraulicFeedToolTest, XiSweepAsAFamilyOfCurvesWithItsTableAndExports) {
    tool->setRegulator(core::FeedRegulator::FeedForward);
    click("feedSweepXi");
    waitIdle();
    QTableWidget* table = tool->charts()->sweepTable();
    ASSERT_EQ(table->rowCount(), 8);
    EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("0.2"));
    EXPECT_EQ(tool->charts()->currentIndex(), FeedChartTabs::SweepTab);
    for (int k = 0; k < 8; ++k)
        EXPECT_EQ(tool->charts()->sweepChart()->pointCount(QStringLiteral("member%1").arg(k)), 801) << k;
    EXPECT_TRUE(tool->summary().contains(QStringLiteral("The spool swings past its final opening in 4 of them")))
        << tool->summary().toStdString();
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_sweep_xi")));
    tool->charts()->setCurrentIndex(FeedChartTabs::SweepTableTab);
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_sweep_table")));

    const QString png = dir.filePath(QStringLiteral("sweep.png"));
    const QString csv = dir.filePath(QStringLiteral("sweep.csv"));
    prompt.fileNames = {png, csv};
    EXPECT_TRUE(tool->exportPng());
    EXPECT_TRUE(tool->exportCsv());
    EXPECT_GT(QFile(png).size(), 10000);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray header = file.readLine();
    EXPECT_TRUE(header.startsWith("time_s,load_n,feed_m_s[xi=0.2]")) << header.toStdString();
    EXPECT_TRUE(header.contains("feed_m_s[xi=2]"));
    EXPECT_EQ(prompt.log,
              (QStringList{QStringLiteral("save: Export the chart"), QStringLiteral("save: Export the curves")}));
}

// The preset hydraulic-feed-chip's loop (y = 0.6): the summary gives the boundary, confirmed by simulation.
TEST_F(HydraulicFeedToolTest, ChipLoopShowsTheStabilityBoundary) {
    tool->setRegulator(core::FeedRegulator::FeedForward);
    QTest::mouseClick(tool->diagram(), Qt::LeftButton, {},
                      tool->diagram()->blockRect(FeedBlock::Sensor).center().toPoint());
    field("sensor.feed_exponent")->setValue(0.6);
    tool->findChild<QDoubleSpinBox*>(QStringLiteral("feedDuration"))->setValue(2.0);
    click("feedSimulate");
    waitIdle();
    EXPECT_TRUE(
        tool->summary().contains(QStringLiteral("Stability boundary: K_a = 140.65 (1.022 × the design gain 137.6)")))
        << tool->summary().toStdString();
    EXPECT_TRUE(tool->summary().contains(QStringLiteral("confirmed")));
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_chip_loop")));
    // The designer's remedy: a bias with the matching lap, then the gain designed for the load.
    QTest::mouseClick(tool->diagram(), Qt::LeftButton, {},
                      tool->diagram()->blockRect(FeedBlock::Amplifier).center().toPoint());
    field("amplifier.bias_v")->setValue(5.0);
    click("feedDesign");
    EXPECT_NEAR(field("amplifier.gain")->value(), 52.31, 0.01);
    EXPECT_GT(field("spool.lap_m")->value(), 0.1);
    click("feedSimulate");
    waitIdle();
    EXPECT_TRUE(tool->summary().contains(QStringLiteral("No gain destabilises the chain")))
        << tool->summary().toStdString();
}

// In Russian, with results on every tab (the i18n test sees the tab before any run).
TEST_F(HydraulicFeedToolTest, RussianWithResults) {
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QApplication::processEvents();
    EXPECT_EQ(tool->title(), QStringLiteral("Гидроподача"));
    click("feedSimulate");
    waitIdle();
    EXPECT_TRUE(tool->summary().startsWith(QStringLiteral("Установившаяся подача 1.0000 мм/с")))
        << tool->summary().toStdString();
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_simulated_ru")));
    click("feedSweepGain");
    waitIdle();
    tool->charts()->setCurrentIndex(FeedChartTabs::SweepTableTab);
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_sweep_gain_table_ru")));
    tool->charts()->setCurrentIndex(FeedChartTabs::SweepTab);
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("hydraulic_feed_sweep_gain_ru")));
    EXPECT_LE(window->minimumSizeHint().height(), 800);
    EXPECT_LE(window->minimumSizeHint().width(), 1280);
    ASSERT_TRUE(language.apply(QStringLiteral("en")));
}

TEST_F(HydraulicFeedToolTest, RefusesALoadStepAfterTheEndAndCancels) {
    tool->findChild<QDoubleSpinBox*>(QStringLiteral("feedStepTime"))->setValue(1.0);
    EXPECT_FALSE(tool->simulate());
    EXPECT_TRUE(tool->status().contains(QStringLiteral("comes after the end of the simulation")));
    tool->findChild<QDoubleSpinBox*>(QStringLiteral("feedStepTime"))->setValue(0.02);
    tool->findChild<QDoubleSpinBox*>(QStringLiteral("feedDuration"))->setValue(60.0);
    ASSERT_TRUE(tool->sweep(core::FeedSweepKind::DampingRatio));
    EXPECT_FALSE(tool->simulate());  // one job at a time
    auto* cancel = tool->findChild<QPushButton*>(QStringLiteral("feedCancel"));
    EXPECT_TRUE(cancel->isEnabled());
    QTest::mouseClick(cancel, Qt::LeftButton);
    waitIdle();
    EXPECT_TRUE(tool->status().startsWith(QStringLiteral("Cancelled"))) << tool->status().toStdString();
    EXPECT_FALSE(cancel->isEnabled());
    EXPECT_EQ(tool->charts()->sweepTable()->rowCount(), 0);
}

}  // namespace
}  // namespace tt::ui
