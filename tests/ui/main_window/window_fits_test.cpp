// The window fits the terminal's 1280 x 800 screen at every page, every tab of the Run and Process
// pages and every page of both calibration wizards, in English and in Russian (issue 17, item 7): the
// window's size and its minimum size stay within 1280 x 800, no button or one-line label is cut off or
// reaches beyond the window, no two widgets overlap, and every button, combo box, spin box and line edit
// is at least a touch target high (40 px). Screenshots of every page and tab in both
// languages: screenshots/terminal_<page>[_tab<n>]_<en|ru>.png.
#include <QCheckBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QTest>

#include "support/fit_checks.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "stand_devices.h"
#include "support/terminal_window.h"
#include "ui/calibration/kp_loads_page.h"
#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_accept_page.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/pages/calibration_page.h"
#include "ui/pages/process_page.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

QString joined(const QStringList& list) {
    return list.join(QLatin1Char('\n'));
}

class WindowFits : public test::TerminalWindowTest, public ::testing::WithParamInterface<const char*> {
protected:
    QString lang() const { return QString::fromLatin1(GetParam()); }
    void check(MainWindow& window, QWidget* root, const QString& where) {
        const QString full = lang() + QStringLiteral(", ") + where;
        problems << test::sizeProblems(window, full) << test::cutOffProblems(root, full)
                 << test::overlapProblems(root, full) << test::touchTargetProblems(root, full);
    }
    QStringList problems;
};

TEST_P(WindowFits, EveryPageAndTab) {
    ASSERT_TRUE(language.apply(lang()));
    auto window = openWindow();
    for (Page* page : window->pages()) {
        window->showPage(page->id());
        QApplication::processEvents();
        QTabWidget* tabs = nullptr;
        if (auto* run = qobject_cast<RunPage*>(page)) tabs = run->tabs();
        if (auto* process = qobject_cast<ProcessPage*>(page)) tabs = process->tabs();
        const int count = tabs ? tabs->count() : 1;
        for (int t = 0; t < count; ++t) {
            if (tabs) tabs->setCurrentIndex(t);
            QApplication::processEvents();
            const QString where = pageKey(page->id()) + (tabs ? QStringLiteral("_tab%1").arg(t) : QString());
            check(*window, page, where);
            EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("terminal_%1_%2").arg(where, lang())));
        }
        if (tabs) tabs->setCurrentIndex(0);
    }
    check(*window, window->statusBar(), QStringLiteral("status bar"));
    EXPECT_TRUE(problems.isEmpty()) << joined(problems).toStdString();
}

// The wizards on the simulator's mandrel and drive on their stands (tests/ui/stand_devices.h), stepped
// through with real captures as in tests/ui/language/calibration_wizards_ru_test.cpp.
TEST_P(WindowFits, EveryPageOfBothCalibrationWizards) {
    ASSERT_TRUE(language.apply(lang()));
    test::StandDevices stand(QStringLiteral("probe"), QStringLiteral("drive"));
    ASSERT_TRUE(stand.waitReady());
    context.devices = &stand.manager;
    auto window = openWindow();
    window->showPage(PageId::Calibration);
    auto* page = dynamic_cast<CalibrationPage*>(window->page(PageId::Calibration));
    ASSERT_NE(page, nullptr);

    page->startProbeCalibration();
    ProbeCalibrationWizard* w = page->probeWizard();
    ASSERT_NE(w, nullptr);
    check(*window, w, QStringLiteral("probe 1"));
    w->next();
    check(*window, w, QStringLiteral("probe 2"));
    w->next();
    ProbeCapturePage* cp = w->capturePage();
    for (int i = 0; i <= 10; ++i) {
        cp->setJack(-250.0 + 50.0 * i);
        stand.step(0.3);  // the mandrel's samples under the old load are through before the press
        ASSERT_TRUE(cp->capturePoint());
        for (int k = 0; k < 200 && cp->capturing(); ++k) {
            stand.step(0.05);
            cp->pollProbe();
        }
    }
    cp->setReferenceUm(320.0);
    cp->setTypedCode(65535.0);  // a saturated point: its long red message
    cp->addTypedPoint();
    check(*window, w, QStringLiteral("probe 3 (capture)"));
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("terminal_probe_capture_%1").arg(lang())));
    w->next();
    check(*window, w, QStringLiteral("probe 4 (fit)"));
    w->next();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    check(*window, w, QStringLiteral("probe 5 (accept)"));
    w->next();
    check(*window, w, QStringLiteral("probe 6 (save)"));

    page->startKpCalibration();
    KpCalibrationWizard* kp = page->kpWizard();
    ASSERT_NE(kp, nullptr);
    check(*window, kp, QStringLiteral("kp 1"));
    kp->next();
    KpLoadsPage* loads = kp->loadsPage();
    for (double load : {0.0, 300.0}) {
        loads->setLoadN(load);
        ASSERT_TRUE(loads->startMeasurement());
        for (int i = 0; i < 2000 && loads->measuring(); ++i) {
            stand.step(0.05);
            loads->step(0.05);
        }
    }
    check(*window, kp, QStringLiteral("kp 2 (loads)"));
    kp->next();
    check(*window, kp, QStringLiteral("kp 3 (fit)"));
    kp->next();
    check(*window, kp, QStringLiteral("kp 4 (save)"));
    EXPECT_TRUE(problems.isEmpty()) << joined(problems).toStdString();
}

INSTANTIATE_TEST_SUITE_P(Languages, WindowFits, ::testing::Values("en", "ru"));

}  // namespace
}  // namespace tt::ui
