// The Run page on the built-in simulator, offscreen: the loop runs in its own thread, the plots fill,
// diameters are typed in by hand (one refused as out of range), and everything lands in the history.
#include "ui/pages/run_page.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>
#include <functional>

#include "core/storage/database.h"
#include "plot/chart.h"
#include "run_window.h"
#include "runtime/devices/device_hub.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/run/manual_entry_panel.h"
#include "ui/run/profile_panel.h"

namespace tt::ui {
namespace {

using test::waitFor;

using test::typeAndEnter;

class RunPageTest : public test::RunWindowTest {};

TEST_F(RunPageTest, RunsTheLoopPlotsThePartsAndTakesDiametersByHand) {
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_idle")));
    EXPECT_NE(page->session().loopThread(), QThread::currentThread()) << "the loop has its own thread";

    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);  // x3600
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page->session().snapshot().partsFinished >= 10; }, tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    EXPECT_EQ(state.loop(), AppState::Loop::Running);
    EXPECT_TRUE(waitFor([&] { return page->profilePanel()->historyParts() >= 8; }, tt::test::kPatientWaitMs));

    // The plot has the data: measured points, the line between them, the simulated part, the model,
    // the correction path, the tolerance band; the history strip one series per control point.
    plot::Chart* profile = page->profilePanel()->profileChart();
    EXPECT_EQ(profile->pointCount(QStringLiteral("measured")), 5);
    EXPECT_GT(profile->pointCount(QStringLiteral("interpolated")), 100);
    EXPECT_GT(profile->pointCount(QStringLiteral("true")), 100);
    EXPECT_GT(profile->pointCount(QStringLiteral("model")), 100);
    EXPECT_GT(profile->pointCount(QStringLiteral("path")), 600);
    EXPECT_EQ(profile->pointCount(QStringLiteral("tolerance")), 2);
    for (int i = 0; i < 5; ++i)
        EXPECT_GE(page->profilePanel()->historyChart()->pointCount(QStringLiteral("point%1").arg(i)), 8);
    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(2);  // x360 for the look
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_running")));

    // By hand: the simulated gauge stops; the part due waits for the operator.
    window.findChild<QCheckBox*>(QStringLiteral("manualEntryCheck"))->setChecked(true);
    ManualEntryPanel* manual = page->manualEntry();
    ASSERT_TRUE(
        waitFor([&] { return page->session().snapshot().manualEntry && page->session().snapshot().awaitingPart; },
                tt::test::kPatientWaitMs));
    const qint64 part = *page->session().snapshot().awaitingPart;
    ASSERT_EQ(manual->fieldCount(), 5);
    const qint64 finishedBefore = page->session().snapshot().partsFinished;

    typeAndEnter(manual->field(0), QStringLiteral("27.012"));
    EXPECT_TRUE(manual->field(1)->hasFocus()) << "Enter moves to the next point";
    typeAndEnter(manual->field(1), QStringLiteral("2.7015"));  // a slipped decimal point
    EXPECT_TRUE(manual->field(1)->hasFocus()) << "a refused value keeps the point open";
    EXPECT_TRUE(manual->field(1)->property("invalid").toBool());
    EXPECT_TRUE(manual->message(1).contains(QStringLiteral("from the nominal 27.000 mm")))
        << manual->message(1).toStdString();
    ASSERT_GT(page->alarms()->count(), 0);
    EXPECT_TRUE(page->alarms()->item(0)->text().contains(QStringLiteral("Point 2")));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_manual_rejected")));

    typeAndEnter(manual->field(1), QStringLiteral("27,015"));  // a comma is fine
    EXPECT_FALSE(manual->field(1)->property("invalid").toBool());
    typeAndEnter(manual->field(2), QStringLiteral("27.021"));
    typeAndEnter(manual->field(3), QStringLiteral("27.009"));
    typeAndEnter(manual->field(4), QStringLiteral("26.998"));
    EXPECT_TRUE(manual->field(0)->text().isEmpty()) << "sent: the fields are ready for the next part";

    // The loop takes the diameters, stores them and goes on with the next part.
    ASSERT_TRUE(waitFor([&] { return page->session().snapshot().partsFinished > finishedBefore + 1; },
                        tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_manual_done")));

    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    QSqlQuery q =
        db.exec(QStringLiteral("SELECT m.point_index, m.measured_mm, m.accepted FROM measurements m"
                               " JOIN parts p ON p.id = m.part_id WHERE p.part_number = ? ORDER BY m.point_index"),
                {part});
    std::vector<double> stored;
    while (q.next()) {
        stored.push_back(q.value(1).toDouble());
        EXPECT_EQ(q.value(2).toInt(), 1);
    }
    EXPECT_EQ(stored, (std::vector<double>{27.012, 27.015, 27.021, 27.009, 26.998}));

    window.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(
        waitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; }, tt::test::kPatientWaitMs));
    EXPECT_EQ(state.loop(), AppState::Loop::Idle);
}

TEST_F(RunPageTest, ASilentGaugePausesTheRunAndItContinuesWhenTheGaugeIsBack) {
    RunPage page(context);
    page.resize(1400, 900);
    page.show();
    page.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page.session().snapshot().partsFinished >= 3; }, tt::test::kPatientWaitMs));
    page.session().silenceGauge(4 * 3600.0);  // 4 simulated hours: about 4 s at x3600
    ASSERT_TRUE(
        waitFor([&] { return page.session().snapshot().state == core::LoopState::Paused; }, tt::test::kPatientWaitMs));
    EXPECT_EQ(state.loop(), AppState::Loop::Paused);
    EXPECT_TRUE(
        page.findChild<QLabel*>(QStringLiteral("deviceText"))->text().contains(QStringLiteral("not answering")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("run_page_gauge_silent")));
    ASSERT_TRUE(
        waitFor([&] { return page.session().snapshot().state == core::LoopState::Running; }, tt::test::kPatientWaitMs));
    const qint64 done = page.session().snapshot().partsFinished;
    EXPECT_TRUE(waitFor([&] { return page.session().snapshot().partsFinished > done; }, tt::test::kPatientWaitMs));
    page.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
}

TEST_F(RunPageTest, AHistoryThatCannotBeOpenedRefusesToStartWithTheReason) {
    context.databasePath = dir.filePath(QStringLiteral("no/such/folder/history.sqlite"));
    RunPage page(context);
    page.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page.alarms()->count() > 0; }, tt::test::kPatientWaitMs));
    EXPECT_TRUE(page.alarms()->item(0)->text().contains(QStringLiteral("history cannot be opened")))
        << page.alarms()->item(0)->text().toStdString();
    EXPECT_TRUE(page.findChild<QPushButton*>(QStringLiteral("startButton"))->isEnabled());
}

}  // namespace
}  // namespace tt::ui
