// Robust run-to-run control on the command line (issue 13): a simulated plant that differs from the
// model (`trueturn simulate --plant-gain --plant-delay --step-*`), integral action (`--integral`), the
// loop's mismatch monitor (`alarms`) and the identification of the disturbance from the history
// (`trueturn identify`).
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "cli_runner.h"

namespace tt {
namespace {

using test::CliResult;
using test::runTrueturn;

QJsonObject runJson(const QStringList& args) {
    const CliResult r = runTrueturn(args, test::kPatientWaitMs);
    EXPECT_EQ(r.exitCode, 0) << qPrintable(args.join(' ')) << "\n" << qPrintable(r.err);
    return r.json();
}

QStringList simulate(int z, const QStringList& more) {
    return QStringList{"simulate", "--preset", "paper-2012", "--delay", QString::number(z), "--seed", "1", "--json"} +
           more;
}

// Issue 13: after a 0.02 mm step the mean error returns below 2 % of the step within 3z + 5 parts for
// z = 1..4 with integral action. Without it the LQG leaves 6.5 / 14 / 21 / 27 % (the issue's figures,
// measured again here: at least 5 %).
TEST(RobustCli, IntegralActionRemovesAStep) {
    for (int z = 1; z <= 4; ++z) {
        const QStringList step{"--parts", "600", "--step-at", "200", "--step-mm", "0.02", "--mismatch-action", "alarm"};
        const QJsonObject with = runJson(simulate(z, step + QStringList{"--integral", "on"}));
        const QJsonObject without = runJson(simulate(z, step + QStringList{"--integral", "off"}));
        const QJsonObject s = with.value("step").toObject();
        EXPECT_EQ(s.value("at_part").toInteger(), 200);
        EXPECT_EQ(s.value("from_part").toInteger(), 200 + 3 * z + 5);
        EXPECT_EQ(s.value("to_part").toInteger(), 200 + 3 * z + 5 + 19);
        EXPECT_LT(std::abs(s.value("residual_pct").toDouble()), 2.0) << "z = " << z;
        EXPECT_GT(without.value("step").toObject().value("residual_pct").toDouble(), 5.0) << "z = " << z;
        EXPECT_TRUE(with.value("integral").isObject());
    }
}

// Paper 000, Table 2 (k_eff = 10.02, 4.23, 2.84, 2.25 for z = 1..4), checked against its sources with the
// tolerances they justify:
// - the design model's analytic k_eff (closed-loop Lyapunov equation: no sampling error) within 1.2 % of the
//   paper, which prints two decimals; the paper-2012 calibration reaches it within 1.0 % (docs/DECISIONS.md,
//   "paper-2012 calibration": 10.01, 4.24, 2.85, 2.23);
// - the simulated k_eff (20 000 parts) within 6 % of the analytic one: three standard deviations of the
//   Monte-Carlo k_eff, measured over seeds 1..12 at 1.8 % (z = 2..4) and 1.6 % (z = 1, 11 seeds: seed 10 is
//   left out, where a false mismatch alarm at part 15 froze the correction).
// The matching plant raises no mismatch alarm in these runs, and integral action costs at most 15 % of k_eff
// (issue 13). Besides, a REGRESSION CHECK (not a validation): seed 1's k_eff pinned to +-0.006 at this build's
// 10.00, 4.23, 2.85, 2.24 (the README's table), so a change of the simulator shows and the README is re-measured.
TEST(RobustCli, TableTwoHoldsAgainstThePaperAndTheAnalyticValueAndIntegralActionCostsLittle) {
    constexpr double kPaperTable2[] = {10.02, 4.23, 2.84, 2.25};
    constexpr double kSeedOneRegression[] = {10.00, 4.23, 2.85, 2.24};
    for (int z = 1; z <= 4; ++z) {
        const QJsonObject off = runJson(simulate(z, {"--parts", "20000", "--controller", "lqg"}));
        const QJsonObject on = runJson(simulate(z, {"--parts", "20000", "--controller", "lqg", "--integral", "on"}));
        const double analytic = off.value("points").toArray().first().toObject().value("k_eff_analytic").toDouble();
        const double simulated = off.value("k_eff").toDouble();
        EXPECT_NEAR(analytic, kPaperTable2[z - 1], 0.012 * kPaperTable2[z - 1]) << "z = " << z;
        EXPECT_NEAR(simulated, analytic, 0.06 * analytic) << "z = " << z;
        EXPECT_NEAR(simulated, kSeedOneRegression[z - 1], 0.006) << "regression check, z = " << z;
        EXPECT_TRUE(off.value("alarms").toArray().isEmpty()) << "z = " << z;
        EXPECT_TRUE(on.value("alarms").toArray().isEmpty()) << "z = " << z;
        EXPECT_GE(on.value("k_eff").toDouble(), 0.85 * simulated) << "z = " << z;
    }
}

// Issue 13: a plant one part slower than the model, or with half or twice its gain, is detected within
// 50 parts; with the action hold the loop then holds the last correction and the corrections stay inside their
// limits (the default action, adapt, is tested in tests/app/adaptive).
TEST(RobustCli, MismatchIsDetectedWithin50Parts) {
    for (int z = 1; z <= 4; ++z) {
        for (const QStringList& mismatch : {QStringList{"--plant-delay", QString::number(z + 1)},
                                            QStringList{"--plant-gain", "0.5"}, QStringList{"--plant-gain", "2"}}) {
            const QJsonObject j = runJson(
                simulate(z, QStringList{"--parts", "300", "--warmup", "0", "--mismatch-action", "hold"} + mismatch));
            const QJsonArray alarms = j.value("alarms").toArray();
            ASSERT_EQ(alarms.size(), 1) << "z = " << z << " " << qPrintable(mismatch.join(' '));
            const QJsonObject a = alarms.first().toObject();
            EXPECT_EQ(a.value("kind").toString(), "model_mismatch");
            EXPECT_LE(a.value("part").toInteger(), 50) << "z = " << z << " " << qPrintable(mismatch.join(' '));
            EXPECT_GE(a.value("point").toInt(), 1);
            EXPECT_TRUE(a.value("held").toBool());
            const QJsonObject c = j.value("corrections").toObject();
            EXPECT_LE(c.value("max_abs_mm").toDouble(), c.value("limit_abs_mm").toDouble() + 1e-12);
            EXPECT_LE(c.value("max_step_mm").toDouble(), c.value("limit_step_mm").toDouble() + 1e-12);
        }
    }
}

// The same from a preset: "plant_mismatch" (a plant with twice the gain) and "controller.integral".
TEST(RobustCli, PresetSectionsSetThePlantAndTheController) {
    QTemporaryDir dir;
    const QString preset = dir.filePath("mismatch.json");
    QFile file(preset);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"name": "mismatch", "description": "paper-2012 with a plant of twice the gain and integral action",
                   "based_on": "paper-2012",
                   "plant_mismatch": {"gain_factor": 2, "step": {"at_part": 150, "size_mm": 0.02, "point": 3}},
                   "controller": {"output_weight": 1, "correction_weight": 0.01, "max_correction_mm": 0.3,
                                  "max_step_mm": 0.1, "integral": {"enabled": true, "weight": 0.3}}})");
    file.close();
    const QJsonObject j =
        runJson({"simulate", "--preset", preset, "--delay", "2", "--parts", "300", "--warmup", "0", "--json"});
    EXPECT_DOUBLE_EQ(j.value("plant").toObject().value("gain_factor").toDouble(), 2.0);
    EXPECT_DOUBLE_EQ(j.value("integral").toObject().value("weight").toDouble(), 0.3);
    EXPECT_EQ(j.value("step").toObject().value("point").toInt(), 3);
    ASSERT_EQ(j.value("alarms").toArray().size(), 1);
    EXPECT_LE(j.value("alarms").toArray().first().toObject().value("part").toInteger(), 50);
    QFile bad(dir.filePath("bad.json"));
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
    bad.write(R"({"name": "bad", "description": "a gain factor out of range", "based_on": "paper-2012",
                  "plant_mismatch": {"gain_factor": 50}})");
    bad.close();
    const CliResult r = runTrueturn({"simulate", "--preset", dir.filePath("bad.json"), "--parts", "100", "--json"});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(r.err.contains("gain_factor")) << qPrintable(r.err);
}

TEST(RobustCli, RefusesBadMismatchOptions) {
    for (const QStringList& bad :
         {QStringList{"--plant-delay", "1"}, QStringList{"--plant-gain", "20"}, QStringList{"--step-at", "10"},
          QStringList{"--step-mm", "0.02"}, QStringList{"--step-at", "10", "--step-mm", "0"},
          QStringList{"--step-at", "10", "--step-mm", "0.02", "--step-point", "6"}, QStringList{"--integral", "maybe"},
          QStringList{"--integral-weight", "2"}, QStringList{"--mismatch-action", "stop"}}) {
        const CliResult r = runTrueturn(simulate(2, QStringList{"--parts", "100"} + bad));
        EXPECT_EQ(r.exitCode, 2) << qPrintable(bad.join(' '));
        EXPECT_FALSE(r.err.trimmed().isEmpty());
    }
    // A step that ends after the run cannot be measured.
    const CliResult late = runTrueturn(simulate(1, {"--parts", "100", "--step-at", "190", "--step-mm", "0.02"}));
    EXPECT_NE(late.exitCode, 0);
    EXPECT_TRUE(late.err.contains("part"));
}

// Issue 13: the disturbance of a stored run fitted as ARMA(1, 1). paper-2012's disturbance is
// W(z) = (z + 0.246) / (z - 0.9215) (resources/presets/paper-2012.json): 2,000 parts under LQG (the
// identification subtracts k_i x the correction each part received) give a and b within 0.03.
TEST(RobustCli, IdentifiesTheStoredDisturbance) {
    QTemporaryDir dir;
    const QString db = dir.filePath("history.sqlite");
    runJson(simulate(1, {"--parts", "2000", "--warmup", "0", "--db", db}));
    const QJsonObject j = runJson({"identify", "--db", db, "--point", "3", "--json"});
    ASSERT_EQ(j.value("ar").toArray().size(), 1);
    ASSERT_EQ(j.value("ma").toArray().size(), 1);
    EXPECT_NEAR(j.value("ar").toArray().at(0).toDouble(), 0.9215, 0.03);
    EXPECT_NEAR(j.value("ma").toArray().at(0).toDouble(), 0.246, 0.03);
    EXPECT_GT(j.value("std_errors").toObject().value("ar").toArray().at(0).toDouble(), 0.0);
    EXPECT_GT(j.value("ljung_box_p").toDouble(), 0.001);
    EXPECT_EQ(j.value("parts").toObject().value("count").toInteger(), 2000);
    const QJsonObject filter = j.value("disturbance").toArray().at(0).toObject();
    EXPECT_EQ(filter.value("type").toString(), "shaping_filter");
    // The stationary variance of the preset is 0.0013 mm^2; 2,000 parts of a process with a memory of about
    // 12 parts estimate it within about 20 %.
    EXPECT_NEAR(filter.value("variance_mm2").toDouble(), 0.0013, 0.0003);

    for (const QStringList& bad :
         {QStringList{"identify", "--json"}, QStringList{"identify", "--db", db, "--point", "9"},
          QStringList{"identify", "--db", db, "--ar", "5"},
          QStringList{"identify", "--db", dir.filePath("none.sqlite")}}) {
        const CliResult r = runTrueturn(bad);
        EXPECT_EQ(r.exitCode, 2) << qPrintable(bad.join(' '));
    }
}

}  // namespace
}  // namespace tt
