// Issue 13 item 7 on the real binary: every dither of the paper's ranges (paper 001: amplitude
// 0.005 .. 0.05 mm, period 0.2 .. 2 s) on the heavy-boring preset either cuts the max bore error by at
// least 70 % with the current method or is refused before the run (exit 2) with a reason that names the
// value that would pass; and the README's boring table (none / current / probe) still holds.
#include <gtest/gtest.h>

#include <QJsonObject>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

double maxError(const CliResult& r) {
    return r.json().value(QStringLiteral("bore_error_mm")).toObject().value(QStringLiteral("max")).toDouble();
}

CliResult boring(const QString& method, const QStringList& extra = {}) {
    return runTrueturn(QStringList{QStringLiteral("boring"), QStringLiteral("--preset"), QStringLiteral("heavy-boring"),
                                   QStringLiteral("--method"), method, QStringLiteral("--json")} +
                       extra);
}

class DitherGrid : public tt::test::CliTest {};

TEST_F(DitherGrid, EveryDitherOfThePapersRangesWorksOrIsRefusedUpFront) {
    const CliResult none = boring(QStringLiteral("none"));
    ASSERT_EQ(none.exitCode, 0) << qPrintable(none.err);
    const double uncompensated = maxError(none);
    int refused = 0, passed = 0;
    for (const char* amplitude : {"0.005", "0.01", "0.02", "0.05"}) {
        for (const char* period : {"0.2", "0.5", "1.0", "2.0"}) {
            SCOPED_TRACE(std::string(amplitude) + " mm / " + period + " s");
            const CliResult r =
                boring(QStringLiteral("current"), {QStringLiteral("--dither-mm"), QString::fromLatin1(amplitude),
                                                   QStringLiteral("--dither-period-s"), QString::fromLatin1(period)});
            if (r.exitCode == 2) {
                ++refused;
                // One line, the value that would pass.
                EXPECT_TRUE(r.err.contains(QStringLiteral("dither"))) << qPrintable(r.err);
                EXPECT_TRUE(r.err.contains(QStringLiteral("use an amplitude of"))) << qPrintable(r.err);
                EXPECT_EQ(r.err.trimmed().count(QLatin1Char('\n')), 0) << qPrintable(r.err);
                continue;
            }
            ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
            ++passed;
            EXPECT_LE(maxError(r), 0.3 * uncompensated) << maxError(r) << " vs " << uncompensated;
        }
    }
    // Measured with this build: 5 pass (0.01 mm at 0.2 / 0.5 s, 0.02 mm at 0.2 / 0.5 / 1 s: 0.045, 0.041,
    // 0.065, 0.058, 0.053 mm against 0.325 mm), 11 are refused (too short to resolve, slower than twice the
    // offset rate, ripple beyond the bore tolerance).
    EXPECT_GE(passed, 5);
    EXPECT_EQ(passed + refused, 16);
}

TEST_F(DitherGrid, RegressionCheckTheReadmeBoringTableStillHolds) {
    // A REGRESSION CHECK, not a validation: README "Results on the built-in simulator" prints this build's own
    // output (none 0.325, current 0.041, probe 0.009 mm max bore diameter error, seed 1) to three decimals,
    // pinned here to +-0.0005 mm so the README is re-measured when the simulator changes.
    const CliResult none = boring(QStringLiteral("none"));
    const CliResult current = boring(QStringLiteral("current"));
    const CliResult probe = boring(QStringLiteral("probe"));
    ASSERT_EQ(none.exitCode, 0);
    ASSERT_EQ(current.exitCode, 0) << qPrintable(current.err);
    ASSERT_EQ(probe.exitCode, 0);
    EXPECT_NEAR(maxError(none), 0.325, 0.0005);
    EXPECT_NEAR(maxError(current), 0.041, 0.0005);
    EXPECT_NEAR(maxError(probe), 0.009, 0.0005);
}

TEST_F(DitherGrid, RefusesDitherOptionsOutsideThePapersRanges) {
    for (const QStringList& bad : {QStringList{QStringLiteral("--dither-mm"), QStringLiteral("0.004")},
                                   QStringList{QStringLiteral("--dither-mm"), QStringLiteral("0.06")},
                                   QStringList{QStringLiteral("--dither-period-s"), QStringLiteral("0.1")},
                                   QStringList{QStringLiteral("--dither-period-s"), QStringLiteral("2.5")}}) {
        const CliResult r = boring(QStringLiteral("current"), bad);
        EXPECT_EQ(r.exitCode, 2) << qPrintable(bad.join(QLatin1Char(' ')));
        EXPECT_TRUE(r.err.contains(bad.first())) << qPrintable(r.err);
    }
}

}  // namespace
