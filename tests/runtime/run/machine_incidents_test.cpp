// A machine's incidents (a real CNC unreachable, a write it refused: core::ShaftMachine::takeIncidents) reach the
// Run page as alarms and are stored as alarms of the run (kind "machine"), as `simulate --cnc --db` stores them.
// The machine here is the built-in simulated lathe that reports one incident when part 3 is done.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QStringList>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "core/run/simulated_lathe.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "runtime/run/run_session.h"
#include "tests/support/patient_wait.h"

namespace tt::runtime {
namespace {

constexpr const char* kIncident = "LinuxCNC at 10.0.0.7:5007 did not answer: the correction of part 4 is held";

/// The simulated lathe, reporting kIncident once its clock has passed the third part.
class IncidentLathe final : public core::ShaftMachine {
public:
    explicit IncidentLathe(std::shared_ptr<core::SimulatedLathe> inner) : m_inner(std::move(inner)) {}
    core::MachineCycle& cycle() override { return m_inner->cycle(); }
    core::CorrectionOutput& output() override { return m_inner->output(); }
    core::DiameterGauge& gauge() override { return m_inner->gauge(); }
    const core::Clock& clock() const override { return m_inner->clock(); }
    double nextEventTimeS() const override { return m_inner->nextEventTimeS(); }
    bool jumpTo(double timeS) override { return m_inner->jumpTo(timeS); }
    std::size_t setManualEntry(bool manual) override { return m_inner->setManualEntry(manual); }
    std::optional<core::TrueProfile> trueProfile(std::int64_t part) const override {
        return m_inner->trueProfile(part);
    }
    void partMeasured(std::int64_t part) override {
        m_measured = part;
        m_inner->partMeasured(part);
    }
    std::vector<std::string> takeIncidents() override {
        if (m_told || m_measured < 3) return {};
        m_told = true;
        return {kIncident};
    }

private:
    std::shared_ptr<core::SimulatedLathe> m_inner;
    std::int64_t m_measured = 0;
    bool m_told = false;
};

TEST(MachineIncidents, ReachTheRunPageAndAreStoredAsAlarmsOfTheRun) {
    QTemporaryDir dir;
    RunStart start;
    start.request.preset = QStringLiteral("paper-2012");
    start.request.endPart = 8;
    start.request.database = dir.filePath(QStringLiteral("history.sqlite"));
    start.machineName = QStringLiteral("incident lathe");
    start.can.adjustableSpeed = true;
    start.make = [](const core::ShaftScenario& scenario) -> std::shared_ptr<core::ShaftMachine> {
        return std::make_shared<IncidentLathe>(std::make_shared<core::SimulatedLathe>(scenario.shopSpec(1)));
    };
    RunSession session;
    QStringList incidents;
    QString failed;
    QObject::connect(&session, &RunSession::machineIncident, [&](const QString& text) { incidents << text; });
    QObject::connect(&session, &RunSession::startFailed, [&](const QString& why) { failed = why; });
    session.start(start);
    QElapsedTimer waited;
    waited.start();
    while (failed.isEmpty() && session.snapshot().partsFinished < 8 && waited.elapsed() < tt::test::kPatientWaitMs)
        QTest::qWait(20);
    ASSERT_TRUE(failed.isEmpty()) << failed.toStdString();
    ASSERT_EQ(incidents, QStringList{QString::fromLatin1(kIncident)});
    QTest::qWait(200);

    storage::Database db(storage::DatabaseConfig::sqlite(start.request.database));
    storage::SqlHistoryStore history(db);
    const std::vector<core::RunSummary> runs = history.runs();
    ASSERT_EQ(runs.size(), 1u);
    int machineAlarms = 0;
    for (const core::AlarmRecord& alarm : history.alarms(runs.front().runId))
        if (alarm.kind == "machine") {
            ++machineAlarms;
            EXPECT_EQ(alarm.message, kIncident);
        }
    EXPECT_EQ(machineAlarms, 1);
}

}  // namespace
}  // namespace tt::runtime
