// The CNC program of a feed schedule read by a real interpreter: LinuxCNC's standalone rs274 (Debian
// package linuxcnc-uspace, installed by scripts/install-deps.sh --with-test-tools). Its canonical output
// (SET_FEED_RATE, STRAIGHT_FEED) must show the schedule's z breakpoints and feeds, in each dialect.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <cmath>
#include <vector>

#include "cli_test.h"
#include "tests/support/patient_wait.h"

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

/// One feed move of the canonical output: the feed in force and where the move ends.
struct FeedMove {
    double feed = 0.0;
    double x = 0.0;
    double z = 0.0;
};

struct Interpreted {
    int exitCode = -1;
    QString out;
    QString err;
    std::vector<FeedMove> moves;
};

Interpreted interpret(const QString& program, const QString& toolTable) {
    Interpreted r;
    const QString rs274 = QStandardPaths::findExecutable(QStringLiteral("rs274"));
    if (rs274.isEmpty()) {
        ADD_FAILURE() << "rs274 not found: install linuxcnc-uspace (scripts/install-deps.sh --with-test-tools, "
                         "apt-get install --no-install-recommends linuxcnc-uspace)";
        return r;
    }
    QProcess p;
    p.start(rs274, {QStringLiteral("-t"), toolTable, QStringLiteral("-g"), program});
    p.closeWriteChannel();
    p.waitForFinished(tt::test::kPatientWaitMs);
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    // "   25 N..... SET_FEED_RATE(0.0641)", "   26 N..... STRAIGHT_FEED(25.0000, 0.0000, -20.0000, ...)"
    const QRegularExpression feedRate(QStringLiteral("SET_FEED_RATE\\(([-0-9.]+)\\)"));
    const QRegularExpression straight(QStringLiteral("STRAIGHT_FEED\\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+),"));
    double feed = 0.0;
    for (const QString& line : r.out.split(QLatin1Char('\n'))) {
        if (const auto m = feedRate.match(line); m.hasMatch()) feed = m.captured(1).toDouble();
        if (const auto m = straight.match(line); m.hasMatch())
            r.moves.push_back({feed, m.captured(1).toDouble(), m.captured(3).toDouble()});
    }
    return r;
}

class Rs274 : public tt::test::CliTest, public ::testing::WithParamInterface<const char*> {
protected:
    void SetUp() override {
        const QString csv = path(QStringLiteral("e.csv"));
        ASSERT_EQ(runTrueturn({QStringLiteral("deformation-experiment"), QStringLiteral("--preset"),
                               QStringLiteral("feed-scheduling"), QStringLiteral("--csv"), csv})
                      .exitCode,
                  0);
        ASSERT_EQ(runTrueturn({QStringLiteral("fit-deformation"), csv, QStringLiteral("--stepwise"),
                               QStringLiteral("--out"), path(QStringLiteral("model.json"))})
                      .exitCode,
                  0);
        // Tool 1 for LinuxCNC's "T1 M6"; a Fanuc T0101 (tool 1, offset 1) reads as tool 101 in rs274ngc.
        write(QStringLiteral("tools.tbl"), "T1 P1 X0 Z0 D0.8 ;finishing tool\nT101 P2 X0 Z0 D0.8 ;Fanuc T0101\n");
    }
};

TEST_P(Rs274, AcceptsTheProgramAndMovesAsScheduled) {
    const QString dialect = QString::fromLatin1(GetParam());
    const QString program = path(QStringLiteral("pass_%1.nc").arg(dialect));
    const CliResult r = runTrueturn({QStringLiteral("schedule-feed"),
                                     QStringLiteral("--model"),
                                     path(QStringLiteral("model.json")),
                                     QStringLiteral("--depth"),
                                     QStringLiteral("1.5"),
                                     QStringLiteral("--feed-min"),
                                     QStringLiteral("0.05"),
                                     QStringLiteral("--feed-max"),
                                     QStringLiteral("0.4"),
                                     QStringLiteral("--feed-step"),
                                     QStringLiteral("0.005"),
                                     QStringLiteral("--z-start"),
                                     QStringLiteral("380"),
                                     QStringLiteral("--z-end"),
                                     QStringLiteral("60"),
                                     QStringLiteral("--level-fraction"),
                                     QStringLiteral("0.5"),
                                     QStringLiteral("--min-length"),
                                     QStringLiteral("5"),
                                     QStringLiteral("--dialect"),
                                     dialect,
                                     QStringLiteral("--gcode"),
                                     program,
                                     QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonArray segments = r.json().value(QStringLiteral("segments")).toArray();
    ASSERT_GE(segments.size(), 10);

    const Interpreted run = interpret(program, path(QStringLiteral("tools.tbl")));
    ASSERT_EQ(run.exitCode, 0) << qPrintable(run.err) << qPrintable(run.out.right(2000));
    EXPECT_TRUE(run.out.contains(QStringLiteral("PROGRAM_END()")));
    EXPECT_TRUE(run.out.contains(QStringLiteral("SET_FEED_MODE(0, 1)")));               // G95: units per revolution
    EXPECT_TRUE(run.out.contains(QStringLiteral("SELECT_PLANE(CANON_PLANE_XZ)")));      // G18
    EXPECT_TRUE(run.out.contains(QStringLiteral("USE_LENGTH_UNITS(CANON_UNITS_MM)")));  // G21
    EXPECT_TRUE(run.out.contains(QStringLiteral("SET_SPINDLE_SPEED(0, 720.0000)")));
    EXPECT_TRUE(run.out.contains(QStringLiteral("START_SPINDLE_CLOCKWISE")));
    EXPECT_TRUE(run.out.contains(QStringLiteral("FLOOD_ON()")));
    EXPECT_TRUE(run.out.contains(QStringLiteral("FLOOD_OFF()")));

    // The approach feed move to z_start, then one feed move per segment: machine Z = z - 400 (the preset's
    // job), the feed of the segment rounded down to 0.0001 mm/rev, all on the 50 mm diameter.
    ASSERT_EQ(run.moves.size(), static_cast<std::size_t>(segments.size()) + 1);
    EXPECT_NEAR(run.moves[0].z, 380.0 - 400.0, 5e-4);
    const double xOfPass = dialect == QStringLiteral("linuxcnc") ? 25.0 : 50.0;  // G7: rs274 reports the radius
    for (qsizetype i = 0; i < segments.size(); ++i) {
        const QJsonObject g = segments.at(i).toObject();
        const FeedMove& m = run.moves[static_cast<std::size_t>(i) + 1];
        EXPECT_NEAR(m.z, g.value(QStringLiteral("z_to")).toDouble() - 400.0, 5e-4) << "segment " << i + 1;
        const double feed = g.value(QStringLiteral("f")).toDouble();
        EXPECT_NEAR(m.feed, std::floor(feed * 1e4 + 1e-6) / 1e4, 1e-9) << "segment " << i + 1;
        EXPECT_LE(m.feed, feed) << "segment " << i + 1;
        EXPECT_NEAR(m.x, xOfPass, 1e-4) << "segment " << i + 1;
    }
}

INSTANTIATE_TEST_SUITE_P(Dialects, Rs274, ::testing::Values("fanuc", "linuxcnc"));

TEST(Rs274Check, RefusesABrokenProgram) {
    // The check is not vacuous: rs274 exits non-zero on a program it cannot read.
    QTemporaryDir dir;
    const QString program = dir.filePath(QStringLiteral("broken.nc"));
    tt::test::writeFile(program, "%\nG18 G21 G90 G95\nG1 Z-10 Q\nM30\n%\n");
    const QString tools = dir.filePath(QStringLiteral("t.tbl"));
    tt::test::writeFile(tools, "T1 P1 X0 Z0 D0.8 ;t\n");
    EXPECT_NE(interpret(program, tools).exitCode, 0);
}

}  // namespace
