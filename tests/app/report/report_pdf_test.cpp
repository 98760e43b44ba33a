// `trueturn report --pdf` and the chart choice (issue 12, item 4): the PDF has a title page and one page per
// control point (pdfinfo), each page names its point (pdftotext), the pages are rendered to PNG in
// <build>/screenshots for a person to look at (pdftoppm); --subgroup picks X-bar-R up to 10 and X-bar-s above,
// --chart chooses, --baseline holds the limits of the first subgroups (textbook constants recomputed here).
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSqlQuery>
#include <QStandardPaths>
#include <algorithm>
#include <vector>

#include "cli_test.h"
#include "core/storage/database.h"
#include "tests/support/patient_wait.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

/// Runs a poppler tool; fails the test when it is not installed (scripts/install-deps.sh --with-test-tools).
QString poppler(const QString& tool, const QStringList& args) {
    const QString program = QStandardPaths::findExecutable(tool);
    EXPECT_FALSE(program.isEmpty()) << qPrintable(tool) << " not found: apt-get install poppler-utils";
    if (program.isEmpty()) return {};
    QProcess p;
    p.start(program, args);
    EXPECT_TRUE(p.waitForFinished(tt::test::kPatientWaitMs));
    EXPECT_EQ(p.exitCode(), 0) << qPrintable(QString::fromUtf8(p.readAllStandardError()));
    return QString::fromUtf8(p.readAllStandardOutput());
}

class ReportPdfTest : public test::CliTest {
protected:
    /// 150 parts of paper-2012-group1 judged against h7 (tighter than the scatter), tagged with a machine.
    QString history() {
        const QString preset =
            write("h7.json", R"({"based_on": "paper-2012-group1", "loop": {"tolerance": {"fit": "h7"}}})");
        const QString db = path("history.sqlite");
        const CliResult r = runTrueturn({"simulate", "--preset", preset, "--parts", "150", "--warmup", "0", "--seed",
                                         "11", "--machine", "lathe-7", "--db", db, "--json"});
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return db;
    }

    std::vector<double> readings(const QString& db, int point) {
        storage::Database history(storage::DatabaseConfig::sqlite(db));
        QSqlQuery q = history.exec(
            QStringLiteral("SELECT m.measured_mm FROM measurements m JOIN parts p ON p.id = m.part_id"
                           " WHERE m.point_index = ? AND m.measured_mm IS NOT NULL AND (m.reason_kind IS NULL OR"
                           " m.reason_kind <> 'implausible') ORDER BY p.part_number"),
            {point - 1});
        std::vector<double> values;
        while (q.next())
            values.push_back(q.value(0).toDouble());
        return values;
    }
};

TEST_F(ReportPdfTest, TitlePageAndOnePagePerControlPoint) {
    const QString db = history();
    const QString pdf = path("report.pdf");
    const CliResult r = runTrueturn({"report", "--db", db, "--pdf", pdf, "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.isEmpty()) << "the offscreen application says nothing: " << qPrintable(r.err);
    const qsizetype points = r.json()["points"].toArray().size();
    ASSERT_EQ(points, 5);  // paper-2012-group1 has five control points

    QFile file(pdf);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.read(5) == "%PDF-");
    const QString info = poppler(QStringLiteral("pdfinfo"), {pdf});
    const QRegularExpressionMatch pages = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(info);
    ASSERT_TRUE(pages.hasMatch()) << qPrintable(info);
    EXPECT_EQ(pages.captured(1).toInt(), points + 1);
    EXPECT_TRUE(info.contains(QStringLiteral("A4"))) << qPrintable(info);

    // Page 1: the title block; page i + 1: control point i.
    const QString title = poppler(QStringLiteral("pdftotext"), {"-f", "1", "-l", "1", pdf, "-"});
    EXPECT_TRUE(title.contains(QStringLiteral("Quality report"))) << qPrintable(title);
    EXPECT_TRUE(title.contains(QStringLiteral("Machine: lathe-7"))) << qPrintable(title);
    EXPECT_TRUE(title.contains(QStringLiteral("Job: h7.json"))) << qPrintable(title);
    EXPECT_TRUE(title.contains(QStringLiteral("Signature"))) << qPrintable(title);
    for (int i = 1; i <= points; ++i) {
        const QString page = QString::number(i + 1);
        const QString text = poppler(QStringLiteral("pdftotext"), {"-f", page, "-l", page, pdf, "-"});
        EXPECT_TRUE(text.contains(QStringLiteral("Point %1 at x =").arg(i))) << qPrintable(text);
        EXPECT_TRUE(text.contains(QStringLiteral("Cpk"))) << qPrintable(text);
        EXPECT_TRUE(text.contains(QStringLiteral("Moving ranges"))) << qPrintable(text);
    }

    // The pages as PNG, for a person to look at.
    const QString shots = QStringLiteral(TRUETURN_BINARY_DIR "/screenshots");
    QDir().mkpath(shots);
    poppler(QStringLiteral("pdftoppm"), {"-r", "80", "-png", pdf, shots + QStringLiteral("/report_pdf_page")});
    EXPECT_TRUE(QFile::exists(shots + QStringLiteral("/report_pdf_page-1.png")));
}

TEST_F(ReportPdfTest, SubgroupSizePicksRangeOrStandardDeviationAndChartChooses) {
    const QString db = history();
    const auto chartOf = [&](const QStringList& extra) {
        const CliResult r = runTrueturn(QStringList{"report", "--db", db, "--point", "1", "--json"} + extra);
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return r.json()["chart"].toString();
    };
    EXPECT_EQ(chartOf({}), QStringLiteral("I-MR"));
    EXPECT_EQ(chartOf({"--subgroup", "10"}), QStringLiteral("X-bar-R"));
    EXPECT_EQ(chartOf({"--subgroup", "11"}), QStringLiteral("X-bar-s"));
    EXPECT_EQ(chartOf({"--subgroup", "5", "--chart", "xbar-s"}), QStringLiteral("X-bar-s"));
    EXPECT_EQ(chartOf({"--subgroup", "12", "--chart", "xbar-r"}), QStringLiteral("X-bar-R"));
    test::expectRefused({"report", "--db", db, "--subgroup", "5", "--chart", "imr"}, QStringLiteral("subgroup size"));
    test::expectRefused({"report", "--db", db, "--chart", "xbar-r"}, QStringLiteral("X-bar chart"));
    test::expectRefused({"report", "--db", db, "--chart", "pareto"}, QStringLiteral("--chart"));
}

TEST_F(ReportPdfTest, BaselineHoldsTheLimitsOfTheFirstSubgroups) {
    const QString db = history();
    const CliResult r =
        runTrueturn({"report", "--db", db, "--point", "2", "--subgroup", "5", "--baseline", "8", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject limits = r.json()["points"].toArray()[0].toObject()["limits"].toObject();
    // Phase I by hand from the first 8 subgroups of 5 (40 parts): X-bar-R with A2 = 0.577, D4 = 2.114, D3 = 0
    // (Montgomery, Introduction to Statistical Quality Control, 6th ed., Appendix VI).
    const std::vector<double> v = readings(db, 2);
    ASSERT_GE(v.size(), 40u);
    double grand = 0.0, rangeSum = 0.0;
    for (int k = 0; k < 8; ++k) {
        const auto first = v.begin() + 5 * k;
        double sum = 0.0;
        for (auto it = first; it != first + 5; ++it)
            sum += *it;
        grand += sum / 5.0;
        const auto [lo, hi] = std::minmax_element(first, first + 5);
        rangeSum += *hi - *lo;
    }
    grand /= 8.0;
    const double rBar = rangeSum / 8.0;
    // Tolerance: the table constants have 3 decimals (A2 = 0.5768 exactly), so 1e-3 of R-bar.
    EXPECT_NEAR(limits["centre"].toDouble(), grand, 1e-9);
    EXPECT_NEAR(limits["ucl"].toDouble(), grand + 0.577 * rBar, 1e-3 * rBar);
    EXPECT_NEAR(limits["lcl"].toDouble(), grand - 0.577 * rBar, 1e-3 * rBar);
    EXPECT_NEAR(limits["r_centre"].toDouble(), rBar, 1e-9);
    EXPECT_NEAR(limits["r_ucl"].toDouble(), 2.114 * rBar, 1e-3 * rBar);
    // Phase II: the limits differ from those of all 30 subgroups.
    const CliResult all = runTrueturn({"report", "--db", db, "--point", "2", "--subgroup", "5", "--json"});
    EXPECT_NE(all.json()["points"].toArray()[0].toObject()["limits"].toObject()["centre"].toDouble(),
              limits["centre"].toDouble());
    test::expectRefused({"report", "--db", db, "--subgroup", "5", "--baseline", "31"}, QStringLiteral("baseline"));
}

}  // namespace
}  // namespace tt
