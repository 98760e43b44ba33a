// The Measurements page reads the run history: every part and control point with accepted/rejected
// and the reason.
#include "ui/pages/measurements_page.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QTableView>
#include <QTemporaryDir>

#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/run/measurements_model.h"

namespace tt::ui {
namespace {

class MeasurementsPageTest : public ::testing::Test {
protected:
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite"))};

    /// A run of 12 parts on 5 points; part 4 point 3 rejected (typing error), part 9 not measured at point 5.
    void record() {
        storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
        storage::SqlHistoryStore store(db);
        const std::vector<double> z = {0.0, 27.5, 162.5, 262.5, 325.0};
        const std::int64_t run = store.beginRun({"paper-2012-group1", "lqg", 2, 27.0, 325.0, z, "{}"});
        for (std::int64_t k = 1; k <= 12; ++k) {
            core::PartCompletionRecord part;
            part.partNumber = k;
            part.finishedS = 360.0 * static_cast<double>(k);
            for (int i = 0; i < 5; ++i)
                part.corrections.push_back({i, z[static_cast<std::size_t>(i)], -0.07, -0.07});
            part.controllerState = {"lqg", {1.0}};
            store.recordPart(run, part);
            core::PartMeasurementRecord m{k, part.finishedS + 45.0, {}};
            for (int i = 0; i < 5; ++i)
                m.points.push_back(
                    {i, z[static_cast<std::size_t>(i)], 27.0 + 0.001 * static_cast<double>(k + i), 27.0, true, ""});
            if (k == 4) {
                m.points[2].measuredMm = 2.7013;
                m.points[2].accepted = false;
                m.points[2].reason =
                    "rejected: reading 2.701 mm is more than 0.500 mm from the nominal 27.000 mm; check the point "
                    "(x = 162.500 mm) and measure again";
            }
            if (k == 9) {
                m.points[4].measuredMm.reset();
                m.points[4].accepted = false;
                m.points[4].reason = "not measured: skipped by the operator";
            }
            store.recordMeasurement(run, m);
        }
    }
};

TEST_F(MeasurementsPageTest, ShowsEveryMeasuredPointWithItsVerdictAndReason) {
    record();
    MeasurementsPage page(context);
    page.resize(1280, 720);
    page.show();  // refreshes
    ASSERT_EQ(page.runs()->count(), 1);
    EXPECT_TRUE(page.runs()->itemText(0).contains(QStringLiteral("12 parts")));
    // The stored "lqg" and "running" in the operator's words: the run was never finished.
    EXPECT_TRUE(page.runs()->itemText(0).contains(QStringLiteral("LQG, z = 2")))
        << page.runs()->itemText(0).toStdString();
    EXPECT_TRUE(page.runs()->itemText(0).endsWith(QStringLiteral("not finished")));
    MeasurementsModel* model = page.model();
    ASSERT_EQ(model->rowCount(), 60);
    EXPECT_EQ(model->problemCount(), 2);
    // Part 4, point 3 (row 3 * 5 + 2).
    EXPECT_EQ(model->index(17, MeasurementsModel::Part).data().toLongLong(), 4);
    EXPECT_EQ(model->index(17, MeasurementsModel::Measured).data().toString(), QStringLiteral("2.701"));
    EXPECT_EQ(model->index(17, MeasurementsModel::Verdict).data().toString(), QStringLiteral("rejected"));
    EXPECT_TRUE(model->index(17, MeasurementsModel::Reason).data().toString().contains(QStringLiteral("nominal")));
    EXPECT_EQ(model->index(17, MeasurementsModel::Applied).data().toString(), QStringLiteral("-0.0700"));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("measurements_page")));

    page.findChild<QCheckBox*>(QStringLiteral("onlyProblemsCheck"))->setChecked(true);
    ASSERT_EQ(model->rowCount(), 2);
    EXPECT_EQ(model->index(1, MeasurementsModel::Verdict).data().toString(), QStringLiteral("not measured"));
    EXPECT_EQ(model->index(1, MeasurementsModel::Measured).data().toString(), QStringLiteral("—"));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("measurements_page_problems")));
}

TEST_F(MeasurementsPageTest, AnEmptyHistorySaysWhatWillAppear) {
    MeasurementsPage page(context);
    page.show();
    EXPECT_EQ(page.runs()->count(), 0);
    EXPECT_EQ(page.model()->rowCount(), 0);
    EXPECT_FALSE(page.findChild<QTableView*>(QStringLiteral("measurementTable"))->isVisible());
}

}  // namespace
}  // namespace tt::ui
