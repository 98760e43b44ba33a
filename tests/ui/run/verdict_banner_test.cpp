// The Run page shows the last part's tolerance verdict big and coloured (issue 17, item 6): an
// out-of-tolerance part never looks accepted; View > "Sound on rework or scrap" sounds the alert for a rework
// or scrap part only when it is on. Screenshot: screenshots/terminal_last_part_scrap.png.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include "runtime/run/run_request.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "support/terminal_window.h"
#include "tests/support/patient_wait.h"
#include "ui/pages/run_page.h"
#include "ui/run/shaft_run_panel.h"
#include "ui/run/verdict_counter.h"

namespace tt::ui {
namespace {

using VerdictBanner = test::TerminalWindowTest;

/// The colour most of the label's pixels have (its background).
QColor dominantColour(QWidget* w) {
    const QImage image = w->grab().toImage();
    QHash<QRgb, int> counts;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ++counts[image.pixel(x, y)];
    QRgb best = 0;
    int most = 0;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        if (it.value() > most) {
            most = it.value();
            best = it.key();
        }
    return QColor(best);
}

// paper-2012-group1 at x3600 with "Pause on scrap": its band (+-0.026 mm, IT9 on 27 mm) is about the part
// scatter (sigma about 0.025 mm), so scrap comes within the first parts (as in tests/ui/verdicts).
TEST_F(VerdictBanner, TheLastScrapPartIsBigRedAndSoundsWhenTheSoundIsOn) {
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* page = qobject_cast<RunPage*>(window->page(PageId::Run));
    ASSERT_NE(page, nullptr);
    auto* banner = window->findChild<QLabel*>(QStringLiteral("lastPartVerdict"));
    ASSERT_NE(banner, nullptr);
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("none"));
    auto* panel = window->findChild<ShaftRunPanel*>();
    ASSERT_NE(panel, nullptr);
    QSignalSpy sounded(panel, &ShaftRunPanel::alertSounded);
    auto* verdicts = window->findChild<VerdictCounter*>();
    QSignalSpy bad(verdicts, &VerdictCounter::outOfTolerance);
    auto* sound = window->findChild<QAction*>(QStringLiteral("soundAction"));  // View > Sound on rework or scrap
    ASSERT_NE(sound, nullptr);
    sound->setChecked(true);
    window->findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(3);  // x3600
    window->findChild<QCheckBox*>(QStringLiteral("pauseOnScrapCheck"))->setChecked(true);
    window->findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return page->session().snapshot().status.kind == core::NoticeKind::PausedOnScrap; },
                        tt::test::kPatientWaitMs));
    QApplication::processEvents();
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("scrap"));
    EXPECT_TRUE(banner->text().contains(QStringLiteral("SCRAP"))) << banner->text().toStdString();
    // Readable from a metre: 24 pt bold, at least 30 px high glyphs.
    EXPECT_GE(banner->fontMetrics().capHeight(), 20) << "cap height in px";
    EXPECT_TRUE(banner->font().bold());
    const QColor background = dominantColour(banner);
    EXPECT_EQ(background, QColor(0xc6, 0x28, 0x28)) << background.name().toStdString() << ": scrap is red";
    // Every rework or scrap part sounded the alert, and only those.
    EXPECT_GE(bad.count(), 1);
    EXPECT_EQ(sounded.count(), bad.count());
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("terminal_last_part_scrap")));

    // Sound off: the next bad parts are shown but silent.
    sound->setChecked(false);
    const qsizetype before = sounded.count();
    const qsizetype badBefore = bad.count();
    window->findChild<QCheckBox*>(QStringLiteral("pauseOnScrapCheck"))->setChecked(false);
    window->findChild<QPushButton*>(QStringLiteral("pauseButton"))->click();  // continue
    ASSERT_TRUE(QTest::qWaitFor([&] { return bad.count() > badBefore; }, tt::test::kPatientWaitMs));
    EXPECT_EQ(sounded.count(), before);
    window->findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; },
                                tt::test::kPatientWaitMs));
    EXPECT_TRUE(QSettings().contains(kSoundOnOutOfTolerance));
    EXPECT_FALSE(QSettings().value(kSoundOnOutOfTolerance).toBool()) << "the setting is saved";
    sound->setChecked(true);
    MainWindow second(context);
    EXPECT_TRUE(second.findChild<QAction*>(QStringLiteral("soundAction"))->isChecked()) << "read at start";
}

TEST_F(VerdictBanner, ReworkIsAmberAndGoodIsGreen) {
    VerdictCounter counter;
    counter.resize(500, 160);
    counter.show();
    auto* banner = counter.findChild<QLabel*>(QStringLiteral("lastPartVerdict"));
    ASSERT_NE(banner, nullptr);
    core::LoopEvent event;
    event.kind = core::LoopEvent::Kind::PartMeasured;
    event.partNumber = 7;
    core::PartMeasurementRecord record;
    record.partNumber = 7;
    record.points.resize(1);
    record.points[0].verdict = core::ToleranceVerdict::Rework;
    event.measurement = record;
    counter.onLoopEvent(event);
    QApplication::processEvents();
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("rework"));
    EXPECT_TRUE(banner->text().startsWith(QStringLiteral("Part 7: REWORK"))) << banner->text().toStdString();
    EXPECT_EQ(dominantColour(banner), QColor(0x9a, 0x5b, 0x00)) << "amber";
    record.points[0].verdict = core::ToleranceVerdict::Good;
    event.measurement = record;
    event.partNumber = 8;
    counter.onLoopEvent(event);
    QApplication::processEvents();
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("good"));
    EXPECT_EQ(dominantColour(banner), QColor(0x2e, 0x7d, 0x32)) << "green";
    counter.reset();
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("none"));
}

// Pause on scrap stops the loop after the scrap part's verdict, but parts already measured may arrive in the same
// step (a busy computer, a fast simulation): they are counted, and the banner keeps the part that paused the run
// until the run goes on.
TEST_F(VerdictBanner, WhilePausedOnScrapTheBannerKeepsTheScrapPartThatPausedTheRun) {
    VerdictCounter counter;
    auto* banner = counter.findChild<QLabel*>(QStringLiteral("lastPartVerdict"));
    ASSERT_NE(banner, nullptr);
    const auto measured = [&](std::int64_t part, core::ToleranceVerdict verdict) {
        core::LoopEvent event;
        event.kind = core::LoopEvent::Kind::PartMeasured;
        event.partNumber = part;
        core::PartMeasurementRecord record;
        record.partNumber = part;
        record.points.resize(1);
        record.points[0].verdict = verdict;
        event.measurement = record;
        counter.onLoopEvent(event);
    };
    const auto state = [&](core::LoopState s, core::Notice notice) {
        core::LoopEvent event;
        event.kind = core::LoopEvent::Kind::StateChanged;
        event.state = s;
        event.notice = notice;
        counter.onLoopEvent(event);
    };
    measured(4, core::ToleranceVerdict::Scrap);
    state(core::LoopState::Paused, core::Notice(core::NoticeKind::PausedOnScrap, 4));
    measured(5, core::ToleranceVerdict::Good);
    measured(6, core::ToleranceVerdict::Rework);
    EXPECT_EQ(banner->property("verdict").toString(), QStringLiteral("scrap"));
    EXPECT_EQ(banner->text(), QStringLiteral("Part 4: SCRAP"));
    EXPECT_EQ(counter.counts().good, 1);
    EXPECT_EQ(counter.counts().rework, 1);
    EXPECT_EQ(counter.counts().scrap, 1);
    EXPECT_EQ(counter.lastVerdict(), core::ToleranceVerdict::Rework) << "the last judged part is still part 6";
    // The operator continues: the banner shows the last measured part again.
    state(core::LoopState::Running, core::Notice(core::NoticeKind::Continuing));
    EXPECT_EQ(banner->text(), QStringLiteral("Part 6: REWORK"));
    measured(7, core::ToleranceVerdict::Good);
    EXPECT_EQ(banner->text(), QStringLiteral("Part 7: GOOD"));
    // An operator's pause holds nothing.
    state(core::LoopState::Paused, core::Notice(core::NoticeKind::PausedByOperator));
    measured(8, core::ToleranceVerdict::Scrap);
    EXPECT_EQ(banner->text(), QStringLiteral("Part 8: SCRAP"));
}

}  // namespace
}  // namespace tt::ui
