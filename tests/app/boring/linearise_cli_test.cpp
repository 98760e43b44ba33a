// `trueturn linearise` on the real binary (issue 6, item 7 and "Done when").
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <cmath>
#include <random>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

// A known degree-3 characteristic of a 12-bit mandrel: code = 2047.5 + 3 d + 2e-4 d² + 3e-6 d³
// (d in µm), increasing everywhere (3 · 3 · 3e-6 > (2e-4)² / ... : its derivative has no real root).
double cubic(double um) {
    return 2047.5 + 3.0 * um + 2.0e-4 * um * um + 3.0e-6 * um * um * um;
}

// The true deflection at a code, by bisection.
double inverse(double code) {
    double lo = -2000.0, hi = 2000.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (cubic(mid) < code ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

class LineariseCommand : public tt::test::CliTest {
protected:
    /// 41 points over ±500 µm with ADC noise of 1.5 codes RMS.
    QString noisyCubic(double (*code)(double) = cubic) {
        std::mt19937_64 rng(42);
        std::normal_distribution<double> noise(0.0, 1.5);
        QByteArray csv = "reference_um,adc_code\n";
        for (int i = 0; i <= 40; ++i) {
            const double um = -500.0 + 25.0 * i;
            csv += QByteArray::number(um) + ',' + QByteArray::number(code(um) + noise(rng), 'f', 2) + '\n';
        }
        return write(QStringLiteral("points.csv"), csv);
    }
};

TEST_F(LineariseCommand, RecoversAKnownCubicAndPicksDegreeThree) {
    const QString table = m_dir.filePath(QStringLiteral("table.csv"));
    const CliResult r = runTrueturn({QStringLiteral("linearise"), noisyCubic(), QStringLiteral("--adc-bits"),
                                     QStringLiteral("12"), QStringLiteral("--degree"), QStringLiteral("auto"),
                                     QStringLiteral("--out"), table, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(j.value(QStringLiteral("degree")).toInt(), 3);
    EXPECT_EQ(j.value(QStringLiteral("degree_choice")).toString(), QStringLiteral("auto"));
    EXPECT_TRUE(j.value(QStringLiteral("monotonic")).toBool());
    EXPECT_EQ(j.value(QStringLiteral("entries")).toInt(), 4096);
    const QJsonArray c = j.value(QStringLiteral("coefficients")).toArray();
    ASSERT_EQ(c.size(), 4);
    EXPECT_NEAR(c[1].toDouble(), 3.0, 0.01);
    EXPECT_NEAR(c[3].toDouble(), 3.0e-6, 5e-8);
    EXPECT_LT(j.value(QStringLiteral("rms_residual_um")).toDouble(), 1.0);
    EXPECT_LT(j.value(QStringLiteral("max_table_error_um")).toDouble(), 0.01 * 1000.0);
    // The written table against the true inverse over the calibrated codes: below 1 % of the
    // 1000 µm range.
    QFile file(table);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    ASSERT_EQ(file.readLine().trimmed(), QByteArray("adc_code,deflection_um"));
    double worst = 0.0;
    int rows = 0;
    while (!file.atEnd()) {
        const QList<QByteArray> cells = file.readLine().trimmed().split(',');
        ASSERT_EQ(cells.size(), 2);
        const int code = cells[0].toInt();
        ++rows;
        if (code >= cubic(-500.0) && code <= cubic(500.0))
            worst = std::max(worst, std::abs(cells[1].toDouble() - inverse(code)));
    }
    EXPECT_EQ(rows, 4096);
    EXPECT_LT(worst, 10.0);
    EXPECT_LT(worst, 1.0);
}

TEST_F(LineariseCommand, WritesABinaryImageCarryingItsCrcAndACHeader) {
    const QString points = noisyCubic();
    const QString bin = m_dir.filePath(QStringLiteral("table.bin"));
    const CliResult r = runTrueturn({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"),
                                     QStringLiteral("12"), QStringLiteral("--out"), bin,
                                     QStringLiteral("--table-version"), QStringLiteral("5"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    QFile file(bin);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray image = file.readAll();
    ASSERT_EQ(image.size(), 32 + 2 * 4096);  // format 2 (docs/protocols/linearisation-table.md)
    EXPECT_EQ(image.left(4), QByteArray("TTLT"));
    EXPECT_EQ(static_cast<unsigned char>(image[4]), 2u);  // format
    EXPECT_EQ(static_cast<unsigned char>(image[8]), 5u);  // table version, little-endian
    unsigned long crc = 0;                                // CRC-32C at offset 28, little-endian
    for (int i = 3; i >= 0; --i)
        crc = (crc << 8) | static_cast<unsigned char>(image[28 + i]);
    EXPECT_EQ(r.json().value(QStringLiteral("out")).toObject().value(QStringLiteral("image_crc")).toString(),
              QStringLiteral("0x") + QString::number(crc, 16).rightJustified(8, QLatin1Char('0')).toUpper());
    const QString header = m_dir.filePath(QStringLiteral("table.h"));
    ASSERT_EQ(runTrueturn({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                           QStringLiteral("--out"), header})
                  .exitCode,
              0);
    QFile h(header);
    ASSERT_TRUE(h.open(QIODevice::ReadOnly));
    const QByteArray text = h.readAll();
    EXPECT_TRUE(text.contains("#define TT_LIN_TABLE_ENTRIES 4096u"));
    EXPECT_TRUE(text.contains("static const int16_t tt_lin_table[TT_LIN_TABLE_ENTRIES]"));
}

double turning(double um) {
    return 2047.5 + 3.0 * um - 1.2e-5 * um * um * um;
}

TEST_F(LineariseCommand, RefusesANonMonotonicSetSayingWhere) {
    // code = 2047.5 + 3 d − 1.2e-5 d³ turns at d = ±sqrt(3 / 3.6e-5) = ±288.7 µm.
    const QString points = noisyCubic(turning);
    expectRefused({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                   QStringLiteral("--degree"), QStringLiteral("3")},
                  QStringLiteral("not monotonic: it turns at -28"));
    const CliResult r =
        runTrueturn({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                     QStringLiteral("--degree"), QStringLiteral("3"), QStringLiteral("--json")});
    EXPECT_EQ(r.exitCode, 2);
    const QJsonObject j = r.json();
    EXPECT_FALSE(j.value(QStringLiteral("monotonic")).toBool());
    EXPECT_EQ(j.value(QStringLiteral("entries")).toInt(), 0);
    EXPECT_NEAR(j.value(QStringLiteral("turning_point")).toObject().value(QStringLiteral("deflection_um")).toDouble(),
                -288.7, 5.0);
}

TEST_F(LineariseCommand, NamesBadRowsAndBadOptions) {
    const QString bad = write(QStringLiteral("bad.csv"), "reference_um,adc_code\n-100,1700\n0,2047\n100,x\n");
    expectRefused({QStringLiteral("linearise"), bad, QStringLiteral("--adc-bits"), QStringLiteral("12")},
                  QStringLiteral("line 4: adc_code 'x' is not a number"));
    const QString high = write(QStringLiteral("high.csv"),
                               "reference_um,adc_code\n-300,100\n-200,400\n-100,900\n0,2047\n100,3000\n200,4095\n"
                               "300,5000\n");
    expectRefused({QStringLiteral("linearise"), high, QStringLiteral("--adc-bits"), QStringLiteral("12")},
                  QStringLiteral("line 8: ADC code 5000 is outside 0 .. 4095"));
    const QString few = write(QStringLiteral("few.csv"), "reference_um,adc_code\n-100,1700\n0,2047\n100,2400\n");
    expectRefused({QStringLiteral("linearise"), few, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                   QStringLiteral("--degree"), QStringLiteral("2")},
                  QStringLiteral("needs at least 5 calibration points, got 3"));
    const QString points = noisyCubic();
    expectRefused({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("9")},
                  QStringLiteral("--adc-bits: 9 is outside 10 .. 16"));
    expectRefused({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                   QStringLiteral("--degree"), QStringLiteral("5")},
                  QStringLiteral("--degree: '5' is not 2, 3, 4 or auto"));
    expectRefused({QStringLiteral("linearise"), points, QStringLiteral("--adc-bits"), QStringLiteral("12"),
                   QStringLiteral("--out"), m_dir.filePath(QStringLiteral("t.txt"))},
                  QStringLiteral("must end in .csv, .h or .bin"));
    expectRefused({QStringLiteral("linearise"), m_dir.filePath(QStringLiteral("missing.csv")),
                   QStringLiteral("--adc-bits"), QStringLiteral("12")},
                  QStringLiteral("cannot read"));
    expectRefused({QStringLiteral("linearise"), points}, QStringLiteral("--adc-bits: is required"));
}

}  // namespace
