// The Run page shows the controller the adaptive loop uses (issue 27, item 5): a run of paper-2012 on a plant of
// half the model's gain (z = 2) alarms on the mismatch, goes to the robust fallback (amber, with its weight) and
// then to the LQG designed for the identified plant, whose line names the part, the plant delay and the margin.
// Source of the expectation: `trueturn simulate --preset paper-2012 --delay 2 --plant-gain 0.5 --warmup 0
// --seed 1` goes to the fallback at part 13 and adapts at part 156 (README, adaptive control).
#include <gtest/gtest.h>

#include <QLabel>

#include "run_window.h"
#include "runtime/run/run_request.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "ui/run/notice_text.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

using RunAdaptationTest = test::RunWindowTest;

TEST_F(RunAdaptationTest, TheRunPageShowsTheFallbackAndThenTheAdaptedController) {
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    auto* inUse = window.findChild<QLabel*>(QStringLiteral("controllerInUse"));
    ASSERT_NE(inUse, nullptr);
    EXPECT_TRUE(inUse->isHidden()) << "nothing adapted yet";

    runtime::RunRequest r;
    r.preset = QStringLiteral("paper-2012");
    r.delay = 2;
    r.seed = 1;
    r.warmupParts = 0;
    r.endPart = 200;
    r.speed = 1e6;
    r.plant.gainFactor = 0.5;
    r.database = context.databasePath;
    ASSERT_TRUE(page->shaft().startRequest(r));

    ASSERT_TRUE(test::waitFor([&] { return inUse->isVisible(); })) << "the fallback took over";
    EXPECT_TRUE(inUse->text().contains(QStringLiteral("robust EWMA fallback"))) << inUse->text().toStdString();
    EXPECT_TRUE(inUse->styleSheet().contains(QStringLiteral("#9a5b00"))) << "amber while on the fallback";

    ASSERT_TRUE(test::waitFor([&] { return inUse->text().contains(QStringLiteral("LQG adapted")); }))
        << inUse->text().toStdString();
    EXPECT_TRUE(inUse->text().contains(QStringLiteral("plant delay 2 parts"))) << inUse->text().toStdString();
    EXPECT_FALSE(inUse->styleSheet().contains(QStringLiteral("#9a5b00")));
    ASSERT_TRUE(test::waitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; }));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_adapted_controller")));
}

TEST(ControllerInUseText, OnlyAdaptationNoticesNameAController) {
    core::Notice fallback(core::NoticeKind::FallbackEngaged, 13, 11);
    fallback.value = 0.49;
    EXPECT_EQ(
        controllerInUseText(fallback),
        QStringLiteral("Controller: robust EWMA fallback (weight 0.49) from part 13, while the plant is identified"));
    EXPECT_TRUE(controllerInUseIsFallback(fallback));
    core::Notice adapted(core::NoticeKind::ControllerAdapted, 156);
    adapted.value = 2;
    adapted.reference = 1.94;
    EXPECT_EQ(controllerInUseText(adapted),
              QStringLiteral("Controller: LQG adapted at part 156 (plant delay 2 parts, smallest gain margin 1.94)"));
    EXPECT_FALSE(controllerInUseIsFallback(adapted));
    EXPECT_TRUE(controllerInUseText(core::Notice(core::NoticeKind::IdentificationWaiting, 20)).isEmpty());
    EXPECT_TRUE(controllerInUseText(core::Notice(core::NoticeKind::ModelMismatch, 11)).isEmpty());
}

}  // namespace
}  // namespace tt::ui
