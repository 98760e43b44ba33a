// The Reports page (issue 12, item 3), offscreen in a 1280 × 800 main window, on a history written by the real
// `trueturn simulate` with a tolerance tighter than the scatter (h7 on 27 mm: good, rework and scrap parts): the
// chart, histogram, capability table, part profile and small multiples against core/quality's figures computed
// here from the readings straight from the history; the PDF, CSV and DFQ exports; screenshots in English and
// Russian.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QSpinBox>
#include <QSqlQuery>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <algorithm>
#include <set>

#include "core/quality/point_analysis.h"
#include "core/storage/database.h"
#include "english_words.h"
#include "plot/chart.h"
#include "reports/report_charts.h"
#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/reports_page.h"
#include "ui/reports/report_filter_bar.h"
#include "ui/reports/report_views.h"

namespace tt::ui {
namespace {

/// h7 on 27 mm is 27.000 / 26.979 mm (ISO 286-1: IT7 = 21 µm, h: upper deviation 0).
constexpr double kUpperMm = 27.000;
constexpr double kLowerMm = 26.979;

class ReportsPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        QFile preset(dir.filePath(QStringLiteral("h7.json")));
        ASSERT_TRUE(preset.open(QIODevice::WriteOnly));
        preset.write(R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"fit": "h7"}}})");
        preset.close();
        QProcess simulate;
        simulate.setProcessEnvironment(QProcessEnvironment::systemEnvironment());
        simulate.start(QStringLiteral(TRUETURN_EXE),
                       {"simulate", "--preset", preset.fileName(), "--parts", "150", "--warmup", "0", "--seed", "11",
                        "--machine", "lathe-7", "--db", context.databasePath, "--json"});
        ASSERT_TRUE(simulate.waitForFinished(tt::test::kPatientWaitMs));
        ASSERT_EQ(simulate.exitCode(), 0) << simulate.readAllStandardError().toStdString();
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }

    /// The plausible readings of point `point` (0-based) in part order, straight from the history.
    core::MeasuredSeries readings(int point) {
        storage::Database history(storage::DatabaseConfig::sqlite(context.databasePath));
        QSqlQuery q = history.exec(
            QStringLiteral("SELECT m.measured_mm, p.part_number FROM measurements m JOIN parts p ON p.id = m.part_id"
                           " WHERE m.point_index = ? AND m.measured_mm IS NOT NULL AND (m.reason_kind IS NULL OR"
                           " m.reason_kind <> 'implausible') ORDER BY p.part_number"),
            {point});
        core::MeasuredSeries s;
        while (q.next()) {
            s.valuesMm.push_back(q.value(0).toDouble());
            s.partNumbers.push_back(q.value(1).toLongLong());
            s.timesS.push_back(0.0);
        }
        return s;
    }

    /// The Reports page of a shown 1280 × 800 main window, its first analysis finished.
    ReportsPage* showReports(MainWindow& window) {
        window.resize(1280, 800);
        window.show();
        window.showPage(PageId::Reports);
        auto* page = qobject_cast<ReportsPage*>(window.page(PageId::Reports));
        EXPECT_NE(page, nullptr);
        if (!page) return nullptr;
        EXPECT_TRUE(QTest::qWaitFor([&] { return !page->busy() && !page->views()->points().empty(); },
                                    tt::test::kPatientWaitMs))
            << page->status()->text().toStdString();
        return page;
    }

    void analyseAgain(ReportsPage* page) {
        bool done = false;
        QObject::connect(page, &ReportsPage::analysed, page, [&] { done = true; });
        page->analyse();
        ASSERT_TRUE(QTest::qWaitFor([&] { return done; }, tt::test::kPatientWaitMs));
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
};

TEST_F(ReportsPageTest, ChartsAndCapabilityOfTheStoredRunAreCoreQualitysFigures) {
    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    ReportViews* views = page->views();
    ASSERT_EQ(views->points().size(), 5u);  // paper-2012-group1: five control points
    EXPECT_EQ(page->filterBar()->machines()->findText(QStringLiteral("lathe-7")), 1);

    for (int point = 0; point < 5; ++point) {
        // core/quality on the readings read here, against the stored h7 limits: I-MR (subgroup 1), limits from all.
        core::PointAnalysisSettings settings;
        settings.spec = core::SpecLimits{kLowerMm, kUpperMm, 27.0};
        const core::PointAnalysis expected = core::analysePoint(readings(point), settings);
        views->pointChoice()->setCurrentIndex(point);
        views->showPoint(point);
        const runtime::PointReport& shown = views->points()[static_cast<std::size_t>(point)];
        ASSERT_TRUE(shown.spec.has_value());
        EXPECT_NEAR(shown.spec->lowerMm, kLowerMm, 1e-9);
        EXPECT_NEAR(shown.spec->upperMm, kUpperMm, 1e-9);
        EXPECT_EQ(views->location()->pointCount(QStringLiteral("values")), static_cast<int>(expected.count));
        EXPECT_EQ(views->spread()->pointCount(QStringLiteral("values")), static_cast<int>(expected.count) - 1);
        EXPECT_EQ(views->location()->pointCount(QStringLiteral("ucl")), 2);
        std::set<std::size_t> violating;
        for (const core::PointViolation& v : expected.violations)
            violating.insert(v.violation.points.begin(), v.violation.points.end());
        EXPECT_EQ(views->location()->pointCount(QStringLiteral("violations")), static_cast<int>(violating.size()));
        EXPECT_GT(violating.size(), 0u) << "a process this far off centre breaks the Western Electric rules";
        // The capability table shows core's indices to two decimals, and the interval of Cpk.
        ASSERT_TRUE(expected.capability.has_value());
        const QTableWidget* table = views->capability();
        ASSERT_GE(table->rowCount(), 5);
        EXPECT_EQ(table->item(0, 1)->text(), QString::number(expected.capability->indices.cp, 'f', 2));
        EXPECT_EQ(table->item(1, 1)->text(), QString::number(expected.capability->indices.cpk, 'f', 2));
        EXPECT_EQ(table->item(3, 1)->text(), QString::number(expected.capability->indices.pp, 'f', 2));
        EXPECT_EQ(table->item(4, 1)->text(), QString::number(expected.capability->indices.ppk, 'f', 2));
        EXPECT_TRUE(table->item(1, 2)->text().contains(
            QString::number(expected.capability->indices.cpkInterval->lower, 'f', 2)));
        // The histogram holds every reading; the fitted normal and both limits are drawn.
        const reports::ReportHistogram h = reports::histogramOf(shown);
        double total = 0.0;
        for (double c : h.counts)
            total += c;
        EXPECT_EQ(total, static_cast<double>(expected.count));
        EXPECT_GT(views->histogram()->pointCount(QStringLiteral("normal")), 0);
        EXPECT_EQ(views->histogram()->pointCount(QStringLiteral("lsl")), 2);
        EXPECT_EQ(views->histogram()->pointCount(QStringLiteral("usl")), 2);
        // Tighter than the scatter: every verdict occurs.
        EXPECT_GT(shown.verdicts.good, 0);
        EXPECT_GT(shown.verdicts.rework, 0);
        EXPECT_GT(shown.verdicts.scrap, 0);
    }
    views->pointChoice()->setCurrentIndex(1);
    views->showPoint(1);
    views->tabs()->setCurrentIndex(0);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_chart_en")));
    views->tabs()->setCurrentIndex(1);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_capability_en")));

    // The profile of part 10: five diameters along the shaft inside the band.
    views->partChoice()->setValue(10);
    EXPECT_EQ(views->profile()->pointCount(QStringLiteral("measured")), 5);
    EXPECT_EQ(views->profile()->pointCount(QStringLiteral("tolerance")), 5);
    views->tabs()->setCurrentIndex(2);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_profile_en")));
    ASSERT_EQ(views->multiples().size(), 5u);
    for (const plot::Chart* chart : views->multiples())
        EXPECT_EQ(chart->pointCount(QStringLiteral("values")), 150);
    views->tabs()->setCurrentIndex(3);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_all_points_en")));

    // Subgroups of 5: X-bar-R of 30 subgroups, limits from the first 10 (phase I), held after.
    page->filterBar()->subgroup()->setValue(5);
    page->filterBar()->baseline()->setValue(10);
    analyseAgain(page);
    const core::ChartLimits& limits = views->points().front().analysis.chart.limits;
    EXPECT_EQ(limits.kind, core::ChartKind::XbarRange);
    EXPECT_EQ(limits.baselinePointCount, 10u);
    EXPECT_EQ(views->location()->pointCount(QStringLiteral("values")), 30);
    EXPECT_EQ(views->location()->pointCount(QStringLiteral("baseline")), 2);
    views->tabs()->setCurrentIndex(0);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_xbar_r_en")));
}

// The adaptive loop's controller changes on the control chart (issue "Adaptive control", item 5): a second run on a
// plant of twice the model's gain (`simulate --plant-gain 2`, the default action adapt) changes the controller; the
// chart marks every applied change from the command's own JSON at that part's chart point (after the first run's
// 150 readings), lists them under the rule violations, and the PDF prints them.
TEST_F(ReportsPageTest, MarksTheAdaptiveLoopsControllerChangesOnTheChart) {
    QProcess simulate;
    simulate.start(QStringLiteral(TRUETURN_EXE),
                   {"simulate", "--preset", "paper-2012", "--delay", "1", "--plant-gain", "2", "--parts", "400",
                    "--warmup", "0", "--seed", "1", "--machine", "lathe-7", "--db", context.databasePath, "--json"});
    ASSERT_TRUE(simulate.waitForFinished(tt::test::kPatientWaitMs));
    ASSERT_EQ(simulate.exitCode(), 0) << simulate.readAllStandardError().toStdString();
    std::vector<std::int64_t> changedAt;  // the parts where the controller changed, from the command's JSON
    for (const QJsonValue& a : QJsonDocument::fromJson(simulate.readAllStandardOutput())["adaptations"].toArray())
        if (a[QStringLiteral("applied")].toBool()) changedAt.push_back(a[QStringLiteral("part")].toInteger());
    ASSERT_GE(changedAt.size(), 2u) << "the fallback and the adapted LQG";

    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    ReportViews* views = page->views();
    for (int point = 0; point < 5; ++point) {
        views->showPoint(point);
        const runtime::PointReport& shown = views->points()[static_cast<std::size_t>(point)];
        ASSERT_EQ(shown.adaptations.size(), changedAt.size()) << "point " << point + 1;
        for (std::size_t i = 0; i < changedAt.size(); ++i) {
            const runtime::ChartAdaptation& mark = shown.adaptations[i];
            EXPECT_EQ(mark.runId, 2);
            EXPECT_EQ(mark.record.partNumber, changedAt[i]);
            EXPECT_GE(mark.chartPoint, 150u) << "after the first run's readings";
            EXPECT_EQ(shown.series.partNumbers[mark.chartPoint], changedAt[i]) << "I-MR: one chart point per part";
        }
        EXPECT_EQ(views->location()->pointCount(QStringLiteral("adaptations")), 3 * static_cast<int>(changedAt.size()));
    }
    const QString text = views->violations()->text();
    EXPECT_TRUE(text.contains(QStringLiteral("Controller changes (marked): %1").arg(changedAt.size())))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Run 2, part %1: EWMA fallback").arg(changedAt.front())))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral(": LQG adapted, delay z = 1\n"))) << text.toStdString();
    views->tabs()->setCurrentIndex(0);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_adaptations_en")));

    // Subgroups of 5: each mark on the subgroup that holds its part.
    page->filterBar()->subgroup()->setValue(5);
    analyseAgain(page);
    const runtime::PointReport& grouped = views->points().front();
    ASSERT_EQ(grouped.adaptations.size(), changedAt.size());
    for (const runtime::ChartAdaptation& mark : grouped.adaptations) {
        const auto reading = std::find(grouped.series.partNumbers.begin() + 150, grouped.series.partNumbers.end(),
                                       mark.record.partNumber);
        EXPECT_EQ(mark.chartPoint, static_cast<std::size_t>(reading - grouped.series.partNumbers.begin()) / 5);
    }
    const QString pdf = dir.filePath(QStringLiteral("adaptations.pdf"));
    EXPECT_TRUE(page->exportPdf(pdf));
    EXPECT_GT(QFileInfo(pdf).size(), 0);

    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    views->showPoint(0);
    const QStringList data{QStringLiteral("lathe-7"), QStringLiteral("I-MR"), QStringLiteral("EWMA"),
                           QStringLiteral("LQG"), QStringLiteral("WE")};
    EXPECT_TRUE(test::englishIn(views->violations(), data).isEmpty())
        << qPrintable(test::englishIn(views->violations(), data).join(QStringLiteral("; ")));
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_adaptations_ru")));
}

TEST_F(ReportsPageTest, ExportsPdfCsvAndDfq) {
    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    prompt.fileNames.push_back(pdf);
    window.findChild<QPushButton*>(QStringLiteral("reportExportPdf"))->click();
    QFile pdfFile(pdf);
    ASSERT_TRUE(pdfFile.open(QIODevice::ReadOnly)) << page->status()->text().toStdString();
    EXPECT_TRUE(pdfFile.read(5) == "%PDF-");

    std::size_t rows = page->views()->rows().size();
    for (const char* kind : {"csv", "dfq"}) {
        const QString path = dir.filePath(QStringLiteral("readings.") + QLatin1String(kind));
        prompt.fileNames.push_back(path);
        bool done = false;
        QObject::connect(page, &ReportsPage::exported, page, [&] { done = true; });
        auto* button = window.findChild<QPushButton*>(QLatin1String(kind) == QLatin1String("csv")
                                                          ? QStringLiteral("reportExportCsv")
                                                          : QStringLiteral("reportExportDfq"));
        ASSERT_NE(button, nullptr);
        button->click();
        ASSERT_TRUE(QTest::qWaitFor([&] { return done; }, tt::test::kPatientWaitMs));
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << page->status()->text().toStdString();
        const QList<QByteArray> lines = file.readAll().split('\n');
        if (QLatin1String(kind) == QLatin1String("csv")) {
            EXPECT_TRUE(lines.front().startsWith("run,machine,part,time,point"));
            EXPECT_EQ(static_cast<std::size_t>(lines.size()), rows + 2);  // header, rows, final newline
        } else {
            std::size_t values = 0;
            for (const QByteArray& line : lines)
                if (line.startsWith("K0001/")) ++values;
            EXPECT_EQ(values, rows);
            EXPECT_TRUE(lines.front().startsWith("K0100 5"));
        }
    }
}

// Cancel during the PDF export: the click is queued before the export starts and handled at its first
// progress call (the page keeps the window alive between pages), so no file is left behind.
TEST_F(ReportsPageTest, CancelledPdfExportLeavesNoFile) {
    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    const QString pdf = dir.filePath(QStringLiteral("cancelled.pdf"));
    QTimer::singleShot(0, page, [&] {
        auto* cancel = window.findChild<QPushButton*>(QStringLiteral("reportCancel"));
        ASSERT_TRUE(cancel && cancel->isVisible());
        cancel->click();
    });
    EXPECT_FALSE(page->exportPdf(pdf));
    EXPECT_FALSE(QFile::exists(pdf));
    EXPECT_EQ(page->status()->text(), QStringLiteral("Cancelled."));
    EXPECT_FALSE(page->busy());
    EXPECT_TRUE(page->exportPdf(pdf));  // and it works again
    EXPECT_TRUE(QFile::exists(pdf));
}

TEST_F(ReportsPageTest, TheStatusLineFollowsALanguageSwitch) {
    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    ASSERT_TRUE(page->exportPdf(pdf));
    EXPECT_EQ(page->status()->text().toStdString(), (QStringLiteral("Written: ") + pdf).toStdString());
    // Before, the line kept the language the work ended in.
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QApplication::processEvents();
    EXPECT_EQ(page->status()->text().toStdString(), (QStringLiteral("Записано: ") + pdf).toStdString());
    ASSERT_TRUE(language.apply(QStringLiteral("en")));
    QApplication::processEvents();
    EXPECT_EQ(page->status()->text().toStdString(), (QStringLiteral("Written: ") + pdf).toStdString());
}

TEST_F(ReportsPageTest, RussianShowsNoEnglish) {
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    MainWindow window(context);
    ReportsPage* page = showReports(window);
    ASSERT_NE(page, nullptr);
    // Standard codes and the machine's name stay as they are: I-MR, X-bar, the Western Electric rule codes
    // (WE1..WE4) and the file formats.
    const QStringList data{QStringLiteral("lathe-7"), QStringLiteral("I-MR"), QStringLiteral("PDF"),
                           QStringLiteral("CSV"),     QStringLiteral("DFQ"),  QStringLiteral("WE")};
    for (int tab = 0; tab < 4; ++tab) {
        page->views()->tabs()->setCurrentIndex(tab);
        QApplication::processEvents();
        EXPECT_TRUE(test::englishIn(page, data).isEmpty())
            << "tab " << tab << ": " << qPrintable(test::englishIn(page, data).join(QStringLiteral("; ")));
    }
    page->views()->tabs()->setCurrentIndex(0);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_chart_ru")));
    page->views()->tabs()->setCurrentIndex(1);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_capability_ru")));
    page->views()->tabs()->setCurrentIndex(3);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("reports_all_points_ru")));
    EXPECT_LE(window.minimumSizeHint().width(), 1280);
    EXPECT_LE(window.minimumSizeHint().height(), 800);
}

}  // namespace
}  // namespace tt::ui
