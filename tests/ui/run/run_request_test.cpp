// One run request, one run: the same request JSON started from the Run page (offscreen, its loop paced by the
// wall clock in the loop thread) and given to `trueturn simulate --request FILE.json --db ...` (headless, as
// fast as possible) machines the same parts, so their stored diameters are equal bit for bit; and
// `simulate --dump-request` prints the request its options make. Source of the expectation: both drive the
// engine through core::ShaftRunStepper, which moves the simulated lathe from event to event in the same order
// whatever the pace.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QTest>
#include <vector>

#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "run_window.h"
#include "runtime/run/run_request.h"
#include "runtime/run/run_session.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {
namespace {

constexpr std::int64_t kParts = 30;

/// Every stored diameter of the only run of `path`, part by part and point by point.
std::vector<double> storedDiameters(const QString& path) {
    storage::Database db(storage::DatabaseConfig::sqlite(path));
    storage::SqlHistoryStore history(db);
    std::vector<double> out;
    const std::vector<core::RunSummary> runs = history.runs();
    if (runs.size() != 1) return out;
    for (const core::StoredPart& part : history.parts(runs.front().runId))
        if (part.measurement)
            for (const core::PointMeasurementRecord& p : part.measurement->points)
                out.push_back(p.measuredMm.value_or(-1.0));
    return out;
}

/// Runs the trueturn binary; its exit code and standard output.
std::pair<int, QByteArray> trueturn(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(TRUETURN_EXE), arguments);
    process.waitForFinished(-1);
    return {process.exitCode(), process.readAllStandardOutput()};
}

class RunRequestTest : public test::RunWindowTest {
protected:
    runtime::RunRequest request() const {
        runtime::RunRequest r;
        r.preset = QStringLiteral("paper-2012-group1");
        r.delay = 2;
        r.seed = 11;
        r.endPart = kParts;
        r.speed = 1e6;  // the Run page paces it; the command line runs it as fast as it can
        return r;
    }
};

TEST_F(RunRequestTest, TheSameRequestGivesTheSameStoredDiametersFromTheRunPageAndTheCommandLine) {
    const QString file = dir.filePath(QStringLiteral("request.json"));
    QFile out(file);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(runtime::toJson(request())).toJson());
    out.close();
    const QString cliDb = dir.filePath(QStringLiteral("cli.sqlite"));
    const auto [code, json] =
        trueturn({QStringLiteral("simulate"), QStringLiteral("--request"), file, QStringLiteral("--db"), cliDb,
                  QStringLiteral("--json")});
    ASSERT_EQ(code, 0) << json.toStdString();

    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    runtime::RunRequest fromFile = runtime::readRunRequestFile(file);
    fromFile.database = context.databasePath;
    ASSERT_TRUE(page->shaft().startRequest(fromFile));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return page->session().snapshot().runId && page->session().snapshot().state == core::LoopState::Idle;
        },
        120000))
        << core::describe(page->session().snapshot().status);

    const std::vector<double> gui = storedDiameters(context.databasePath);
    const std::vector<double> cli = storedDiameters(cliDb);
    ASSERT_EQ(gui.size(), static_cast<std::size_t>(kParts * 5)) << "every part measured at its five points";
    ASSERT_EQ(cli.size(), gui.size());
    for (std::size_t i = 0; i < gui.size(); ++i)
        ASSERT_EQ(gui[i], cli[i]) << "reading " << i << " (part " << i / 5 + 1 << ", point " << i % 5 + 1 << ")";
}

TEST_F(RunRequestTest, DumpRequestPrintsTheRequestTheOptionsMake) {
    const auto [code, json] = trueturn({QStringLiteral("simulate"), QStringLiteral("--preset"),
                                        QStringLiteral("paper-2012"), QStringLiteral("--parts"), QStringLiteral("500"),
                                        QStringLiteral("--warmup"), QStringLiteral("20"), QStringLiteral("--seed"),
                                        QStringLiteral("4"), QStringLiteral("--plant-gain"), QStringLiteral("0.7"),
                                        QStringLiteral("--integral"), QStringLiteral("on"),
                                        QStringLiteral("--dump-request")});
    ASSERT_EQ(code, 0);
    const runtime::RunRequest dumped = runtime::runRequestFromJson(QJsonDocument::fromJson(json).object());
    EXPECT_EQ(dumped.preset, QStringLiteral("paper-2012"));
    EXPECT_EQ(dumped.endPart, std::optional<std::int64_t>(520));
    EXPECT_EQ(dumped.warmupParts, 20);
    EXPECT_EQ(dumped.seed, 4u);
    EXPECT_EQ(dumped.plant.gainFactor, std::optional<double>(0.7));
    EXPECT_EQ(dumped.integral, std::optional<bool>(true));
    // The dump is itself a request the command line runs.
    EXPECT_NO_THROW(runtime::validate(dumped));
}

}  // namespace
}  // namespace tt::ui
