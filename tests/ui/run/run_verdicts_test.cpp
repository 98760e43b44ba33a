// The Run page's tolerance verdicts (issue 12), offscreen: good / rework / scrap counters and the yield
// fill as parts are measured, an out-of-tolerance part is an alarm naming the point, and "Pause on scrap"
// pauses the loop at the first scrap part until the operator continues.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <functional>

#include "run_window.h"
#include "runtime/devices/device_hub.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

using test::waitFor;

class RunVerdictsTest : public ::testing::Test {
protected:
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
};

int countIn(const QLabel* label) {
    return label->text().section(QLatin1Char(':'), 1).trimmed().toInt();
}

// paper-2012-group1: the tolerance band of the preset is +-0.026 mm (IT9 on 27 mm), about the part-to-part
// scatter (sigma about 0.025 mm), so a part below the lower limit (scrap) comes within the first parts.
TEST_F(RunVerdictsTest, CountersYieldAlarmsAndThePauseOnTheFirstScrap) {
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Run);
    auto* page = qobject_cast<RunPage*>(window.page(PageId::Run));
    ASSERT_NE(page, nullptr);
    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);  // x3600
    window.findChild<QCheckBox*>(QStringLiteral("pauseOnScrapCheck"))->setChecked(true);
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page->session().snapshot().status.kind == core::NoticeKind::PausedOnScrap; },
                        tt::test::kPatientWaitMs))
        << core::describe(page->session().snapshot().status);
    EXPECT_EQ(page->session().snapshot().state, core::LoopState::Paused);
    const auto* good = window.findChild<QLabel*>(QStringLiteral("verdictGood"));
    const auto* rework = window.findChild<QLabel*>(QStringLiteral("verdictRework"));
    const auto* scrap = window.findChild<QLabel*>(QStringLiteral("verdictScrap"));
    const auto* yield = window.findChild<QLabel*>(QStringLiteral("verdictYield"));
    ASSERT_TRUE(good && rework && scrap && yield);
    EXPECT_EQ(countIn(scrap), 1) << "paused at the first scrap part";
    EXPECT_EQ(countIn(good) + countIn(rework) + countIn(scrap), page->session().snapshot().status.part)
        << "every part up to the scrap one is judged";
    EXPECT_TRUE(yield->text().contains(QLatin1Char('%'))) << qPrintable(yield->text());
    bool alarmed = false;
    for (int i = 0; i < page->alarms()->count(); ++i)
        alarmed = alarmed || page->alarms()->item(i)->text().contains(QStringLiteral("below the lower limit"));
    EXPECT_TRUE(alarmed) << "the scrap part's alarm names the point and the limit";
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_paused_on_scrap")));

    // Nothing new while paused; the operator continues.
    const qint64 next = page->session().snapshot().nextPart;
    QTest::qWait(500);
    EXPECT_EQ(page->session().snapshot().nextPart, next);
    window.findChild<QPushButton*>(QStringLiteral("pauseButton"))->click();
    EXPECT_TRUE(waitFor([&] { return page->session().snapshot().nextPart > next; }, tt::test::kPatientWaitMs));
    window.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    EXPECT_TRUE(
        waitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; }, tt::test::kPatientWaitMs));
}

}  // namespace
}  // namespace tt::ui
