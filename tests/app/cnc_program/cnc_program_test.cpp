// `trueturn cnc-program`: the parametric LinuxCNC part program, read by LinuxCNC's standalone interpreter rs274
// (Debian package linuxcnc-uspace; run with a HOME of its own: it shares $HOME/.tool.mmap with a running
// LinuxCNC). Its parameters come from a parameter file; the cutter path rs274 reports (STRAIGHT_FEED, X as a
// radius, four decimals) must be the approximation unit's path core::buildCorrectionPath for those corrections,
// the same samples a G-code file output gets.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "cli_test.h"
#include "config/loop_scenario.h"
#include "core/control/correction_path_builder.h"
#include "core/loop/loop_engine.h"

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

struct Move {
    double x = 0.0;  ///< radius, program units
    double z = 0.0;
};

struct Interpreted {
    int exitCode = -1;
    QString out;
    std::vector<Move> feeds;
};

Interpreted interpret(const QString& program, const QString& tools, const QString& parameters) {
    Interpreted r;
    const QString rs274 = QStandardPaths::findExecutable(QStringLiteral("rs274"));
    if (rs274.isEmpty()) {
        ADD_FAILURE() << "rs274 not found: install linuxcnc-uspace (scripts/install-deps.sh --with-test-tools)";
        return r;
    }
    QTemporaryDir home;
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("HOME"), home.path());
    p.setProcessEnvironment(env);
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(rs274, {QStringLiteral("-t"), tools, QStringLiteral("-v"), parameters, QStringLiteral("-g"), program});
    p.closeWriteChannel();
    p.waitForFinished(60000);
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAll());
    const QRegularExpression straight(QStringLiteral("STRAIGHT_FEED\\(([-0-9.]+), [-0-9.]+, ([-0-9.]+),"));
    for (const QString& line : r.out.split(QLatin1Char('\n')))
        if (const auto m = straight.match(line); m.hasMatch())
            r.feeds.push_back({m.captured(1).toDouble(), m.captured(2).toDouble()});
    return r;
}

const std::vector<double> kCorrectionsMm{0.0123, -0.0211, 0.0157, 0.0309, -0.0087};

class CncProgram : public tt::test::CliTest {
protected:
    QString tools() { return write(QStringLiteral("tools.tbl"), "T1 P1 X0 Z0 D0.8 ;finishing tool\n"); }
    /// A parameter file with the corrections (radial mm, doubled in diameter mode) and the part number.
    QString parameters(const std::vector<double>& radialMm, bool diameter, int partNumber = 7) {
        QByteArray text;
        for (std::size_t i = 0; i < radialMm.size(); ++i)
            text += QByteArray::number(500 + static_cast<int>(i)) + '\t' +
                    QByteArray::number((diameter ? 2.0 : 1.0) * radialMm[i], 'f', 6) + '\n';
        if (partNumber > 0) text += "505\t" + QByteArray::number(partNumber) + '\n';
        return write(QStringLiteral("p.var"), text);
    }
    /// rs274's path against the approximation unit's for `preset`.
    void expectApproximationUnitsPath(const QString& preset, const QString& xMode) {
        const QString out = path(QStringLiteral("part.ngc"));
        const CliResult r =
            runTrueturn({QStringLiteral("cnc-program"), QStringLiteral("--preset"), preset, QStringLiteral("--dialect"),
                         QStringLiteral("linuxcnc"), QStringLiteral("--parametric"), QStringLiteral("500"),
                         QStringLiteral("--x-mode"), xMode, QStringLiteral("--out"), out, QStringLiteral("--json")});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        EXPECT_EQ(r.json().value(QStringLiteral("parameters")).toObject().value(QStringLiteral("part_number")).toInt(),
                  505);
        const Interpreted run = interpret(out, tools(), parameters(kCorrectionsMm, xMode == QLatin1String("diameter")));
        ASSERT_EQ(run.exitCode, 0) << qPrintable(run.out.right(3000));

        const tt::config::LoopScenario scenario = tt::config::loadLoopScenario(preset);
        const tt::core::PartCorrection reference =
            tt::core::partCorrectionFor(scenario.loopConfig(true, std::nullopt), 7, kCorrectionsMm);
        const auto& zs = reference.path.zMm;
        // The feed to half the clearance before the part, to the start of the cut, then one move per sample after
        // the first.
        ASSERT_EQ(run.feeds.size(), zs.size() + 1) << qPrintable(run.out.right(2000));
        EXPECT_NEAR(run.feeds[0].z, 1.0, 6e-5) << "half the 2 mm clearance before z = 0 (machine Z = -z)";
        double worst = 0.0;
        for (std::size_t i = 0; i < zs.size(); ++i) {
            const Move& m = run.feeds[i + 1];
            EXPECT_NEAR(m.z, -zs[i], 6e-5) << "sample " << i;
            const double x = 0.5 * scenario.nominalDiameterMm + reference.path.xCorrectionMm[i];
            worst = std::max(worst, std::fabs(m.x - x));
        }
        // rs274 prints four decimals: 0.05 um of rounding, nothing else.
        EXPECT_LE(worst, 6e-5) << "largest difference from the approximation unit's path, mm";
    }
};

TEST_F(CncProgram, Rs274CutsTheApproximationUnitsPathInRadiusMode) {
    expectApproximationUnitsPath(QStringLiteral("paper-2012-group1"), QStringLiteral("radius"));
}

TEST_F(CncProgram, Rs274CutsTheApproximationUnitsPathInDiameterMode) {
    expectApproximationUnitsPath(QStringLiteral("paper-2012-group1"), QStringLiteral("diameter"));
}

TEST_F(CncProgram, Rs274CutsTheNaturalSplineOfASetUpThatAsksForIt) {
    const QString preset = write(QStringLiteral("spline.json"),
                                 R"({"name": "spline", "based_on": "paper-2012-group1",
                                     "loop": {"nominal_diameter_mm": 27.0, "part_length_mm": 325,
                                              "path_step_mm": 0.5, "interpolation": "spline"}})");
    expectApproximationUnitsPath(preset, QStringLiteral("radius"));
}

TEST_F(CncProgram, TheProgramRefusesToCutWithoutTheCorrectionsOfThePartOrWithOneBeyondTheLimit) {
    const QString out = path(QStringLiteral("part.ngc"));
    ASSERT_EQ(
        runTrueturn({QStringLiteral("cnc-program"), QStringLiteral("--preset"), QStringLiteral("paper-2012-group1"),
                     QStringLiteral("--parametric"), QStringLiteral("500"), QStringLiteral("--out"), out})
            .exitCode,
        0);
    const Interpreted unset = interpret(out, tools(), parameters(kCorrectionsMm, true, 0));
    EXPECT_NE(unset.exitCode, 0);
    EXPECT_TRUE(unset.out.contains(QStringLiteral("NO CORRECTIONS WERE WRITTEN FOR THIS PART")))
        << qPrintable(unset.out);
    EXPECT_TRUE(unset.feeds.empty()) << "nothing is cut";
    std::vector<double> beyond = kCorrectionsMm;
    beyond[2] = 0.6;  // the set-up's limit is 0.5 mm radial
    const Interpreted tooLarge = interpret(out, tools(), parameters(beyond, true));
    EXPECT_NE(tooLarge.exitCode, 0);
    EXPECT_TRUE(tooLarge.out.contains(QStringLiteral("THE CORRECTION #502 IS BEYOND THE LARGEST CORRECTION")))
        << qPrintable(tooLarge.out);
    EXPECT_TRUE(tooLarge.feeds.empty());
}

TEST_F(CncProgram, TheWearProgramCutsTheNominalPathWithTheWearEntryApplied) {
    const QString out = path(QStringLiteral("wear.ngc"));
    const CliResult r =
        runTrueturn({QStringLiteral("cnc-program"), QStringLiteral("--preset"), QStringLiteral("paper-2012-group1"),
                     QStringLiteral("--wear-tool"), QStringLiteral("10001"), QStringLiteral("--units"),
                     QStringLiteral("inch"), QStringLiteral("--out"), out, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    EXPECT_EQ(r.json().value(QStringLiteral("mode")).toString(), QStringLiteral("wear"));
    const QString wearTools =
        write(QStringLiteral("wear.tbl"), "T1 P1 X0 Z0 D0.8 ;finishing tool\nT10001 P2 X0.0004 Z0 ;wear of T1\n");
    const Interpreted run = interpret(out, wearTools, parameters({}, false, 0));
    ASSERT_EQ(run.exitCode, 0) << qPrintable(run.out.right(2000));
    EXPECT_TRUE(run.out.contains(QStringLiteral("USE_TOOL_LENGTH_OFFSET(0.0004 0.0000 0.0000")))
        << qPrintable(run.out.left(3000));
    const tt::config::LoopScenario scenario = tt::config::loadLoopScenario(QStringLiteral("paper-2012-group1"));
    const auto nominal = tt::core::partCorrectionFor(scenario.loopConfig(true, std::nullopt), 1,
                                                     std::vector<double>(kCorrectionsMm.size(), 0.0));
    ASSERT_EQ(run.feeds.size(), nominal.path.zMm.size() + 1);
    for (std::size_t i = 0; i < nominal.path.zMm.size(); i += 50)
        EXPECT_NEAR(run.feeds[i + 1].x * 25.4, 13.5 + nominal.path.xCorrectionMm[i], 25.4 * 6e-5) << "sample " << i;
}

TEST_F(CncProgram, RefusesBadOptionsWithOneLine) {
    const QString out = path(QStringLiteral("p.ngc"));
    const QStringList base{QStringLiteral("cnc-program"), QStringLiteral("--preset"),
                           QStringLiteral("paper-2012-group1"), QStringLiteral("--out"), out};
    tt::test::expectRefused(base, QStringLiteral("--parametric"));
    tt::test::expectRefused(base + QStringList{QStringLiteral("--parametric"), QStringLiteral("500"),
                                               QStringLiteral("--wear-tool"), QStringLiteral("7")},
                            QStringLiteral("exactly one"));
    tt::test::expectRefused(base + QStringList{QStringLiteral("--parametric"), QStringLiteral("4999")},
                            QStringLiteral("--parametric"));
    tt::test::expectRefused(base + QStringList{QStringLiteral("--parametric"), QStringLiteral("500"),
                                               QStringLiteral("--dialect"), QStringLiteral("fanuc")},
                            QStringLiteral("--dialect"));
    tt::test::expectRefused(
        {QStringLiteral("cnc-program"), QStringLiteral("--preset"), QStringLiteral("no-such-set-up"),
         QStringLiteral("--parametric"), QStringLiteral("500"), QStringLiteral("--out"), out},
        QStringLiteral("no-such-set-up"));
}

}  // namespace
