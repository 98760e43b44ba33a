// The closed loop through a real CNC: the run-to-run loop (core::LoopEngine, assembled by buildShaftRun as for
// every machine) on the LinuxCNC lathe. LinuxCNC cuts every part; the built-in physics is applied to the path it
// executed. The loop must do what it does on the built-in simulated lathe, and hold (not fault, not lose what is
// stored) while LinuxCNC is killed and started again. The runtime's part is played here by the stepping loop:
// it steps the engine, and records the machine's incidents as alarms of the run (what the runtime must do).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <QTemporaryDir>
#include <cmath>

#include "config/loop_scenario.h"
#include "core/run/shaft_run.h"
#include "core/run/shaft_run_builder.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"
#include "devices/linuxcnc/linuxcnc_lathe_offer.h"
#include "devices/linuxcnc/linuxcnc_settings.h"
#include "tests/devices/support/linuxcnc_comparison.h"
#include "tests/devices/support/linuxcnc_test_machine.h"

namespace {

using namespace tt;
using devices::linuxcnc::LinuxCncLathe;

/// The true diameter deviation of each finished part at the control points (as runLatheLoop records it).
class PartCollector final : public core::LoopListener {
public:
    PartCollector(core::ShaftMachine& machine, std::vector<double> points, double nominal)
        : m_machine(machine), m_points(std::move(points)), m_nominal(nominal) {}
    void onLoopEvent(const core::LoopEvent& event) override {
        if (event.kind == core::LoopEvent::Kind::StateChanged && event.state == core::LoopState::Fault)
            faults.push_back(event.message);
        if (event.kind != core::LoopEvent::Kind::PartFinished) return;
        const auto profile = m_machine.trueProfile(event.partNumber);
        ASSERT_TRUE(profile.has_value()) << "part " << event.partNumber;
        core::TurnedPart part{event.partNumber, profile->zMm, {}};
        for (const double e : profile->errorMm)
            part.diameterMm.push_back(m_nominal + e);
        Eigen::VectorXd at(static_cast<Eigen::Index>(m_points.size()));
        for (std::size_t i = 0; i < m_points.size(); ++i)
            at(static_cast<Eigen::Index>(i)) = part.diameterAtMm(m_points[i]) - m_nominal;
        if (deviations.size() < static_cast<std::size_t>(event.partNumber)) deviations.resize(event.partNumber);
        deviations[static_cast<std::size_t>(event.partNumber - 1)] = at;
    }
    std::vector<Eigen::VectorXd> deviations;
    std::vector<std::string> faults;

private:
    core::ShaftMachine& m_machine;
    std::vector<double> m_points;
    double m_nominal;
};

/// Steps the engine until it completes (or `seconds` pass), recording the machine's incidents as alarms of the run
/// (when there is a history) and in `incidents`.
bool runToEnd(core::LoopEngine& engine, LinuxCncLathe& lathe, core::HistoryStore* history, double seconds,
              std::vector<std::string>& incidents, const std::function<void()>& each = {}) {
    return test::waitUntil(
               [&] {
                   engine.step();
                   for (const std::string& incident : lathe.takeIncidents()) {
                       incidents.push_back(incident);
                       if (history && engine.runId())
                           history->recordAlarm(*engine.runId(), {engine.partAwaitingMeasurement(),
                                                                  lathe.clock().nowS(), "machine", incident});
                   }
                   if (each) each();
                   return engine.complete() || engine.state() == core::LoopState::Fault;
               },
               seconds) &&
           engine.complete();
}

/// An alarm of the machine names `host` and says `what` failed.
void expectAlarmNaming(const std::vector<core::AlarmRecord>& alarms, const std::string& host, const std::string& what) {
    const bool named = std::any_of(alarms.begin(), alarms.end(), [&](const core::AlarmRecord& a) {
        return a.kind == "machine" && a.message.find(host) != std::string::npos &&
               a.message.find(what) != std::string::npos;
    });
    std::string all;
    for (const auto& a : alarms)
        all += a.kind + ": " + a.message + "\n";
    EXPECT_TRUE(named) << all;
}

std::string joined(const std::vector<std::string>& texts) {
    std::string all;
    for (const std::string& t : texts)
        all += t + "\n";
    return all;
}

core::ShaftRunPlan planFor(const core::ShaftScenario& scenario, std::int64_t parts) {
    core::ShaftRunChoice choice;
    choice.controller = core::ControllerKind::Lqg;
    choice.lastPartNumber = parts;
    return core::planShaftRun(scenario, choice);
}

core::RunDescription describe(const core::ShaftScenario& scenario, const char* machine) {
    core::RunDescription d;
    d.preset = "paper-2012-group1";
    d.controller = "lqg";
    d.delayParts = scenario.delay();
    d.nominalDiameterMm = scenario.nominalDiameterMm;
    d.partLengthMm = scenario.partLengthMm;
    d.pointZMm = scenario.loopConfig(false, std::nullopt).pointZMm;
    d.settingsJson = "{}";
    d.machine = machine;
    return d;
}

TEST(LinuxCncLoop, SixtyPartsThroughLinuxCncMatchTheBuiltInLatheAndEveryWriteIsReadBack) {
    TT_REQUIRE_LINUXCNC(lc);
    constexpr std::int64_t kParts = 60;
    constexpr std::uint64_t kSeed = 5;
    const config::LoopScenario scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"), 2);
    const core::ShaftRunPlan plan = planFor(scenario, kParts);

    // The same run on the built-in simulated lathe.
    core::LatheRunSpec builtIn;
    builtIn.scenario = scenario;
    builtIn.seed = kSeed;
    builtIn.plan = plan;
    builtIn.description = describe(scenario, "simulated");
    const core::LatheRunRecord reference = core::runLatheLoop(builtIn);
    ASSERT_TRUE(reference.outcome.complete) << reference.outcome.stopReason;

    test::bringUpNow(*lc);
    LinuxCncLathe lathe(
        scenario, kSeed,
        devices::linuxcnc::latheOptions(devices::linuxcnc::settingsFromUrl(lc->url(), QStringLiteral("profile")),
                                        lc->programFolder(), true));
    const std::unique_ptr<core::LoopEngine> engine = core::buildShaftRun(scenario, plan, lathe, nullptr);
    PartCollector collector(lathe, plan.loop.pointZMm, scenario.nominalDiameterMm);
    engine->setListener(&collector);
    engine->start(describe(scenario, "linuxcnc"));
    std::vector<std::string> incidents;
    ASSERT_TRUE(runToEnd(*engine, lathe, nullptr, 1200.0, incidents))
        << engine->detail() << "; " << lathe.snapshot().health.message;
    EXPECT_TRUE(collector.faults.empty());

    // Per control point, the systematic error (mean true deviation) after the loop's start-up of 2z + 5 parts.
    const std::int64_t from = 2 * scenario.delay() + 5 + 1;
    ASSERT_EQ(collector.deviations.size(), static_cast<std::size_t>(kParts));
    const Eigen::VectorXd builtInMean = core::profileStatistics(reference.pointDeviationMm, from, kParts).meanMm;
    const Eigen::VectorXd linuxCncMean = core::profileStatistics(collector.deviations, from, kParts).meanMm;
    test::expectSystematicErrorsMatch(builtInMean, linuxCncMean);

    // Every correction written was read back equal. A part whose cut was interrupted (a busy computer can starve
    // the sampling) is written and cut again, each time reported.
    const std::vector<devices::linuxcnc::WriteRecord> writes = lathe.takeWrites();
    const auto counters = lathe.snapshot().counters;
    for (const auto& w : writes) {
        EXPECT_TRUE(w.applied()) << w.message;
        EXPECT_EQ(w.readBackMm, w.writtenMm) << "part " << w.partNumber;
    }
    EXPECT_EQ(counters.writesVerified, writes.size());
    EXPECT_GE(writes.size(), static_cast<std::size_t>(kParts));
    EXPECT_EQ(writes.size() - static_cast<std::size_t>(kParts), incidents.size()) << joined(incidents);
    EXPECT_LE(incidents.size(), 3u) << "parts cut again: " << joined(incidents);
    RecordProperty("parts_cut_again", static_cast<int>(incidents.size()));
}

TEST(LinuxCncLoop, KilledMidRunTheLoopHoldsAlarmsLosesNothingAndResumesWhenLinuxCncIsBack) {
    TT_REQUIRE_LINUXCNC(lc);
    constexpr std::int64_t kParts = 6;
    const config::LoopScenario scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"), 2);
    const core::ShaftRunPlan plan = planFor(scenario, kParts);
    QTemporaryDir folder;
    storage::Database database(storage::DatabaseConfig::sqlite(folder.filePath(QStringLiteral("history.sqlite"))));
    storage::SqlHistoryStore history(database);

    test::bringUpNow(*lc);
    LinuxCncLathe lathe(
        scenario, 5,
        devices::linuxcnc::latheOptions(devices::linuxcnc::settingsFromUrl(lc->url(), QStringLiteral("profile")),
                                        lc->programFolder(), true));
    const std::unique_ptr<core::LoopEngine> engine = core::buildShaftRun(scenario, plan, lathe, &history);
    PartCollector collector(lathe, plan.loop.pointZMm, scenario.nominalDiameterMm);
    engine->setListener(&collector);
    engine->start(describe(scenario, "linuxcnc"));

    bool killed = false;
    bool restarted = false;
    std::int64_t storedBefore = 0;
    const auto killDuringPartThree = [&] {
        if (killed) return;
        if (lathe.snapshot().health.message.find("cutting part 3") == std::string::npos) return;
        storedBefore = static_cast<std::int64_t>(history.parts(*engine->runId()).size());
        killed = test::killLinuxCnc(*lc);
        ASSERT_TRUE(killed) << "LinuxCNC could not be killed";
        // LinuxCNC is gone: the loop holds (machining part 3), the machine reports it.
        ASSERT_TRUE(test::waitUntil([&] { return lathe.snapshot().health.state == core::DeviceState::Error; }, 30.0));
        for (int i = 0; i < 20; ++i)
            engine->step();
        EXPECT_EQ(engine->state(), core::LoopState::Running) << engine->detail();
        EXPECT_EQ(engine->partsFinished(), 2);
        restarted = test::restartLinuxCnc(*lc);
        ASSERT_TRUE(restarted);
        // The operator brings the restarted machine up (on TrueTurn's connection, between its requests).
        ASSERT_TRUE(test::operate(
            lathe.session(), [](devices::linuxcnc::LinuxCncController& c) { test::bringUp(c); }, 120.0));
    };
    std::vector<std::string> incidents;
    ASSERT_TRUE(runToEnd(*engine, lathe, &history, 600.0, incidents, killDuringPartThree))
        << engine->detail() << "; " << lathe.snapshot().health.message;
    ASSERT_TRUE(killed);
    ASSERT_TRUE(restarted);
    EXPECT_TRUE(collector.faults.empty()) << "the loop never faulted";
    EXPECT_EQ(storedBefore, 2) << "parts 1 and 2 were stored before the kill";

    // Nothing stored was lost: every part once, in order.
    const auto parts = history.parts(*engine->runId());
    ASSERT_EQ(parts.size(), static_cast<std::size_t>(kParts));
    for (std::size_t i = 0; i < parts.size(); ++i) {
        EXPECT_EQ(parts[i].partNumber, static_cast<std::int64_t>(i) + 1);
        EXPECT_TRUE(parts[i].measurement.has_value()) << "part " << i + 1 << " measured";
    }
    // An alarm names the host and what failed.
    expectAlarmNaming(history.alarms(*engine->runId()), "LinuxCNC at " + lc->endpoint().text(), "part 3 was being cut");
    EXPECT_EQ(lathe.snapshot().counters.partsAborted, 1u);
    // A part whose path the sampling did not see whole (a busy computer) is cut again (and reported).
    EXPECT_EQ(lathe.snapshot().counters.partsCut, static_cast<std::uint64_t>(kParts) + lathe.partsCutAgain());
}

}  // namespace
