// `trueturn boring` on the real binary: the paper 001 result on the heavy-boring preset
// (issue 6, "Done when": the max bore error falls by ≥ 80 % with current and with probe, force
// estimate within 10 %).
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonObject>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

QJsonObject boring(const QString& method) {
    const CliResult r =
        runTrueturn({QStringLiteral("boring"), QStringLiteral("--preset"), QStringLiteral("heavy-boring"),
                     QStringLiteral("--method"), method, QStringLiteral("--json")});
    EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
    return r.json();
}

double maxError(const QJsonObject& j) {
    return j.value(QStringLiteral("bore_error_mm")).toObject().value(QStringLiteral("max")).toDouble();
}

class BoringCommand : public tt::test::CliTest {};

TEST_F(BoringCommand, CompensationFromCurrentAndFromProbeCutsTheBoreErrorByEightyPercent) {
    const QJsonObject none = boring(QStringLiteral("none"));
    const QJsonObject current = boring(QStringLiteral("current"));
    const QJsonObject probe = boring(QStringLiteral("probe"));
    EXPECT_EQ(none.value(QStringLiteral("method")).toString(), QStringLiteral("none"));
    EXPECT_EQ(none.value(QStringLiteral("slenderness_l_over_d")).toDouble(), 10.0);
    // The slender bar alone: 0.09 .. 0.19 mm of deflection, twice that on the bore diameter.
    EXPECT_GT(maxError(none), 0.25);
    EXPECT_GT(none.value(QStringLiteral("deflection_mm")).toObject().value(QStringLiteral("max")).toDouble(), 0.12);
    EXPECT_TRUE(none.value(QStringLiteral("force_estimate_error_pct")).isNull());
    for (const QJsonObject& j : {current, probe}) {
        EXPECT_LE(maxError(j), 0.2 * maxError(none)) << maxError(j) << " vs " << maxError(none);
        EXPECT_LT(j.value(QStringLiteral("force_estimate_error_pct")).toDouble(), 10.0);
        EXPECT_TRUE(j.value(QStringLiteral("bore_error_mm")).toObject().contains(QStringLiteral("rms")));
    }
    // Coulomb friction three times the cutting force.
    EXPECT_NEAR(current.value(QStringLiteral("coulomb_friction_to_mean_force")).toDouble(), 3.0, 0.1);
    EXPECT_EQ(probe.value(QStringLiteral("probe_calibration")).toObject().value(QStringLiteral("degree")).toInt(), 3);
}

TEST_F(BoringCommand, WritesATraceAndPrintsText) {
    const QString trace = path(QStringLiteral("trace.csv"));
    const CliResult r = runTrueturn({QStringLiteral("boring"), QStringLiteral("--method"), QStringLiteral("probe"),
                                     QStringLiteral("--trace"), trace});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Bore diameter error from 5 to 495 mm")));
    QFile file(trace);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readLine().trimmed(),
              QByteArray("time_s,z_mm,diameter_error_mm,deflection_mm,offset_mm,force_n,estimated_force_n"));
    int rows = 0;
    while (!file.atEnd() && file.readLine().size() > 1)
        ++rows;
    EXPECT_GT(rows, 20000);  // 500 mm at 0.95 mm/s and a 20 ms PLC cycle: about 26 000 cycles
}

TEST_F(BoringCommand, RefusesBadOptionsAndPresets) {
    expectRefused({QStringLiteral("boring"), QStringLiteral("--method"), QStringLiteral("laser")},
                  QStringLiteral("--method: 'laser' is not one of current, probe, none"));
    expectRefused({QStringLiteral("boring"), QStringLiteral("--preset"), QStringLiteral("no-such-preset")},
                  QStringLiteral("unknown preset 'no-such-preset'"));
    const QString bad =
        write(QStringLiteral("bad.json"),
              R"({"tool": {"section": "round", "diameter_mm": 80, "overhang_mm": 800, "youngs_modulus_mpa": 210000,
                   "current_to_force_n_per_a": 150}, "dither": {"amplitude_mm": 0.2}})");
    expectRefused({QStringLiteral("boring"), QStringLiteral("--preset"), bad},
                  QStringLiteral("dither.amplitude_mm: 0.2 is outside 0.005 .. 0.05"));
}

}  // namespace
