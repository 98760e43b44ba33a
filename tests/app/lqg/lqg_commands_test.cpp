// The run-to-run commands on the real binary: lqg, simulate, bench (issue "Core engine: run-to-run
// LQG control of the shaft profile", item 8), and the Table 2 reproduction of paper 000 through them.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <cmath>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

/// Paper 000, Table 2: k_eff for z = 1..4.
constexpr double kTable2[4] = {10.02, 4.23, 2.84, 2.25};

QSet<QString> keysOf(const QJsonObject& o) {
    QSet<QString> keys;
    for (auto it = o.begin(); it != o.end(); ++it)
        keys.insert(it.key());
    return keys;
}

QSet<QString> set(std::initializer_list<const char*> names) {
    QSet<QString> s;
    for (const char* n : names)
        s.insert(QString::fromLatin1(n));
    return s;
}

/// rows x cols of a JSON matrix (array of rows).
std::pair<int, int> shape(const QJsonValue& m) {
    const QJsonArray rows = m.toArray();
    return {static_cast<int>(rows.size()), rows.isEmpty() ? 0 : static_cast<int>(rows.first().toArray().size())};
}

double at(const QJsonValue& m, int r, int c) {
    return m.toArray().at(r).toArray().at(c).toDouble();
}

class RunToRunCommands : public tt::test::CliTest {};

TEST_F(RunToRunCommands, LqgJsonReportsMarginsPerPointAndFlagsTheShortDelayMargin) {
    // Issue 13 item 3: margins {gain, phase_deg, delay_parts, disk} per point. Values at z = 1 from Octave's
    // control package (tests/crosscheck/lqg_margins.m): gain margin 1.651585, delay margin 0.7528 parts,
    // disk alpha 0.491468; tolerance 1e-4. A delay margin under one part gives a warning per point.
    const CliResult r = runTrueturn({"lqg", "--delay", "1", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject m = r.json()["margins"].toObject();
    for (const char* key : {"gain", "phase_deg", "delay_parts", "disk", "extra_parts_tolerated", "sensitivity_peak"})
        ASSERT_EQ(m[QString::fromLatin1(key)].toArray().size(), 5) << key;
    EXPECT_TRUE(m["closed_loop_stable"].toBool());
    EXPECT_NEAR(m["gain"].toArray()[2].toDouble(), 1.651585, 1e-4);
    EXPECT_NEAR(m["delay_parts"].toArray()[2].toDouble(), 0.7528, 1e-4);
    EXPECT_NEAR(m["disk"].toArray()[2].toDouble(), 0.491468, 1e-4);
    const QJsonArray warnings = r.json()["warnings"].toArray();
    ASSERT_EQ(warnings.size(), 5);
    EXPECT_EQ(warnings[0].toObject()["kind"].toString(), "delay_margin_below_one_part");
    EXPECT_EQ(warnings[4].toObject()["point"].toInt(), 4);
}

TEST_F(RunToRunCommands, LqgJsonHasExactlyTheIssuesFields) {
    const CliResult r = runTrueturn({"lqg", "--preset", "paper-2012", "--delay", "4", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(keysOf(j), set({"delay", "points", "plant", "noise", "weights", "lq", "kalman", "margins", "warnings"}));
    EXPECT_EQ(keysOf(j["plant"].toObject()), set({"A", "B", "C", "D", "G"}));
    EXPECT_EQ(keysOf(j["noise"].toObject()), set({"W", "V"}));
    EXPECT_EQ(keysOf(j["weights"].toObject()), set({"R1", "R2"}));
    EXPECT_EQ(keysOf(j["lq"].toObject()), set({"K"}));
    EXPECT_EQ(keysOf(j["kalman"].toObject()), set({"L", "P"}));
    EXPECT_EQ(j["delay"].toInt(), 4);
    const QJsonArray points = j["points"].toArray();
    ASSERT_EQ(points.size(), 5);
    EXPECT_EQ(keysOf(points[0].toObject()), set({"x_mm"}));
    EXPECT_DOUBLE_EQ(points[2].toObject()["x_mm"].toDouble(), 162.5);
    // 5 delay chains of 4 states (the paper's n = 20) + 5 disturbance filters of 2 states.
    const QJsonObject plant = j["plant"].toObject();
    const int n = shape(plant["A"]).first;
    EXPECT_EQ(n, 30);
    EXPECT_EQ(shape(plant["B"]), std::make_pair(n, 5));
    EXPECT_EQ(shape(plant["C"]), std::make_pair(5, n));
    EXPECT_EQ(shape(plant["D"]), std::make_pair(5, 5));
    EXPECT_EQ(shape(j["lq"].toObject()["K"]), std::make_pair(5, n));
    const QJsonObject kalman = j["kalman"].toObject();
    EXPECT_EQ(shape(kalman["L"]), std::make_pair(n, 5));
    EXPECT_EQ(shape(kalman["P"]), std::make_pair(n, n));
    EXPECT_DOUBLE_EQ(at(j["noise"].toObject()["V"], 0, 0), 2.5e-7);
    EXPECT_DOUBLE_EQ(at(j["weights"].toObject()["R2"], 1, 1), 0.01);
    // L = P C'(C P C' + V)^-1, checked from the printed matrices (C P C' + V is diagonal: the points
    // are independent).
    const QJsonValue C = plant["C"];
    const QJsonValue P = kalman["P"];
    const QJsonValue V = j["noise"].toObject()["V"];
    for (int i = 0; i < 5; ++i) {
        double cpc = 0.0;
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b)
                cpc += at(C, i, a) * at(P, a, b) * at(C, i, b);
        for (int s = 0; s < n; ++s) {
            double pc = 0.0;
            for (int a = 0; a < n; ++a)
                pc += at(P, s, a) * at(C, i, a);
            EXPECT_NEAR(at(kalman["L"], s, i), pc / (cpc + at(V, i, i)), 1e-12);
        }
    }
}

TEST_F(RunToRunCommands, LqgTextIsAReadableTable) {
    const CliResult r = runTrueturn({"lqg", "--delay", "2"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains("delay z = 2")) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains("k_eff"));
    EXPECT_TRUE(r.out.contains("162.5"));
}

// Table 2 through the command line: 20 000 parts per delay, every point within +-15 % of the paper,
// Monte-Carlo within 5 % of the analytic k_eff, and LQG better than the best-weighted EWMA.
TEST_F(RunToRunCommands, SimulateReproducesTable2AndLqgBeatsTheBestEwma) {
    for (int z = 1; z <= 4; ++z) {
        const QString delay = QString::number(z);
        const CliResult lqg = runTrueturn({"simulate", "--preset", "paper-2012", "--delay", delay, "--parts", "20000",
                                           "--seed", "1", "--controller", "lqg", "--json"});
        ASSERT_EQ(lqg.exitCode, 0) << qPrintable(lqg.err);
        const QJsonObject j = lqg.json();
        EXPECT_EQ(keysOf(j),
                  set({"controller", "delay", "parts", "warmup_parts", "points", "k_eff", "verdicts",
                       "tolerance_alarms", "alarms", "corrections", "integral", "plant", "systematic_from_part",
                       "largest_systematic_mm", "mismatch_action", "adaptations", "adaptation_notices"}));
        EXPECT_TRUE(j["adaptations"].toArray().isEmpty()) << "the matching plant: no adaptation";
        EXPECT_EQ(j["controller"].toString(), "lqg");
        EXPECT_EQ(j["delay"].toInt(), z);
        EXPECT_EQ(j["parts"].toInt(), 20000);
        const QJsonArray points = j["points"].toArray();
        ASSERT_EQ(points.size(), 5);
        double analyticOpen = 0.0, analyticClosed = 0.0;
        for (const QJsonValue& pv : points) {
            const QJsonObject p = pv.toObject();
            EXPECT_EQ(keysOf(p), set({"x_mm", "var_open", "var_closed", "k_eff", "k_eff_analytic", "systematic_mm"}));
            EXPECT_NEAR(p["k_eff"].toDouble() / kTable2[z - 1], 1.0, 0.15) << "z " << z;
            EXPECT_NEAR(p["var_open"].toDouble() / p["var_closed"].toDouble(), p["k_eff"].toDouble(), 1e-9);
            EXPECT_NEAR(p["var_open"].toDouble(), 0.0013, 0.0013 * 0.15);  // paper: 0.0013 mm^2
            analyticOpen += 1.0;
            analyticClosed += 1.0 / p["k_eff_analytic"].toDouble();
        }
        const double kEffAnalytic = analyticOpen / analyticClosed;  // equal open variances at every point
        EXPECT_NEAR(j["k_eff"].toDouble() / kEffAnalytic, 1.0, 0.05) << "z " << z;
        EXPECT_NEAR(j["k_eff"].toDouble() / kTable2[z - 1], 1.0, 0.15) << "z " << z;

        const CliResult ewma = runTrueturn({"simulate", "--delay", delay, "--parts", "20000", "--seed", "1",
                                            "--controller", "ewma", "--ewma-weight", "auto", "--json"});
        ASSERT_EQ(ewma.exitCode, 0) << qPrintable(ewma.err);
        const QJsonObject e = ewma.json();
        EXPECT_EQ(keysOf(e),
                  set({"controller", "delay", "parts", "warmup_parts", "points", "k_eff", "ewma_weight", "verdicts",
                       "alarms", "corrections", "integral", "plant", "tolerance_alarms", "systematic_from_part",
                       "largest_systematic_mm", "mismatch_action", "adaptations", "adaptation_notices"}));
        EXPECT_GT(e["ewma_weight"].toDouble(), 0.0);
        EXPECT_LE(e["ewma_weight"].toDouble(), 1.0);
        EXPECT_LT(e["k_eff"].toDouble(), j["k_eff"].toDouble()) << "z " << z;
    }
}

TEST_F(RunToRunCommands, SimulateOpenLoopAndGivenEwmaWeightAndText) {
    const CliResult open = runTrueturn({"simulate", "--controller", "open", "--parts", "1000", "--json"});
    ASSERT_EQ(open.exitCode, 0) << qPrintable(open.err);
    EXPECT_DOUBLE_EQ(open.json()["k_eff"].toDouble(), 1.0);
    const CliResult ewma = runTrueturn(
        {"simulate", "--controller", "ewma", "--ewma-weight", "0.3", "--parts", "1000", "--delay", "2", "--json"});
    ASSERT_EQ(ewma.exitCode, 0) << qPrintable(ewma.err);
    EXPECT_DOUBLE_EQ(ewma.json()["ewma_weight"].toDouble(), 0.3);
    const CliResult text = runTrueturn({"simulate", "--parts", "1000"});
    ASSERT_EQ(text.exitCode, 0);
    EXPECT_TRUE(text.out.contains("k_eff (all points)")) << qPrintable(text.out);
    // Same seed, same result.
    const CliResult again = runTrueturn({"simulate", "--parts", "1000"});
    EXPECT_EQ(again.out, text.out);
}

TEST_F(RunToRunCommands, PapersOwnFilterPresetRuns) {
    const CliResult r =
        runTrueturn({"simulate", "--preset", "paper-2012-filter", "--delay", "4", "--parts", "2000", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_GT(r.json()["points"].toArray()[0].toObject()["k_eff_analytic"].toDouble(), 1000.0);
}

TEST_F(RunToRunCommands, BenchReportsTheHotPaths) {
    const CliResult r = runTrueturn({"bench", "--seconds", "0.05", "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    for (const char* key : {"lqg_synthesis_us", "controller_update_us", "sim_part_steps_per_s"})
        EXPECT_GT(j[key].toDouble(), 0.0) << key;
    EXPECT_EQ(j["delay"].toInt(), 4);
    EXPECT_EQ(j["points"].toInt(), 5);
    const CliResult text = runTrueturn({"bench", "--seconds", "0.05"});
    EXPECT_TRUE(text.out.contains("LQG synthesis")) << qPrintable(text.out);
}

TEST_F(RunToRunCommands, BadInputExitsTwoWithOneLine) {
    expectRefused({"lqg", "--delay", "9"}, "--delay: 9 is outside 1 .. 8");
    expectRefused({"lqg", "--delay", "x"}, "--delay: 'x' is not a whole number");
    expectRefused({"lqg", "--preset", "nosuch"}, "unknown preset 'nosuch'");
    expectRefused({"lqg", "--frobnicate"}, "frobnicate");
    expectRefused({"lqg", "--preset", "paper-2012-table1-group1"}, "plant: missing");
    expectRefused({"simulate", "--parts", "0"}, "--parts: 0 is outside 100 .. 10000000");
    expectRefused({"simulate", "--controller", "pid"}, "--controller: 'pid' is not one of lqg, ewma, open");
    expectRefused({"simulate", "--controller", "ewma", "--ewma-weight", "1.5"}, "--ewma-weight: 1.5 is outside");
    expectRefused({"simulate", "--controller", "ewma", "--ewma-weight", "0"}, "--ewma-weight: must be in (0, 1]");
    expectRefused({"simulate", "--ewma-weight", "0.5"}, "--ewma-weight: only with --controller ewma");
    expectRefused({"simulate", "--seed", "-1"}, "--seed: -1 is outside");
    expectRefused({"simulate", "--delay", "0"}, "--delay: 0 is outside 1 .. 8");
    expectRefused({"bench", "--seconds", "100"}, "--seconds: 100 is outside");
    expectRefused({"simulate", "extra"}, "unexpected argument 'extra'");
}

// The paper's printed, rounded filter coefficients have a root at 1.0029: a preset that uses them is
// refused, naming the root and the field.
TEST_F(RunToRunCommands, UnstableFilterPresetIsRefusedNamingTheRoot) {
    const QString path = write("rounded.json", R"({
        "name": "rounded", "description": "the paper's rounded coefficients",
        "plant": {"part_length_mm": 325, "delay": 2, "gauge_noise_variance_mm2": 2.5e-7,
                  "disturbance": [{"type": "shaping_filter", "numerator": [0.001, -0.0006, 0.0004],
                                   "denominator": [1, -2.024, 1.08, -0.0561], "variance_mm2": 0.0013}]}
    })");
    for (const char* command : {"lqg", "simulate"})
        expectRefused({command, "--preset", path},
                      "plant.disturbance[0].denominator: shaping filter is unstable: "
                      "the denominator has a root at 1.0029");
}

TEST_F(RunToRunCommands, MalformedPresetFieldsAreNamed) {
    auto preset = [&](const QByteArray& plant) {
        return write("p.json", R"({"name": "p", "description": "", "plant": )" + plant + "}");
    };
    expectRefused({"lqg", "--preset", preset(R"({"part_length_mm": 325, "gauge_noise_variance_mm2": 1e-7,
        "disturbance": [{"type": "ar1", "pole": 1.2, "variance_mm2": 0.001}]})")},
                  "plant.disturbance[0]: AR(1) disturbance: the pole 1.2");
    expectRefused({"lqg", "--preset", preset(R"({"part_length_mm": 325, "gauge_noise_variance_mm2": 1e-7,
        "disturbance": [{"type": "pink", "variance_mm2": 0.001}]})")},
                  "plant.disturbance[0].type: 'pink' is not one of");
    expectRefused({"lqg", "--preset", preset(R"({"part_length_mm": 325, "disturbance": [{"type": "white",
        "variance_mm2": 0.001}]})")},
                  "gauge_noise_variance_mm2: missing");
    expectRefused({"lqg", "--preset", preset(R"({"points_mm": [], "gauge_noise_variance_mm2": 1e-7,
        "disturbance": [{"type": "white", "variance_mm2": 0.001}]})")},
                  "plant.points_mm: must be a non-empty array");
    expectRefused({"lqg", "--preset", preset(R"({"part_length_mm": 325, "delay": 2.5, "gauge_noise_variance_mm2": 1e-7,
        "disturbance": [{"type": "white", "variance_mm2": 0.001}]})")},
                  "plant.delay: must be a whole number");
}

}  // namespace
