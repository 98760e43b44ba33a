// `trueturn simulate --cnc linuxcnc://HOST:PORT`: the closed run's parts cut by the test LinuxCNC
// (scripts/start-test-linuxcnc.sh; the test FAILS when TRUETURN_LINUXCNC_URL is unset, like every LinuxCNC test), its
// systematic errors those of the same run on the built-in simulated lathe, every correction written read back; and
// the bad uses of the CNC options refused with a clear message.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <cmath>

#include "tests/app/cli_runner.h"
#include "tests/devices/support/linuxcnc_comparison.h"
#include "tests/devices/support/linuxcnc_test_machine.h"

namespace {

using tt::test::CliResult;
using tt::test::runTrueturn;

/// 60 parts through LinuxCNC take a few minutes of wall time.
constexpr int kRunTimeoutMs = 1'500'000;

QStringList sixtyParts(const QString& cnc) {
    return {QStringLiteral("simulate"),
            QStringLiteral("--preset"),
            QStringLiteral("paper-2012-group1"),
            QStringLiteral("--delay"),
            QStringLiteral("2"),
            QStringLiteral("--cnc"),
            cnc,
            QStringLiteral("--parts"),
            QStringLiteral("60"),
            QStringLiteral("--seed"),
            QStringLiteral("5")};
}

/// Per control point, the systematic error the simulate JSON reports, mm.
Eigen::VectorXd systematicOf(const QJsonObject& json) {
    const QJsonArray points = json.value(QStringLiteral("points")).toArray();
    Eigen::VectorXd v(points.size());
    for (qsizetype i = 0; i < points.size(); ++i)
        v(i) = points[i].toObject().value(QStringLiteral("systematic_mm")).toDouble(std::nan(""));
    return v;
}

/// The same run on the built-in simulated lathe: the request the --cnc options make, without the CNC.
CliResult builtInRun(const QString& cnc, const QTemporaryDir& folder) {
    const CliResult dumped = runTrueturn(sixtyParts(cnc) << QStringLiteral("--dump-request"));
    EXPECT_EQ(dumped.exitCode, 0) << dumped.err.toStdString();
    QJsonObject request = dumped.json();
    EXPECT_EQ(request.value(QStringLiteral("cnc")).toObject().value(QStringLiteral("url")).toString(), cnc);
    EXPECT_EQ(request.value(QStringLiteral("end_part")).toInt(), 60) << "no warm-up through a CNC";
    request.remove(QStringLiteral("cnc"));
    request.insert(QStringLiteral("machine"), QStringLiteral("simulated-lathe"));
    const QString path = folder.filePath(QStringLiteral("built-in.json"));
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(request).toJson());
    file.close();
    return runTrueturn({QStringLiteral("simulate"), QStringLiteral("--request"), path, QStringLiteral("--json")});
}

TEST(SimulateCnc, SixtyPartsThroughLinuxCncMatchTheBuiltInLatheAndEveryCorrectionIsReadBack) {
    TT_REQUIRE_LINUXCNC(lc);
    QTemporaryDir folder;
    const CliResult builtIn = builtInRun(lc->url(), folder);
    ASSERT_EQ(builtIn.exitCode, 0) << builtIn.err.toStdString();
    EXPECT_FALSE(builtIn.json().contains(QStringLiteral("cnc")));

    tt::test::bringUpNow(*lc);
    const CliResult through = runTrueturn(sixtyParts(lc->url()) << QStringLiteral("--json"), kRunTimeoutMs);
    ASSERT_EQ(through.exitCode, 0) << through.err.toStdString();
    const QJsonObject json = through.json();
    EXPECT_EQ(json.value(QStringLiteral("cnc")).toString(), QStringLiteral("linuxcnc"));
    EXPECT_EQ(json.value(QStringLiteral("parts")).toInt(), 60);
    EXPECT_EQ(json.value(QStringLiteral("systematic_from_part")).toInt(), 2 * 2 + 6);

    const QJsonObject corrections = json.value(QStringLiteral("cnc_corrections")).toObject();
    const int written = corrections.value(QStringLiteral("written")).toInt();
    const int readBack = corrections.value(QStringLiteral("read_back")).toInt();
    RecordProperty("written", written);
    RecordProperty("read_back", readBack);
    EXPECT_GE(written, 60) << "one write per part at least (a part cut again is written again)";
    EXPECT_EQ(readBack, written);
    EXPECT_EQ(corrections.value(QStringLiteral("not_written")).toInt(), 0);
    EXPECT_LE(corrections.value(QStringLiteral("incidents")).toArray().size(), 3);

    tt::test::expectSystematicErrorsMatch(systematicOf(builtIn.json()), systematicOf(json));
}

/// A refused invocation: exit `code`, one line on stderr that contains `words`.
void expectRefused(const QStringList& extra, int code, const QString& words) {
    QStringList args{QStringLiteral("simulate"), QStringLiteral("--preset"), QStringLiteral("paper-2012-group1"),
                     QStringLiteral("--parts"), QStringLiteral("100")};
    const CliResult r = runTrueturn(args << extra);
    EXPECT_EQ(r.exitCode, code) << extra.join(QLatin1Char(' ')).toStdString() << ": " << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(words)) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
}

TEST(SimulateCnc, CncModeWithoutCncIsAUsageError) {
    expectRefused({QStringLiteral("--cnc-mode"), QStringLiteral("wear")}, 2,
                  QStringLiteral("--cnc-mode: only with --cnc"));
}

TEST(SimulateCnc, AnUnknownSchemeIsAUsageError) {
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("fanuc://127.0.0.1:8193")}, 2,
                  QStringLiteral("is not linuxcnc://HOST[:PORT]"));
}

TEST(SimulateCnc, ABadPortIsAUsageError) {
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1:99999")}, 2,
                  QStringLiteral("--cnc: the port '99999'"));
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1:x")}, 2, QStringLiteral("--cnc:"));
}

TEST(SimulateCnc, AModeOtherThanProfileOrWearIsAUsageError) {
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1"), QStringLiteral("--cnc-mode"),
                   QStringLiteral("offset")},
                  2, QStringLiteral("--cnc-mode"));
}

TEST(SimulateCnc, APresetWithoutALatheOrAPaceIsAUsageError) {
    const CliResult r = runTrueturn({QStringLiteral("simulate"), QStringLiteral("--preset"),
                                     QStringLiteral("paper-2012"), QStringLiteral("--parts"), QStringLiteral("20"),
                                     QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1:1")});
    EXPECT_EQ(r.exitCode, 2) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--preset: a run through a CNC needs a preset with a lathe section")))
        << r.err.toStdString();
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1:1"), QStringLiteral("--speed"),
                   QStringLiteral("10")},
                  2, QStringLiteral("--speed: a run through a CNC goes at the machine's own pace"));
}

TEST(SimulateCnc, AnUnreachableLinuxCncFailsAsADeviceDoesNamingIt) {
    // Nothing listens on port 1 of this computer: the connection is refused at once.
    expectRefused({QStringLiteral("--cnc"), QStringLiteral("linuxcnc://127.0.0.1:1")}, 1,
                  QStringLiteral("LinuxCNC at 127.0.0.1:1 does not answer"));
}

}  // namespace
