// The Plant page, offscreen in a 1280 x 800 main window, on a plant history of four lathes: three that made parts
// for the last ten hours (one whose terminal reports, one whose terminal went silent) and one running now with an
// open alarm. The states, backlog and capability shown are the overview's; a click on a machine opens the Reports
// page with that machine's reports; the page reads in a worker and again every 10 s while shown. Screenshots in
// English and Russian.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDateTime>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "core/storage/synthetic_history.h"
#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/plant_page.h"
#include "ui/pages/reports_page.h"
#include "ui/plant/plant_model.h"
#include "ui/reports/report_filter_bar.h"

namespace tt::ui {
namespace {

class PlantPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        const QDateTime now = QDateTime::currentDateTimeUtc();
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        db.migrate(storage::historySchema());
        storage::SyntheticHistorySpec spec;
        spec.parts = 1500;
        spec.machines = 3;
        spec.runs = 3;
        spec.machinesInParallel = true;
        spec.firstPartEpochS = now.addSecs(-600 * 60).toSecsSinceEpoch();
        storage::writeSyntheticHistory(db, spec);
        const auto reported = [&db](const char* machine, const QDateTime& at, int backlog) {
            db.exec(QStringLiteral("INSERT INTO plant_terminal_status (machine, reported_at, backlog_parts,"
                                   " journal_bytes, journal_limit_bytes) VALUES (?, ?, ?, 1000000, 1073741824)"),
                    {QString::fromLatin1(machine), at.toString(Qt::ISODateWithMs), backlog});
        };
        reported("lathe-2", now, 17);
        reported("lathe-3", now.addSecs(-600), 230);
        storage::SqlHistoryStore history(db);
        const std::int64_t run = history.beginRun({"paper-2012", "lqg", 1, 27.0, 325.0, {0.0, 100.0}, "{}", "lathe-4"});
        core::PartCompletionRecord part;
        part.partNumber = 1;
        part.corrections = {{0, 0.0, 0.0, 0.0}, {1, 100.0, 0.0, 0.0}};
        history.recordPart(run, part);
        history.recordAlarm(run, {1, 10.0, "gauge-silent", "the gauge is not ready"});
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }

    PlantPage* showPlant(MainWindow& window) {
        window.resize(1280, 800);
        window.show();
        auto* page = dynamic_cast<PlantPage*>(window.page(PageId::Plant));
        EXPECT_NE(page, nullptr);
        QSignalSpy refreshed(page, &PlantPage::refreshed);
        window.showPage(PageId::Plant);
        EXPECT_TRUE(page->busy()) << "the page reads in a worker, the window stays responsive";
        EXPECT_TRUE(refreshed.wait(30000));
        return page;
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("plant.sqlite")), &devices};
};

TEST_F(PlantPageTest, ShowsEveryMachineWithItsStateAndCapabilityAndOpensItsReports) {
    MainWindow window(context);
    PlantPage* page = showPlant(window);
    PlantModel* model = page->model();
    ASSERT_EQ(model->rowCount(), 4);
    EXPECT_EQ(model->machineAt(0), QStringLiteral("lathe-1"));
    const auto cell = [model](int row, int column) { return model->index(row, column).data().toString(); };
    EXPECT_TRUE(cell(0, PlantModel::State).startsWith(QStringLiteral("idle, last part"))) << qPrintable(cell(0, 1));
    EXPECT_TRUE(cell(1, PlantModel::State).startsWith(QStringLiteral("idle"))) << qPrintable(cell(1, 1));
    EXPECT_EQ(cell(1, PlantModel::Backlog), QStringLiteral("17"));
    EXPECT_TRUE(cell(2, PlantModel::State).startsWith(QStringLiteral("offline"))) << qPrintable(cell(2, 1));
    EXPECT_EQ(cell(2, PlantModel::Backlog), QStringLiteral("230"));
    EXPECT_EQ(cell(3, PlantModel::State), QStringLiteral("running"));
    EXPECT_EQ(cell(3, PlantModel::Alarms), QStringLiteral("1"));
    EXPECT_EQ(model->pointColumns(), 5);
    // Capability of the last 125 parts, with its change against the 125 before.
    const runtime::PlantMachine& lathe1 = model->overview().machines.front();
    ASSERT_EQ(lathe1.points.size(), 5u);
    ASSERT_TRUE(lathe1.points[0].cpk && lathe1.points[0].cpkBefore);
    EXPECT_TRUE(cell(0, PlantModel::kFirstPointColumn).startsWith(QString::number(*lathe1.points[0].cpk, 'f', 2)));
    EXPECT_TRUE(cell(0, PlantModel::kFirstPointColumn).contains(*lathe1.points[0].change() >= 0 ? u'▲' : u'▼'));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("plant_page_en")));

    // One click on lathe-2: the Reports page with lathe-2's reports.
    auto* reports = dynamic_cast<ReportsPage*>(window.page(PageId::Reports));
    ASSERT_NE(reports, nullptr);
    QSignalSpy analysed(reports, &ReportsPage::analysed);
    QTableView* table = page->table();
    const QRect row = table->visualRect(model->index(1, PlantModel::Machine));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, row.center());
    EXPECT_EQ(window.currentPage(), PageId::Reports);
    EXPECT_EQ(reports->filterBar()->machines()->currentData().toString(), QStringLiteral("lathe-2"));
    EXPECT_TRUE(analysed.wait(60000));
    EXPECT_EQ(reports->filterBar()->filter().machine, std::optional<std::string>("lathe-2"));
}

TEST_F(PlantPageTest, ReadsAgainEveryTenSecondsWhileShownAndSpeaksRussian) {
    MainWindow window(context);
    PlantPage* page = showPlant(window);
    EXPECT_EQ(page->refreshMs(), 10000);
    page->setRefreshMs(300);  // the test does not wait 10 s
    // A new machine appears without anyone asking.
    {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        storage::SqlHistoryStore(db).beginRun({"paper-2012", "lqg", 1, 27.0, 325.0, {0.0}, "{}", "lathe-5"});
    }
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->model()->rowCount() == 5; }, 30000));
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QApplication::processEvents();
    EXPECT_EQ(page->model()->headerData(PlantModel::Machine, Qt::Horizontal).toString(), QStringLiteral("Станок"));
    EXPECT_EQ(page->model()->index(3, PlantModel::State).data().toString(), QStringLiteral("работает"));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("plant_page_ru")));
}

}  // namespace
}  // namespace tt::ui
