// The three commands of the feed scheduling (paper 004) run as the planner runs them: the experiment on
// the simulator, the model fitted to it, the schedule with its check on the simulator and its program.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

/// The preset's own request (resources/presets/feed-scheduling.json, "schedule").
QStringList presetRequest(const QString& model) {
    return {QStringLiteral("schedule-feed"), QStringLiteral("--model"),    model,
            QStringLiteral("--depth"),       QStringLiteral("1.5"),        QStringLiteral("--feed-min"),
            QStringLiteral("0.05"),          QStringLiteral("--feed-max"), QStringLiteral("0.4"),
            QStringLiteral("--feed-step"),   QStringLiteral("0.005"),      QStringLiteral("--z-start"),
            QStringLiteral("380"),           QStringLiteral("--z-end"),    QStringLiteral("60"),
            QStringLiteral("--min-length"),  QStringLiteral("5")};
}

class FeedScheduleCommands : public tt::test::CliTest {
protected:
    /// Experiment (seed 4) and stepwise cubic-z fit, as the README runs them; returns the model file.
    QString model() {
        const QString csv = path(QStringLiteral("experiment.csv"));
        const CliResult e = runTrueturn({QStringLiteral("deformation-experiment"), QStringLiteral("--preset"),
                                         QStringLiteral("feed-scheduling"), QStringLiteral("--csv"), csv});
        EXPECT_EQ(e.exitCode, 0) << qPrintable(e.err);
        const QString file = path(QStringLiteral("model.json"));
        const CliResult f = runTrueturn({QStringLiteral("fit-deformation"), csv, QStringLiteral("--stepwise"),
                                         QStringLiteral("--out"), file, QStringLiteral("--json")});
        EXPECT_EQ(f.exitCode, 0) << qPrintable(f.err);
        m_fit = f.json();
        return file;
    }

    QJsonObject m_fit;
};

TEST_F(FeedScheduleCommands, ExperimentWritesTheCsvFitDeformationReads) {
    const QString csv = path(QStringLiteral("e.csv"));
    const CliResult r = runTrueturn({QStringLiteral("deformation-experiment"), QStringLiteral("--preset"),
                                     QStringLiteral("feed-scheduling"), QStringLiteral("--csv"), csv,
                                     QStringLiteral("--seed"), QStringLiteral("9"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    // 4 depths x 8 feeds = 32 bars, each gauged at z = 20 .. 390 mm every 10 mm (38 positions).
    EXPECT_EQ(r.json().value(QStringLiteral("rows")).toInt(), 32 * 38);
    EXPECT_EQ(r.json().value(QStringLiteral("bars")).toInt(), 32);
    EXPECT_EQ(r.json().value(QStringLiteral("seed")).toInt(), 9);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = file.readAll().split('\n');
    EXPECT_TRUE(lines.contains("# preset: feed-scheduling"));
    EXPECT_TRUE(lines.contains("# seed: 9"));
    EXPECT_TRUE(lines.contains("a_mm,f_mm_rev,z_mm,y_um"));
    EXPECT_EQ(lines.size(), 4 + 32 * 38 + 1);  // three comments, the header, the rows, the final newline
}

TEST_F(FeedScheduleCommands, FitReportsThePlannersStatistics) {
    model();
    const QJsonObject s = m_fit.value(QStringLiteral("statistics")).toObject();
    EXPECT_EQ(s.value(QStringLiteral("n")).toInt(), 1216);
    EXPECT_GT(s.value(QStringLiteral("r2")).toDouble(), 0.99);
    EXPECT_LT(s.value(QStringLiteral("r2_adj")).toDouble(), s.value(QStringLiteral("r2")).toDouble());
    EXPECT_GT(s.value(QStringLiteral("f")).toDouble(), s.value(QStringLiteral("f_critical")).toDouble());
    EXPECT_TRUE(s.value(QStringLiteral("significant")).toBool());
    EXPECT_DOUBLE_EQ(s.value(QStringLiteral("two_sigma_um")).toDouble(),
                     2.0 * s.value(QStringLiteral("sigma_resid_um")).toDouble());
    // Stepwise: every kept term is significant, every removed one was not.
    const double tCritical = s.value(QStringLiteral("t_critical")).toDouble();
    EXPECT_NEAR(tCritical, 1.962, 2e-3);  // t(0.975; about 1200) = 1.962 (NIST/SEMATECH table 1.3.6.7.2)
    const QJsonArray terms = m_fit.value(QStringLiteral("terms")).toArray();
    ASSERT_GE(terms.size(), 8);
    for (const QJsonValue& t : terms) {
        EXPECT_GT(t.toObject().value(QStringLiteral("std_error_um")).toDouble(), 0.0);
        EXPECT_GE(std::abs(t.toObject().value(QStringLiteral("t")).toDouble()), tCritical);
    }
    for (const QJsonValue& t : m_fit.value(QStringLiteral("removed_terms")).toArray())
        EXPECT_LT(t.toObject().value(QStringLiteral("t")).toDouble(), tCritical);
    EXPECT_EQ(terms.size() + m_fit.value(QStringLiteral("removed_terms")).toArray().size(), 24);
    EXPECT_EQ(m_fit.value(QStringLiteral("source")).toObject().value(QStringLiteral("preset")).toString(),
              QStringLiteral("feed-scheduling"));
    EXPECT_EQ(m_fit.value(QStringLiteral("job")).toObject().value(QStringLiteral("spindle_rpm")).toInt(), 720);
}

TEST_F(FeedScheduleCommands, ScheduleHoldsTheLevelOnTheSimulatorAndSavesTime) {
    const QString file = model();
    QStringList args = presetRequest(file);
    args << QStringLiteral("--level-fraction") << QStringLiteral("0.5") << QStringLiteral("--verify")
         << QStringLiteral("--json");
    const CliResult r = runTrueturn(args);
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    const double yc = j.value(QStringLiteral("yc_um")).toDouble();
    EXPECT_NEAR(yc, 0.5 * (j.value(QStringLiteral("y1_um")).toDouble() + j.value(QStringLiteral("y2_um")).toDouble()),
                1e-9);
    const QJsonArray segments = j.value(QStringLiteral("segments")).toArray();
    ASSERT_GE(segments.size(), 10);
    EXPECT_DOUBLE_EQ(segments.first().toObject().value(QStringLiteral("z_from")).toDouble(), 380.0);
    EXPECT_DOUBLE_EQ(segments.last().toObject().value(QStringLiteral("z_to")).toDouble(), 60.0);
    double previousFeed = 0.0;
    for (const QJsonValue& v : segments) {
        const QJsonObject g = v.toObject();
        for (const char* key : {"z_from", "z_to", "f", "y_from_um", "y_to_um"})
            EXPECT_TRUE(g.contains(QLatin1String(key))) << key;
        EXPECT_NEAR(g.value(QStringLiteral("y_from_um")).toDouble(), yc, 1e-6);
        EXPECT_LT(g.value(QStringLiteral("y_to_um")).toDouble(), yc);
        EXPECT_GT(g.value(QStringLiteral("f")).toDouble(), previousFeed);
        previousFeed = g.value(QStringLiteral("f")).toDouble();
    }
    const QJsonObject time = j.value(QStringLiteral("time_s")).toObject();
    const double schedule = time.value(QStringLiteral("schedule")).toDouble();
    // Constant fmin over 320 mm at 720 rpm: 60 * 320 / (0.05 * 720) = 533.33 s; fmax: 66.67 s.
    EXPECT_NEAR(time.value(QStringLiteral("fmin")).toDouble(), 60.0 * 320.0 / (0.05 * 720.0), 1e-9);
    EXPECT_NEAR(time.value(QStringLiteral("fmax")).toDouble(), 60.0 * 320.0 / (0.4 * 720.0), 1e-9);
    EXPECT_LT(schedule, time.value(QStringLiteral("fmin")).toDouble());
    EXPECT_GT(schedule, time.value(QStringLiteral("fmax")).toDouble());
    EXPECT_NEAR(time.value(QStringLiteral("saved_vs_fmin_pct")).toDouble(),
                100.0 * (1.0 - schedule / time.value(QStringLiteral("fmin")).toDouble()), 1e-9);
    // Paper 004 on the simulator: within +-10 % of Yc along the scheduled length; constant fmax far above it.
    const QJsonObject verify = j.value(QStringLiteral("verify")).toObject();
    EXPECT_LT(verify.value(QStringLiteral("max_deviation_pct")).toDouble(), 10.0);
    const double worstZ = verify.value(QStringLiteral("worst_z")).toDouble();
    EXPECT_GE(worstZ, 60.0);
    EXPECT_LE(worstZ, 380.0);
    EXPECT_GT(verify.value(QStringLiteral("fmax_excess_pct")).toDouble(), 10.0);
}

TEST_F(FeedScheduleCommands, VerifyOutsideTheBandExitsThreeNamingTheWorstPointAndProposes) {
    // a = 0.5 mm at Y1 with the paper's rule: a level of about 6.5 µm against the model's error there.
    const QString file = model();
    QStringList args = presetRequest(file);
    args[args.indexOf(QStringLiteral("--depth")) + 1] = QStringLiteral("0.5");
    args << QStringLiteral("--level-fraction") << QStringLiteral("0") << QStringLiteral("--verify")
         << QStringLiteral("--json");
    const CliResult r = runTrueturn(args);
    ASSERT_EQ(r.exitCode, 3) << qPrintable(r.err);
    EXPECT_EQ(r.err.trimmed().count(QLatin1Char('\n')), 0) << qPrintable(r.err);
    const QJsonObject j = r.json();  // the JSON is written all the same
    const QJsonObject verify = j.value(QStringLiteral("verify")).toObject();
    const double worst = verify.value(QStringLiteral("max_deviation_pct")).toDouble();
    EXPECT_GT(worst, 10.0);
    EXPECT_FALSE(verify.value(QStringLiteral("within_10_pct")).toBool());
    const QString where =
        QStringLiteral("z = %1 mm").arg(verify.value(QStringLiteral("worst_z")).toDouble(), 0, 'f', 1);
    EXPECT_TRUE(r.err.contains(where)) << qPrintable(r.err) << " / " << qPrintable(where);
    EXPECT_TRUE(r.err.contains(QStringLiteral("%1 % off Yc").arg(worst, 0, 'f', 2))) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--refine"))) << qPrintable(r.err);
    // The proposal: bars at 0.5 mm with their gauge points, and the band the plan expects.
    const QJsonObject proposal = j.value(QStringLiteral("proposal")).toObject();
    EXPECT_DOUBLE_EQ(proposal.value(QStringLiteral("depth_mm")).toDouble(), 0.5);
    const QJsonArray bars = proposal.value(QStringLiteral("bars")).toArray();
    ASSERT_GE(bars.size(), 1);
    EXPECT_EQ(proposal.value(QStringLiteral("bar_count")).toInt(), bars.size());
    EXPECT_EQ(bars.first().toObject().value(QStringLiteral("z")).toArray().size(), 33);
    EXPECT_LT(proposal.value(QStringLiteral("half_width_after_um")).toDouble(),
              proposal.value(QStringLiteral("half_width_before_um")).toDouble());
    EXPECT_FALSE(j.contains(QStringLiteral("refine")));
    // Inside the band the command exits 0 and proposes nothing (the preset's own request).
    QStringList ok = presetRequest(file);
    ok << QStringLiteral("--level-fraction") << QStringLiteral("0.5") << QStringLiteral("--verify")
       << QStringLiteral("--json");
    const CliResult held = runTrueturn(ok);
    ASSERT_EQ(held.exitCode, 0) << qPrintable(held.err);
    EXPECT_TRUE(held.err.isEmpty()) << qPrintable(held.err);
    EXPECT_FALSE(held.json().contains(QStringLiteral("proposal")));
}

TEST_F(FeedScheduleCommands, RefineClosesTheLoopAndSaysHowItGotThere) {
    const QString file = model();
    QStringList args = presetRequest(file);
    args[args.indexOf(QStringLiteral("--depth")) + 1] = QStringLiteral("0.5");
    args[args.indexOf(QStringLiteral("--feed-step")) + 1] = QStringLiteral("0.01");
    const QString refined = path(QStringLiteral("refined.json"));
    const QString program = path(QStringLiteral("pass.nc"));
    args << QStringLiteral("--level-fraction") << QStringLiteral("0") << QStringLiteral("--switch")
         << QStringLiteral("centred") << QStringLiteral("--verify") << QStringLiteral("--refine")
         << QStringLiteral("--experiment") << path(QStringLiteral("experiment.csv"))
         << QStringLiteral("--refined-model") << refined << QStringLiteral("--gcode") << program
         << QStringLiteral("--json");
    const CliResult r = runTrueturn(args);
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(j.value(QStringLiteral("switch")).toString(), QStringLiteral("centred"));
    const QJsonObject refine = j.value(QStringLiteral("refine")).toObject();
    const QJsonArray rounds = refine.value(QStringLiteral("rounds")).toArray();
    EXPECT_GT(refine.value(QStringLiteral("initial")).toObject().value(QStringLiteral("max_deviation_pct")).toDouble(),
              10.0);
    ASSERT_GE(rounds.size(), 1);
    EXPECT_EQ(refine.value(QStringLiteral("rounds_run")).toInt(), rounds.size());
    EXPECT_LE(rounds.size(), refine.value(QStringLiteral("max_rounds")).toInt());
    EXPECT_EQ(refine.value(QStringLiteral("max_rounds")).toInt(), 3);
    int bars = 0;
    for (const QJsonValue& v : rounds) {
        const QJsonObject round = v.toObject();
        bars += round.value(QStringLiteral("plan")).toObject().value(QStringLiteral("bar_count")).toInt();
        EXPECT_TRUE(round.contains(QStringLiteral("verify")) || round.contains(QStringLiteral("problem")));
    }
    EXPECT_EQ(refine.value(QStringLiteral("bars")).toInt(), bars);
    EXPECT_TRUE(refine.value(QStringLiteral("within_10_pct")).toBool());
    // The result is the last round's: the schedule's verify is that round's.
    const QJsonObject last = rounds.last().toObject().value(QStringLiteral("verify")).toObject();
    EXPECT_DOUBLE_EQ(j.value(QStringLiteral("verify")).toObject().value(QStringLiteral("max_deviation_pct")).toDouble(),
                     last.value(QStringLiteral("max_deviation_pct")).toDouble());
    EXPECT_LE(last.value(QStringLiteral("max_deviation_pct")).toDouble(), 10.0);
    // The refined model file: one depth, cubic in f and z; the program names it.
    QFile saved(refined);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    const QJsonObject m = QJsonDocument::fromJson(saved.readAll()).object();
    EXPECT_EQ(m.value(QStringLiteral("term_set")).toString(), QStringLiteral("cubic-fz"));
    const QJsonObject a = m.value(QStringLiteral("factors")).toObject().value(QStringLiteral("a_mm")).toObject();
    EXPECT_DOUBLE_EQ(a.value(QStringLiteral("min")).toDouble(), 0.5);
    EXPECT_DOUBLE_EQ(a.value(QStringLiteral("max")).toDouble(), 0.5);
    QFile nc(program);
    ASSERT_TRUE(nc.open(QIODevice::ReadOnly));
    EXPECT_TRUE(nc.readAll().contains("CUBIC-FZ"));  // comments are upper case
    // It schedules on its own as a model file.
    QStringList again = presetRequest(refined);
    again[again.indexOf(QStringLiteral("--depth")) + 1] = QStringLiteral("0.5");
    again << QStringLiteral("--level-fraction") << QStringLiteral("0") << QStringLiteral("--switch")
          << QStringLiteral("centred");
    EXPECT_EQ(runTrueturn(again).exitCode, 0);
    // Refusals: --refine needs --verify; the limits of the options.
    QStringList noVerify = presetRequest(file);
    noVerify << QStringLiteral("--level-fraction") << QStringLiteral("0") << QStringLiteral("--refine");
    expectRefused(noVerify, QStringLiteral("--refine needs --verify"));
    QStringList rounds11 = noVerify;
    rounds11 << QStringLiteral("--verify") << QStringLiteral("--refine-rounds") << QStringLiteral("11");
    expectRefused(rounds11, QStringLiteral("--refine-rounds"));
    QStringList badSwitch = presetRequest(file);
    badSwitch << QStringLiteral("--level-fraction") << QStringLiteral("0") << QStringLiteral("--switch")
              << QStringLiteral("middle");
    expectRefused(badSwitch, QStringLiteral("--switch"));
}

TEST_F(FeedScheduleCommands, TextOutputAndTheLevelInMicrometres) {
    const QString file = model();
    const double y1 = 24.0;  // below Y1 (about 24.4 um): refused; 27 um inside [Y1, Y2]: scheduled
    QStringList refused = presetRequest(file);
    refused << QStringLiteral("--level") << QString::number(y1);
    expectRefused(refused, QStringLiteral("is outside [Y1, Y2]"));
    QStringList args = presetRequest(file);
    args << QStringLiteral("--level") << QStringLiteral("27");
    const CliResult r = runTrueturn(args);
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Yc 27.00 um"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("saved"))) << qPrintable(r.out);
    const CliResult fit = runTrueturn({QStringLiteral("fit-deformation"), path(QStringLiteral("experiment.csv"))});
    ASSERT_EQ(fit.exitCode, 0) << qPrintable(fit.err);
    EXPECT_TRUE(fit.out.contains(QStringLiteral("adjusted R²"))) << qPrintable(fit.out);
    EXPECT_TRUE(fit.out.contains(QStringLiteral("2 sigma"))) << qPrintable(fit.out);
}

TEST_F(FeedScheduleCommands, RefusesBadRequestsWithOneLine) {
    const QString file = model();
    const auto with = [&](QStringList extra) {
        QStringList args = presetRequest(file);
        args << extra;
        return args;
    };
    expectRefused(with({QStringLiteral("--level-fraction"), QStringLiteral("0.5"), QStringLiteral("--level"),
                        QStringLiteral("27")}),
                  QStringLiteral("exactly one of --level"));
    expectRefused(with({}), QStringLiteral("exactly one of --level"));
    QStringList zeroStep = with({QStringLiteral("--level-fraction"), QStringLiteral("0.5")});
    zeroStep[zeroStep.indexOf(QStringLiteral("--feed-step")) + 1] = QStringLiteral("0");
    expectRefused(zeroStep, QStringLiteral("the feed step f_mm 0 mm/rev must be above 0"));
    QStringList sameZ = with({QStringLiteral("--level-fraction"), QStringLiteral("0.5")});
    sameZ[sameZ.indexOf(QStringLiteral("--z-end")) + 1] = QStringLiteral("380");
    expectRefused(sameZ, QStringLiteral("z_start and z_end are both 380 mm"));
    QStringList deep = with({QStringLiteral("--level-fraction"), QStringLiteral("0.5")});
    deep[deep.indexOf(QStringLiteral("--depth")) + 1] = QStringLiteral("3");
    expectRefused(deep, QStringLiteral("the depth of cut 3 mm is outside the model's range 0.5 .. 2 mm"));
    QStringList reversed = with({QStringLiteral("--level-fraction"), QStringLiteral("0.5")});
    reversed[reversed.indexOf(QStringLiteral("--z-start")) + 1] = QStringLiteral("60");
    reversed[reversed.indexOf(QStringLiteral("--z-end")) + 1] = QStringLiteral("380");
    expectRefused(reversed, QStringLiteral("no feed between fmin"));
    expectRefused(with({QStringLiteral("--level-fraction"), QStringLiteral("0.5"), QStringLiteral("--dialect"),
                        QStringLiteral("heidenhain")}),
                  QStringLiteral("--dialect"));
    const QString notJson = write(QStringLiteral("bad.json"), "{\"kind\": \"something else\"}");
    QStringList badModel = presetRequest(notJson);
    badModel << QStringLiteral("--level-fraction") << QStringLiteral("0.5");
    expectRefused(badModel, QStringLiteral("not a force-deformation model file"));
    // fit-deformation: a bad header, an unknown term set, too few levels for the terms.
    expectRefused({QStringLiteral("fit-deformation"), write(QStringLiteral("h.csv"), "a,f,z,y\n1,2,3,4\n")},
                  QStringLiteral("expected the header 'a_mm,f_mm_rev,z_mm,y_um'"));
    expectRefused({QStringLiteral("fit-deformation"), path(QStringLiteral("experiment.csv")), QStringLiteral("--terms"),
                   QStringLiteral("quartic")},
                  QStringLiteral("--terms"));
    expectRefused(
        {QStringLiteral("fit-deformation"), write(QStringLiteral("two.csv"),
                                                  "a_mm,f_mm_rev,z_mm,y_um\n1,0.1,10,5\n2,0.1,10,6\n1,0.2,10,7\n"
                                                  "2,0.2,10,8\n1,0.1,20,5\n2,0.2,20,9\n")},
        QStringLiteral("a^2 needs at least 3 different depths of cut a; the data has 2"));
    // A model fitted without a set-up has no machine job: schedule-feed says so.
    const QString bare = write(QStringLiteral("bare.csv"),
                               "a_mm,f_mm_rev,z_mm,y_um\n1,0.1,10,5\n2,0.1,10,6\n"
                               "1,0.2,10,7\n2,0.2,10,8\n1,0.1,20,6\n2,0.2,20,10\n");
    const CliResult bareFit =
        runTrueturn({QStringLiteral("fit-deformation"), bare, QStringLiteral("--terms"), QStringLiteral("linear"),
                     QStringLiteral("--out"), path(QStringLiteral("bare.json"))});
    ASSERT_EQ(bareFit.exitCode, 0) << qPrintable(bareFit.err);
    expectRefused(
        {QStringLiteral("schedule-feed"), QStringLiteral("--model"), path(QStringLiteral("bare.json")),
         QStringLiteral("--depth"), QStringLiteral("1.5"), QStringLiteral("--feed-min"), QStringLiteral("0.1"),
         QStringLiteral("--feed-max"), QStringLiteral("0.2"), QStringLiteral("--feed-step"), QStringLiteral("0.01"),
         QStringLiteral("--z-start"), QStringLiteral("20"), QStringLiteral("--z-end"), QStringLiteral("10"),
         QStringLiteral("--level-fraction"), QStringLiteral("0.5")},
        QStringLiteral("has no machine job"));
    expectRefused({QStringLiteral("deformation-experiment"), QStringLiteral("--preset"), QStringLiteral("paper-2012"),
                   QStringLiteral("--csv"), path(QStringLiteral("x.csv"))},
                  QStringLiteral("--preset paper-2012"));
}

}  // namespace
