// Both calibration wizards in Russian inside the main window at 1280 × 800, on the built-in
// simulator's probe mandrel and drive read-out (their stands' jacks): every wizard page fits the
// terminal's screen and shows no English text that has a translation, with the procedures'
// events (captures, a saturated point, the fit, verification, upload, loads) worded in Russian.
// Screenshots: screenshots/i18n_calibration_*_ru.png.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QFile>
#include <QLabel>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include "screenshots.h"
#include "scripted_prompt.h"
#include "stand_devices.h"
#include "ui/app_state.h"
#include "ui/calibration/kp_fit_page.h"
#include "ui/calibration/kp_loads_page.h"
#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_accept_page.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_save_page.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/calibration_page.h"

namespace tt::ui {
namespace {

/// The English sources of finished translations that differ from their Russian: on screen they
/// are English left behind. Read with a pattern: the file is the one lupdate writes.
QSet<QString> translatedSources() {
    QFile file(QStringLiteral(TRUETURN_SOURCE_DIR "/resources/translations/trueturn_ru.ts"));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    const QString ts = QString::fromUtf8(file.readAll());
    static const QRegularExpression message(
        QStringLiteral("<message>\\s*<source>(.*?)</source>\\s*<translation>(.*?)</translation>"),
        QRegularExpression::DotMatchesEverythingOption);
    auto unescape = [](QString s) {
        return s.replace(QStringLiteral("&lt;"), QStringLiteral("<"))
            .replace(QStringLiteral("&gt;"), QStringLiteral(">"))
            .replace(QStringLiteral("&apos;"), QStringLiteral("'"))
            .replace(QStringLiteral("&quot;"), QStringLiteral("\""))
            .replace(QStringLiteral("&amp;"), QStringLiteral("&"));
    };
    QSet<QString> sources;
    for (auto it = message.globalMatch(ts); it.hasNext();) {
        const auto m = it.next();
        if (m.captured(1) != m.captured(2)) sources.insert(unescape(m.captured(1)));
    }
    return sources;
}

class CalibrationWizardsInRussian : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        context =
            AppContext{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &stand.manager};
        ASSERT_TRUE(stand.waitReady());
        ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }
    void step(double seconds) { stand.step(seconds); }
    /// The window fits 1280 × 800, and no label or button of `root` shows translated English.
    void check(MainWindow& window, QWidget* root, const QString& name) {
        QApplication::processEvents();
        EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("i18n_calibration_%1_ru").arg(name)));
        const QSize need = window.minimumSizeHint();
        EXPECT_LE(need.width(), 1280) << name.toStdString();
        EXPECT_LE(need.height(), 800) << name.toStdString();
        for (QWidget* w : root->findChildren<QWidget*>()) {
            if (!w->isVisibleTo(root)) continue;
            QString text;
            if (auto* label = qobject_cast<QLabel*>(w)) text = label->text();
            if (auto* button = qobject_cast<QAbstractButton*>(w)) text = button->text();
            EXPECT_FALSE(english.contains(text)) << name.toStdString() << ": English \"" << text.toStdString()
                                                 << "\" in " << w->objectName().toStdString();
            EXPECT_FALSE(text.contains(QStringLiteral("Point")) || text.contains(QStringLiteral("Check at")) ||
                         text.contains(QStringLiteral(" N: ")) || text.contains(QStringLiteral("Verified")))
                << name.toStdString() << ": an English event \"" << text.toStdString() << "\"";
        }
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    test::StandDevices stand{QStringLiteral("Симулятор оправки-датчика"),
                             QStringLiteral("Симулятор датчика тока привода")};
    AppContext context;
    const QSet<QString> english = translatedSources();
};

TEST_F(CalibrationWizardsInRussian, ProbeWizardPagesFitAndSpeakRussian) {
    MainWindow window(context);
    state.setOperatorName(QStringLiteral("Анна"));  // after the Settings page read its own
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Calibration);
    auto* page = dynamic_cast<CalibrationPage*>(window.page(PageId::Calibration));
    ASSERT_NE(page, nullptr);
    page->startProbeCalibration();
    ProbeCalibrationWizard* w = page->probeWizard();
    check(window, w, QStringLiteral("probe_1_choose"));
    w->next();
    check(window, w, QStringLiteral("probe_2_reference"));
    w->next();
    ProbeCapturePage* cp = w->capturePage();
    for (int i = 0; i <= 10; ++i) {  // on the stand: the jack bends the bar, the point is captured
        cp->setJack(-250.0 + 50.0 * i);
        step(0.3);  // the mandrel's samples under the old load are through before the press
        ASSERT_TRUE(cp->capturePoint());
        for (int k = 0; k < 200 && cp->capturing(); ++k) {
            step(0.05);
            cp->pollProbe();
        }
    }
    EXPECT_TRUE(cp->message().startsWith(QStringLiteral("Точка 11"))) << cp->message().toStdString();
    cp->setReferenceUm(320.0);
    cp->setTypedCode(65535.0);
    cp->addTypedPoint();  // at the ADC's limit: flagged in red
    EXPECT_TRUE(cp->message().contains(QStringLiteral("насыщении"))) << cp->message().toStdString();
    check(window, w, QStringLiteral("probe_3_capture"));
    w->next();
    check(window, w, QStringLiteral("probe_4_fit"));
    w->next();
    w->acceptPage()->setJack(123.0);
    step(0.3);  // the mandrel's samples under the old load are through before the press
    ASSERT_TRUE(w->acceptPage()->checkPoint());
    for (int i = 0; i < 200 && page->probeSession().procedure.capturing(); ++i) {
        step(0.05);
        w->acceptPage()->pollProbe();
    }
    EXPECT_TRUE(w->acceptPage()->checkResult().startsWith(QStringLiteral("Проверка")))
        << w->acceptPage()->checkResult().toStdString();
    w->acceptPage()->findChild<QCheckBox*>(QStringLiteral("acceptCheck"))->setChecked(true);
    check(window, w, QStringLiteral("probe_5_accept"));
    w->next();
    ASSERT_TRUE(w->savePage()->save())
        << w->savePage()->findChild<QLabel*>(QStringLiteral("saveResult"))->text().toStdString();
    ASSERT_TRUE(w->savePage()->upload());
    for (int i = 0; i < 1000 && !w->savePage()->isComplete(); ++i) {
        step(0.05);
        w->savePage()->pollUpload();
    }
    EXPECT_TRUE(w->savePage()->isComplete());
    check(window, w, QStringLiteral("probe_6_upload"));
}

TEST_F(CalibrationWizardsInRussian, KpWizardPagesFitAndSpeakRussian) {
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    window.showPage(PageId::Calibration);
    auto* page = dynamic_cast<CalibrationPage*>(window.page(PageId::Calibration));
    ASSERT_NE(page, nullptr);
    page->startKpCalibration();
    KpCalibrationWizard* w = page->kpWizard();
    check(window, w, QStringLiteral("kp_1_setup"));
    w->next();
    KpLoadsPage* loads = w->loadsPage();
    for (double load : {0.0, 300.0}) {
        loads->setLoadN(load);
        ASSERT_TRUE(loads->startMeasurement());
        for (int i = 0; i < 2000 && loads->measuring(); ++i) {
            step(0.05);
            loads->step(0.05);
        }
    }
    loads->setLoadN(600.0);
    loads->setTypedCurrentDifference(4.0);
    loads->addTypedPoint();
    check(window, w, QStringLiteral("kp_2_loads"));
    w->next();
    KpFitPage* fp = w->fitPage();
    fp->setCheckLoadN(150.0);
    ASSERT_TRUE(fp->checkLoad());
    for (int i = 0; i < 2000 && fp->checking(); ++i) {
        step(0.05);
        fp->step(0.05);
    }
    EXPECT_TRUE(fp->checkResult().startsWith(QStringLiteral("Проверка"))) << fp->checkResult().toStdString();
    check(window, w, QStringLiteral("kp_3_fit"));
    w->next();
    check(window, w, QStringLiteral("kp_4_save"));
}

}  // namespace
}  // namespace tt::ui
