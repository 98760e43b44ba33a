// Russian, the second language of the terminal (resources/translations/trueturn_ru.ts): every
// message is translated, keeps the source's placeholders and accelerators, and the main window
// switched to Russian at 1280 × 800 shows no English text where a translation exists and no button
// or one-line label cut off. Screenshots of every page and of both Run tabs: screenshots/i18n_*_ru.png.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QGroupBox>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QMap>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QXmlStreamReader>

#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "runtime/devices/terminal_devices.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui {
namespace {

const QString kRussianTs = QStringLiteral(TRUETURN_SOURCE_DIR "/resources/translations/trueturn_ru.ts");
const QString kBuildPlugins = QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins");

/// One message of a .ts file as lupdate wrote it.
struct TsMessage {
    QString context;
    QString source;
    QStringList translations;  ///< one text, or the numerus forms
    bool numerus = false;
    QString type;  ///< "unfinished", "vanished", "obsolete" or empty (finished)
};

/// The messages of `path` and the file's language; fails the test when the XML is not well formed.
std::pair<QList<TsMessage>, QString> readTs(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    QXmlStreamReader xml(&file);
    QList<TsMessage> messages;
    QString language;
    QString context;
    TsMessage current;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        const auto name = xml.name();
        if (name == QLatin1String("TS")) {
            language = xml.attributes().value(QStringLiteral("language")).toString();
        } else if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            current = TsMessage{context, {}, {}, xml.attributes().value(QStringLiteral("numerus")) == u"yes", {}};
        } else if (name == QLatin1String("source")) {
            current.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            current.type = xml.attributes().value(QStringLiteral("type")).toString();
            if (current.numerus) {
                while (xml.readNextStartElement())  // <numerusform>, up to </translation>
                    current.translations << xml.readElementText();
            } else {
                current.translations << xml.readElementText();
            }
            messages << current;
        }
    }
    EXPECT_FALSE(xml.hasError()) << path.toStdString() << ": " << xml.errorString().toStdString() << " at line "
                                 << xml.lineNumber();
    return {messages, language};
}

QString where(const TsMessage& m) {
    return m.context + QStringLiteral(" | \"") + m.source + QLatin1Char('"');
}

/// How often each placeholder occurs: %1 to %99 (also %L1) and %n.
QMap<QString, int> placeholders(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral("%L?([0-9]{1,2}|n)"));
    QMap<QString, int> counts;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        ++counts[it.next().captured(1)];
    return counts;
}

/// Keyboard accelerators: '&' before a character, "&&" being a literal ampersand.
int accelerators(const QString& text) {
    int count = 0;
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&')) continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        if (!text[i + 1].isSpace()) ++count;
    }
    return count;
}

QString joined(const QStringList& problems) {
    return QStringLiteral("\n  ") + problems.join(QStringLiteral("\n  "));
}

TEST(RussianTranslationFile, EveryMessageIsTranslated) {
    const auto [messages, language] = readTs(kRussianTs);
    EXPECT_EQ(language, QStringLiteral("ru_RU"));
    ASSERT_GT(messages.size(), 600);  // 904 when written; a few more or less as the UI changes
    QStringList problems;
    for (const TsMessage& m : messages) {
        if (m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete")) continue;
        if (m.type == QLatin1String("unfinished")) {
            problems << QStringLiteral("unfinished: ") + where(m);
            continue;
        }
        // Russian has three plural forms (1, 2-4, 5-20: деталь, детали, деталей).
        if (m.numerus && m.translations.size() != 3)
            problems << QStringLiteral("%1 plural forms instead of 3: ").arg(m.translations.size()) + where(m);
        for (const QString& t : m.translations)
            if (t.trimmed().isEmpty()) problems << QStringLiteral("empty: ") + where(m);
    }
    EXPECT_TRUE(problems.isEmpty()) << problems.size() << " message(s) to translate in " << kRussianTs.toStdString()
                                    << " (Qt Linguist, or fill <translation> and drop type=\"unfinished\"):"
                                    << joined(problems).toStdString();
}

TEST(RussianTranslationFile, TranslationsKeepPlaceholdersAndAccelerators) {
    const auto [messages, language] = readTs(kRussianTs);
    ASSERT_FALSE(messages.isEmpty());
    QStringList problems;
    for (const TsMessage& m : messages) {
        if (!m.type.isEmpty()) continue;
        const QMap<QString, int> expected = placeholders(m.source);
        for (const QString& t : m.translations) {
            QMap<QString, int> got = placeholders(t);
            // A plural form may leave out the count ("одна деталь"); every %1..%99 must stay.
            if (m.numerus && !got.contains(QStringLiteral("n")))
                got.insert(QStringLiteral("n"), expected.value(QStringLiteral("n")));
            if (got != expected) problems << QStringLiteral("placeholders differ in \"%1\": ").arg(t) + where(m);
            if (accelerators(t) != accelerators(m.source))
                problems << QStringLiteral("accelerator '&' missing or extra in \"%1\": ").arg(t) + where(m);
        }
    }
    EXPECT_TRUE(problems.isEmpty()) << joined(problems).toStdString();
}

/// The main window as the terminal starts in Russian: devices made on a first start in Russian
/// (TerminalDevices, like app/gui.cpp), the window built in English and switched at run time.
class RussianWindow : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        ASSERT_TRUE(language.apply(QStringLiteral("ru")));
        devices = std::make_unique<runtime::TerminalDevices>(kBuildPlugins);
        ASSERT_TRUE(language.apply(QStringLiteral("en")));
        context =
            AppContext{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices->hub()};
        recordFinishedRun();
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }

    /// A finished run in the history, so the Measurements page lists it (a long line).
    void recordFinishedRun() {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        storage::SqlHistoryStore store(db);
        const std::vector<double> z = {0.0, 27.5, 162.5, 262.5, 325.0};
        const std::int64_t run = store.beginRun({"paper-2012-group1", "open", 4, 27.0, 325.0, z, "{}"});
        store.finishRun(run, "complete");
    }

    /// The terminal's smallest screen is 1280 × 800: with each page shown, the window must fit it.
    static QStringList fitProblems(MainWindow& window, const QString& how) {
        QStringList problems;
        for (Page* page : window.pages()) {
            window.showPage(page->id());
            QApplication::processEvents();
            const QSize need = window.minimumSizeHint();
            if (need.width() > 1280 || need.height() > 800)
                problems << QStringLiteral(
                                "%1, %2: the window needs %3 × %4 px (the page %5 × %6 px), more than "
                                "1280 × 800")
                                .arg(how, pageKey(page->id()))
                                .arg(need.width())
                                .arg(need.height())
                                .arg(page->minimumSizeHint().width())
                                .arg(page->minimumSizeHint().height());
        }
        return problems;
    }

    /// Source texts whose Russian differs: seen on screen, they are English left untranslated.
    static QSet<QString> englishTexts() {
        QSet<QString> texts;
        for (const TsMessage& m : readTs(kRussianTs).first)
            if (m.type.isEmpty() && !m.numerus && m.translations.value(0) != m.source) texts.insert(m.source);
        return texts;
    }

    /// What `root` shows that is still English, and buttons and one-line labels narrower than
    /// their text (cut off), each with the widget's class and object name.
    static QStringList problemsOf(QWidget* root, const QSet<QString>& english) {
        QStringList problems;
        auto name = [](const QWidget* w) {
            return QStringLiteral("%1 '%2'").arg(QString::fromLatin1(w->metaObject()->className()), w->objectName());
        };
        auto checkText = [&](const QWidget* w, const QString& text) {
            if (english.contains(text)) problems << QStringLiteral("English \"%1\" in %2").arg(text, name(w));
        };
        for (QWidget* w : root->findChildren<QWidget*>()) {
            if (!w->isVisibleTo(root) || w->width() <= 0) continue;
            if (auto* label = qobject_cast<QLabel*>(w)) {
                checkText(w, label->text());
                if (!label->wordWrap() && !label->text().isEmpty() && label->textFormat() != Qt::RichText &&
                    !label->text().contains(QLatin1Char('<')) && label->sizeHint().width() > label->width() + 1)
                    problems << QStringLiteral("cut off: \"%1\" in %2 (%3 px of %4 px)")
                                    .arg(label->text(), name(w))
                                    .arg(label->width())
                                    .arg(label->sizeHint().width());
            } else if (auto* button = qobject_cast<QAbstractButton*>(w)) {
                checkText(w, button->text());
                if (!button->text().isEmpty() && button->sizeHint().width() > button->width() + 1)
                    problems << QStringLiteral("cut off: \"%1\" in %2 (%3 px of %4 px)")
                                    .arg(button->text(), name(w))
                                    .arg(button->width())
                                    .arg(button->sizeHint().width());
            } else if (auto* group = qobject_cast<QGroupBox*>(w)) {
                checkText(w, group->title());
            } else if (auto* combo = qobject_cast<QComboBox*>(w)) {
                for (int i = 0; i < combo->count(); ++i)
                    checkText(w, combo->itemText(i));
            } else if (auto* tabs = qobject_cast<QTabBar*>(w)) {
                for (int i = 0; i < tabs->count(); ++i)
                    checkText(w, tabs->tabText(i));
            } else if (auto* view = qobject_cast<QAbstractItemView*>(w); view && view->model()) {
                for (int c = 0; c < view->model()->columnCount(); ++c)
                    checkText(w, view->model()->headerData(c, Qt::Horizontal).toString());
            }
        }
        return problems;
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    std::unique_ptr<runtime::TerminalDevices> devices;
    AppContext context;
};

TEST_F(RussianWindow, EveryPageAndBothRunTabsAreRussianAndNothingIsCutOff) {
    MainWindow window(context);
    window.resize(1280, 800);
    window.show();
    QApplication::processEvents();
    auto* settingsButton = window.findChild<QToolButton*>(QStringLiteral("nav_settings"));
    ASSERT_NE(settingsButton, nullptr);
    EXPECT_EQ(settingsButton->text(), QStringLiteral("Settings"));

    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QApplication::processEvents();
    EXPECT_EQ(settingsButton->text(), QStringLiteral("Настройки"));
    // The simulators were made on a Russian first start: their names are Russian.
    const runtime::DeviceHub& manager = devices->hub();
    EXPECT_EQ(manager.view(manager.devicesOfKind(devices::DeviceKind::Gauge).value(0))->name,
              QStringLiteral("Симулятор микрометра"));
    // The simulated devices tell their state in Russian once they tick after the switch.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return manager.view(manager.devicesOfKind(devices::DeviceKind::Gauge).value(0))->health.message ==
                   "симулятор микрометра готов";
        },
        tt::test::kPatientWaitMs));

    const QSet<QString> english = englishTexts();
    QStringList problems;
    for (Page* page : window.pages()) {
        window.findChild<QToolButton*>(QStringLiteral("nav_") + pageKey(page->id()))->click();
        QApplication::processEvents();
        const QString key = pageKey(page->id());
        if (page->id() == PageId::Run) {
            auto* run = dynamic_cast<RunPage*>(page);
            ASSERT_NE(run, nullptr);
            ASSERT_EQ(run->tabs()->count(), 2);
            const QStringList tabNames{QStringLiteral("shaft"), QStringLiteral("boring")};
            for (int tab = 0; tab < 2; ++tab) {
                run->tabs()->setCurrentIndex(tab);
                QApplication::processEvents();
                EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("i18n_run_%1_ru").arg(tabNames[tab])));
                for (const QString& p : problemsOf(run->tabs()->currentWidget(), english))
                    problems << QStringLiteral("run/%1: ").arg(tabNames[tab]) + p;
            }
            run->tabs()->setCurrentIndex(0);
            QApplication::processEvents();
        } else {
            EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("i18n_page_%1_ru").arg(key)));
            for (const QString& p : problemsOf(page, english))
                problems << key + QStringLiteral(": ") + p;
        }
        EXPECT_NE(page->title(), QString()) << key.toStdString();
    }
    problems << fitProblems(window, QStringLiteral("switched to Russian"));
    for (const QString& p : problemsOf(window.statusBar(), english))
        problems << QStringLiteral("status bar: ") + p;
    for (QToolButton* button : window.findChildren<QToolButton*>())
        if (button->objectName().startsWith(QLatin1String("nav_"))) {
            if (english.contains(button->text()))
                problems << QStringLiteral("navigation: English \"%1\"").arg(button->text());
            if (button->width() < button->sizeHint().width())
                problems << QStringLiteral("navigation: \"%1\" cut off").arg(button->text());
        }
    EXPECT_TRUE(problems.isEmpty()) << joined(problems).toStdString();

    // A terminal that starts in Russian sizes its combo boxes to the Russian texts on first show.
    MainWindow startedInRussian(context);
    startedInRussian.resize(1280, 800);
    startedInRussian.show();
    QApplication::processEvents();
    const QStringList startProblems = fitProblems(startedInRussian, QStringLiteral("started in Russian"));
    EXPECT_TRUE(startProblems.isEmpty()) << joined(startProblems).toStdString();

    ASSERT_TRUE(language.apply(QStringLiteral("en")));
    QApplication::processEvents();
    EXPECT_EQ(settingsButton->text(), QStringLiteral("Settings"));
}

}  // namespace
}  // namespace tt::ui
