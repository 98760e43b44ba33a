// The About box says what is implemented and what is not yet, in both languages, and fits the
// 1280 x 800 terminal.
#include "ui/about.h"

#include <gtest/gtest.h>

#include <trueturn/version.h>
#include <QLabel>
#include <QMessageBox>

#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/planned_page.h"

namespace tt::ui {
namespace {

class AboutTest : public ::testing::Test {
protected:
    void TearDown() override { language.apply(QStringLiteral("en")); }

    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, QStringLiteral("/tmp/trueturn-test/history.sqlite"), &devices};
};

TEST_F(AboutTest, TheAboutBoxListsWhatIsImplementedAndWhatIsNotYet) {
    state.setLogFilePath(QStringLiteral("/tmp/trueturn-test/logs/trueturn.log"));
    MainWindow window(context);
    window.showAbout();
    ASSERT_EQ(prompt.log.size(), 1);
    const QString text = prompt.lastText;
    EXPECT_TRUE(text.contains(QString::fromLatin1(tt::kVersion)));
    EXPECT_TRUE(text.contains(QStringLiteral("/tmp/trueturn-test/logs/trueturn.log")));
    ASSERT_FALSE(About::notYet().isEmpty());
    ASSERT_FALSE(About::implemented().isEmpty());
    for (const QString& item : About::implemented() + About::notYet())
        EXPECT_TRUE(text.contains(item.toHtmlEscaped())) << item.toStdString();
    // Every page still shown as planned (ui/pages/page_factory.cpp) is named in the "not yet" list.
    int planned = 0;
    for (Page* page : window.pages()) {
        if (!qobject_cast<PlannedPage*>(page)) continue;
        ++planned;
        const QStringList naming = About::notYet().filter(page->title());
        EXPECT_FALSE(naming.isEmpty()) << "the planned page " << page->title().toStdString() << " is not listed";
    }
    RecordProperty("planned_pages", planned);
}

TEST_F(AboutTest, EveryItemIsTranslatedToRussian) {
    const QStringList english = About::implemented() + About::notYet();
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    const QStringList russian = About::implemented() + About::notYet();
    ASSERT_EQ(russian.size(), english.size());
    for (qsizetype i = 0; i < english.size(); ++i)
        EXPECT_NE(russian[i], english[i]) << "untranslated: " << english[i].toStdString();
}

TEST_F(AboutTest, TheBoxFitsTheTerminalInBothLanguages) {
    for (const QString& code : {QStringLiteral("en"), QStringLiteral("ru")}) {
        ASSERT_TRUE(language.apply(code));
        QMessageBox box(QMessageBox::Information, QStringLiteral("TrueTurn"),
                        About::text(QStringLiteral("/root/.local/share/TrueTurn/TrueTurn/logs/trueturn.log")));
        box.show();
        EXPECT_TRUE(test::saveScreenshot(box, QStringLiteral("about_") + code));
        // One line per item: the label shows its whole width (QMessageBox caps its width).
        const auto* label = box.findChild<QLabel*>(QStringLiteral("qt_msgbox_label"));
        ASSERT_NE(label, nullptr);
        EXPECT_GE(label->width(), label->sizeHint().width()) << "cut off in " << code.toStdString();
        EXPECT_LE(box.width(), 1280) << code.toStdString();
        EXPECT_LE(box.height(), 800) << code.toStdString();
    }
}

}  // namespace
}  // namespace tt::ui
