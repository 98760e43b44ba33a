#include <gtest/gtest.h>

#include <QJsonArray>
#include <cmath>
#include <vector>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

// Table 1 of the 2012 shaft paper (shared/SEEDS.md, section 000), group 1: d(x) in mm, x in mm.
const std::vector<double> kGroupOne = {0.071, -0.000132, 2.379e-5, -2.09e-7, 6.42e-10, -6.6e-13};

double groupOne(double x) {
    double sum = 0.0;
    for (std::size_t k = kGroupOne.size(); k-- > 0;)
        sum = sum * x + kGroupOne[k];
    return sum;
}

class FitProfileCommand : public tt::test::CliTest {};

TEST_F(FitProfileCommand, RecoversTableOneGroupOneAsJson) {
    QByteArray csv = "x_mm,error_mm\n";
    for (int i = 0; i <= 13; ++i)  // every 25 mm along the 325 mm shaft, as the paper gauged
        csv += QByteArray::number(25.0 * i, 'g', 17) + ',' + QByteArray::number(groupOne(25.0 * i), 'g', 17) + '\n';
    const CliResult r = runTrueturn({QStringLiteral("fit-profile"), write(QStringLiteral("group1.csv"), csv),
                                     QStringLiteral("--degree"), QStringLiteral("5"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(j.value(QStringLiteral("degree")).toInt(), 5);
    EXPECT_EQ(j.value(QStringLiteral("n")).toInt(), 14);
    const QJsonArray b = j.value(QStringLiteral("coefficients")).toArray();
    ASSERT_EQ(b.size(), 6);
    for (int k = 0; k < 6; ++k)
        EXPECT_LT(std::abs(b.at(k).toDouble() - kGroupOne[static_cast<std::size_t>(k)]) /
                      std::abs(kGroupOne[static_cast<std::size_t>(k)]),
                  1e-9)
            << "b" << k;
    EXPECT_NEAR(j.value(QStringLiteral("r2")).toDouble(), 1.0, 1e-12);
    for (const char* key : {"r2_adj", "f", "f_critical", "sigma_resid"})
        EXPECT_TRUE(j.contains(QLatin1String(key))) << key;
    // F(0.95; 5, 8) = 3.69 (upper 5 % points of the F distribution, NIST/SEMATECH e-Handbook 1.3.6.7.3).
    EXPECT_NEAR(j.value(QStringLiteral("f_critical")).toDouble(), 3.687, 1e-3);
    // The printed polynomial peaks at about 0.156 mm near x = 140 mm (SEEDS.md, section 000).
    const QJsonObject peak = j.value(QStringLiteral("peak")).toObject();
    EXPECT_NEAR(peak.value(QStringLiteral("error_mm")).toDouble(), 0.156, 1e-3);
    EXPECT_NEAR(peak.value(QStringLiteral("x_mm")).toDouble(), 140.0, 3.0);
}

TEST_F(FitProfileCommand, AutoDegreeReportsEveryCandidateAndTextIsReadable) {
    // Three parts gauged at the same positions with a fixed +-0.004 mm part-to-part offset pattern.
    QByteArray csv = "  x_mm ,  error_mm  \r\n# three parts of group 1\r\n\r\n";
    const double offset[3] = {-0.004, 0.001, 0.003};
    for (int part = 0; part < 3; ++part)
        for (int i = 0; i <= 13; ++i)
            csv += QByteArray::number(25.0 * i) + " ,  " +
                   QByteArray::number(groupOne(25.0 * i) + offset[part] * ((i % 3) - 1), 'g', 12) + "\r\n";
    const QString path = write(QStringLiteral("parts.csv"), csv);
    const CliResult r = runTrueturn({QStringLiteral("fit-profile"), path, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(j.value(QStringLiteral("n")).toInt(), 42);
    EXPECT_EQ(j.value(QStringLiteral("degree_choice")).toString(), QStringLiteral("auto"));
    EXPECT_EQ(j.value(QStringLiteral("selection")).toArray().size(), 6);
    EXPECT_GE(j.value(QStringLiteral("degree")).toInt(), 4);

    const CliResult text = runTrueturn({QStringLiteral("fit-profile"), path});
    ASSERT_EQ(text.exitCode, 0) << qPrintable(text.err);
    EXPECT_TRUE(text.out.contains(QStringLiteral("42 points")));
    EXPECT_TRUE(text.out.contains(QStringLiteral("<- chosen")));
    EXPECT_TRUE(text.out.contains(QStringLiteral("R² ")));
    EXPECT_TRUE(text.out.contains(QStringLiteral("Residual sigma")));
    EXPECT_TRUE(text.out.contains(QStringLiteral("y_ff(x) = -d(x)/2")));
}

TEST_F(FitProfileCommand, TableOnePresetsShowTheirPeaks) {
    // Table 1 groups as built-in presets; the printed polynomials peak at about 0.156, 0.104 and
    // 0.206 mm near x = 140 mm (shared/SEEDS.md, section 000).
    const double peaks[3] = {0.156, 0.104, 0.206};
    for (int g = 1; g <= 3; ++g) {
        const CliResult r = runTrueturn({QStringLiteral("fit-profile"), QStringLiteral("--preset"),
                                         QStringLiteral("paper-2012-table1-group%1").arg(g), QStringLiteral("--json")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        const QJsonObject j = r.json();
        EXPECT_EQ(j.value(QStringLiteral("degree")).toInt(), 5);
        EXPECT_EQ(j.value(QStringLiteral("part_length_mm")).toDouble(), 325.0);
        const QJsonObject peak = j.value(QStringLiteral("peak")).toObject();
        EXPECT_NEAR(peak.value(QStringLiteral("error_mm")).toDouble(), peaks[g - 1], 1e-3) << "group " << g;
        EXPECT_NEAR(peak.value(QStringLiteral("x_mm")).toDouble(), 140.0, 3.0) << "group " << g;
        EXPECT_NEAR(j.value(QStringLiteral("feed_forward_at_peak_mm")).toDouble(), -peaks[g - 1] / 2.0, 1e-3);
    }
    const CliResult group1 = runTrueturn({QStringLiteral("fit-profile"), QStringLiteral("--preset"),
                                          QStringLiteral("paper-2012-table1-group1"), QStringLiteral("--json")});
    const QJsonArray b = group1.json().value(QStringLiteral("coefficients")).toArray();
    ASSERT_EQ(b.size(), 6);
    for (int k = 0; k < 6; ++k)
        EXPECT_EQ(b.at(k).toDouble(), kGroupOne[static_cast<std::size_t>(k)]) << "b" << k;
}

TEST_F(FitProfileCommand, SavedFitReadsBackAsAPreset) {
    QByteArray csv = "x_mm,error_mm\n";
    for (int i = 0; i <= 13; ++i)
        csv += QByteArray::number(25.0 * i) + ',' +
               QByteArray::number(groupOne(25.0 * i) + 0.003 * ((i * 7) % 5 - 2) / 2.0, 'g', 12) + '\n';
    const QString saved = m_dir.filePath(QStringLiteral("shaft.json"));
    const CliResult fit =
        runTrueturn({QStringLiteral("fit-profile"), write(QStringLiteral("shaft.csv"), csv), QStringLiteral("--degree"),
                     QStringLiteral("5"), QStringLiteral("--save"), saved, QStringLiteral("--json")});
    ASSERT_EQ(fit.exitCode, 0) << qPrintable(fit.err);
    const CliResult shown =
        runTrueturn({QStringLiteral("fit-profile"), QStringLiteral("--preset"), saved, QStringLiteral("--json")});
    ASSERT_EQ(shown.exitCode, 0) << qPrintable(shown.err);
    const QJsonArray fitted = fit.json().value(QStringLiteral("coefficients")).toArray();
    const QJsonArray stored = shown.json().value(QStringLiteral("coefficients")).toArray();
    ASSERT_EQ(stored.size(), fitted.size());
    for (int k = 0; k < fitted.size(); ++k)
        EXPECT_EQ(stored.at(k).toDouble(), fitted.at(k).toDouble()) << "b" << k;
    EXPECT_EQ(shown.json().value(QStringLiteral("part_length_mm")).toDouble(), 325.0);
    const QJsonObject peakFit = fit.json().value(QStringLiteral("peak")).toObject();
    const QJsonObject peakShown = shown.json().value(QStringLiteral("peak")).toObject();
    EXPECT_NEAR(peakShown.value(QStringLiteral("x_mm")).toDouble(), peakFit.value(QStringLiteral("x_mm")).toDouble(),
                1e-9);
}

TEST_F(FitProfileCommand, BadRowsAreNamedByLineNumber) {
    expectRefused(
        {QStringLiteral("fit-profile"), write(QStringLiteral("a.csv"), "x_mm,error_mm\n0,0.1\n25,0.12\n50,abc\n")},
        QStringLiteral("line 4: error_mm 'abc' is not a number"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("b.csv"), "x_mm,error_mm\n0,0.1\nNaN,0.12\n")},
                  QStringLiteral("line 3: x_mm 'NaN' is not a finite number"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("c.csv"), "x_mm,error_mm\n0,0.1\n25\n")},
                  QStringLiteral("line 3: missing the error_mm column"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("d.csv"), "x_mm,error_mm\n0,0.1\n25,0,13\n")},
                  QStringLiteral("line 3: 3 columns"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("e.csv"), "x;error\n0;0.1\n")},
                  QStringLiteral("line 1: expected the header 'x_mm,error_mm'"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("f.csv"), "x_mm,error_mm\n0,\n")},
                  QStringLiteral("line 2: the error_mm value is empty"));
}

TEST_F(FitProfileCommand, DataThatCannotCarryTheModelAreRefused) {
    expectRefused({QStringLiteral("fit-profile"),
                   write(QStringLiteral("few.csv"), "x_mm,error_mm\n0,0.1\n25,0.12\n50,0.15\n75,0.13\n"),
                   QStringLiteral("--degree"), QStringLiteral("5")},
                  QStringLiteral("degree 5 needs at least 7 points"));
    expectRefused({QStringLiteral("fit-profile"),
                   write(QStringLiteral("same.csv"), "x_mm,error_mm\n100,0.1\n100,0.12\n100,0.15\n100,0.13\n")},
                  QStringLiteral("same position"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("header.csv"), "x_mm,error_mm\n")},
                  QStringLiteral("no data rows"));
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("empty.csv"), "")}, QStringLiteral("empty"));
}

TEST_F(FitProfileCommand, BadArgumentsAreRefused) {
    const QString ok = write(QStringLiteral("ok.csv"), "x_mm,error_mm\n0,0.1\n25,0.12\n50,0.15\n75,0.13\n");
    expectRefused({QStringLiteral("fit-profile"), ok, QStringLiteral("--degree"), QStringLiteral("7")},
                  QStringLiteral("--degree"));
    expectRefused({QStringLiteral("fit-profile"), ok, QStringLiteral("--degree"), QStringLiteral("five")},
                  QStringLiteral("or 'auto'"));
    expectRefused({QStringLiteral("fit-profile"), m_dir.filePath(QStringLiteral("missing.csv"))},
                  QStringLiteral("cannot read"));
    expectRefused({QStringLiteral("fit-profile")}, QStringLiteral("missing FILE.csv"));
    expectRefused({QStringLiteral("fit-profile"), QStringLiteral("--preset"), QStringLiteral("no-such-preset")},
                  QStringLiteral("unknown preset"));
    expectRefused(
        {QStringLiteral("fit-profile"), ok, QStringLiteral("--preset"), QStringLiteral("paper-2012-table1-group1")},
        QStringLiteral("without FILE.csv"));
    const QString noModel = write(QStringLiteral("nomodel.json"), R"({"name": "x", "description": "y"})");
    expectRefused({QStringLiteral("fit-profile"), QStringLiteral("--preset"), noModel},
                  QStringLiteral("no \"systematic_model\" section"));
}

}  // namespace
