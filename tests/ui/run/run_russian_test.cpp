// The shaft Run tab in Russian during a run with a gauge fault and a rejected measurement (issue 11,
// "Engine events as kinds"): the loop's state, its alarms and the reasons are worded by the terminal from
// the engine's kinds, so nothing English reaches the operator. Screenshots: run_tab_ru_gauge_silent.png,
// run_tab_ru_rejected.png.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <optional>

#include "runtime/devices/device_hub.h"
#include "english_words.h"
#include "run_window.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"
#include "ui/run/manual_entry_panel.h"
#include "runtime/run/run_session.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

/// Names the preset gives (set-up files) and the controllers' international abbreviations, not texts of
/// the terminal.
const QStringList kData = {QStringLiteral("paper-2012-group1"),
                           QStringLiteral("paper-2012-group2"),
                           QStringLiteral("paper-2012-group3"),
                           QStringLiteral("paper-2012"),
                           QStringLiteral("LQG"),
                           QStringLiteral("EWMA"),
                           QStringLiteral("Enter")};

bool anyAlarmContains(const QListWidget* alarms, const QString& text) {
    for (int i = 0; i < alarms->count(); ++i)
        if (alarms->item(i)->text().contains(text)) return true;
    return false;
}

using test::typeAndEnter;

class RunTabInRussian : public test::RunWindowTest {
protected:
    void SetUp() override {
        QSettings().remove(QStringLiteral("run"));
        ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }
};

TEST_F(RunTabInRussian, AGaugeFaultAndARejectedMeasurementShowNoEnglish) {
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    ShaftRunPanel& shaft = page->shaft();
    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);  // x3600
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return page->session().snapshot().partsFinished >= 4; }, tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);

    // The simulated lathe's gauge goes silent (for longer than the test): the loop pauses when the
    // diameters the next part needs do not come, holds the correction and says why.
    page->session().silenceGauge(1e6);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const core::NoticeKind k = page->session().snapshot().status.kind;
            return k == core::NoticeKind::NoDiameters || k == core::NoticeKind::GaugeNotReady;
        },
        tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    QTest::qWait(100);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_tab_ru_gauge_silent")));
    QStringList english = test::englishIn(&shaft, kData);

    page->session().stop();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; },
                                tt::test::kPatientWaitMs));

    // A new run with the diameters typed by hand: a slipped decimal point is refused at once; a diameter
    // 0.49 mm off (inside the plausible window) goes to the loop, whose controller rejects it as an
    // outlier; every word of it is Russian.
    window.findChild<QCheckBox*>(QStringLiteral("manualEntryCheck"))->setChecked(true);
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ManualEntryPanel* manual = page->manualEntry();
    std::optional<qint64> typed;  // the part whose diameters were typed last
    for (int n = 0; n < 6 && !anyAlarmContains(page->alarms(), QStringLiteral("точка 3")); ++n) {
        ASSERT_TRUE(QTest::qWaitFor(
            [&] {
                const runtime::LoopSnapshot& s = page->session().snapshot();
                return s.manualEntry && s.awaitingPart && s.awaitingPart != typed && manual->field(0)->isEnabled();
            },
            tt::test::kPatientWaitMs));
        typed = page->session().snapshot().awaitingPart;
        typeAndEnter(manual->field(0), QStringLiteral("2.7012"));
        EXPECT_TRUE(manual->field(0)->property("invalid").toBool());
        for (int i = 0; i < manual->fieldCount(); ++i)
            typeAndEnter(manual->field(i), i == 2 ? QStringLiteral("27.49") : QStringLiteral("27.000"));
        const bool taken =
            QTest::qWaitFor([&] { return page->session().snapshot().awaitingPart != typed; }, tt::test::kPatientWaitMs);
        if (!taken) test::saveScreenshot(window, QStringLiteral("run_tab_ru_not_taken"));
        ASSERT_TRUE(taken) << core::describe(page->session().snapshot().status);
    }
    EXPECT_TRUE(anyAlarmContains(page->alarms(), QStringLiteral("точка 3")))
        << page->alarms()->item(0)->text().toStdString();
    QTest::qWait(200);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_tab_ru_rejected")));
    english << test::englishIn(&shaft, kData);
    page->session().stop();
    QTest::qWait(100);
    EXPECT_TRUE(english.isEmpty()) << english.join(QStringLiteral("\n  ")).toStdString();
}

}  // namespace
}  // namespace tt::ui
