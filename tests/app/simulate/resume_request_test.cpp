// A run is stored with its whole run request, so a run started with a plant that differs from the model and with
// integral action resumes with both: cut off with SIGTERM part-way and continued with `simulate --resume`, it
// stores the same diameters as the same run left alone (the simulated lathe depends only on the part number
// and the corrections its parts received, and the controller continues from its stored state; 1e-12 mm allows
// for nothing but the stored state's rounding), and the resumed run's JSON reports the plant gain and the
// integral action it ran with.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>

#include "cli_test.h"
#include "tests/support/stored_runs.h"

namespace tt {
namespace {

const QStringList kRun{QStringLiteral("--preset"),     QStringLiteral("paper-2012"), QStringLiteral("--delay"),
                       QStringLiteral("2"),            QStringLiteral("--parts"),    QStringLiteral("400"),
                       QStringLiteral("--warmup"),     QStringLiteral("0"),          QStringLiteral("--seed"),
                       QStringLiteral("3"),            QStringLiteral("--plant-gain"), QStringLiteral("0.7"),
                       QStringLiteral("--integral"),   QStringLiteral("on")};

class ResumeRequest : public test::CliTest {};

TEST_F(ResumeRequest, APlantMismatchAndIntegralActionSurviveAnInterruption) {
    const QString whole = path(QStringLiteral("whole.sqlite"));
    const test::CliResult left = test::runTrueturn(QStringList{QStringLiteral("simulate")} + kRun +
                                                   QStringList{QStringLiteral("--db"), whole, QStringLiteral("--json")});
    ASSERT_EQ(left.exitCode, 0) << qPrintable(left.err);

    const QString cut = path(QStringLiteral("cut.sqlite"));
    // Paced (a 6-minute part in 20 ms) so that it can be cut off after part 60.
    const int code = test::interruptedSimulate(
        QStringLiteral(TRUETURN_EXE), kRun + QStringList{QStringLiteral("--db"), cut, QStringLiteral("--speed"),
                                                         QStringLiteral("18000")},
        60);
    ASSERT_EQ(code, 130) << "stopped after a part by SIGTERM";
    const test::CliResult resumed = test::runTrueturn(
        {QStringLiteral("simulate"), QStringLiteral("--db"), cut, QStringLiteral("--resume"), QStringLiteral("--json")});
    ASSERT_EQ(resumed.exitCode, 0) << qPrintable(resumed.err);
    const QJsonObject json = QJsonDocument::fromJson(resumed.out.toUtf8()).object();
    EXPECT_DOUBLE_EQ(json.value(QStringLiteral("plant")).toObject().value(QStringLiteral("gain_factor")).toDouble(),
                     0.7);
    EXPECT_TRUE(json.value(QStringLiteral("integral")).isObject()) << "integral action on after the resume";

    const std::vector<double> a = test::storedDiameters(whole);
    const std::vector<double> b = test::storedDiameters(cut);
    ASSERT_EQ(a.size(), 400u * 5u);
    ASSERT_EQ(b.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_NEAR(a[i], b[i], 1e-12) << "reading " << i << " (part " << i / 5 + 1 << ")";
}

}  // namespace
}  // namespace tt
