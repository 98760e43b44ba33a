#include "core/run/shaft_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/loop/loop_engine.h"
#include "core/loop/loop_runner.h"
#include "core/loop/shaft_run_stepper.h"
#include "core/run/run_limits.h"
#include "core/run/simulated_lathe.h"

namespace tt::core {

namespace {

/// Collects the true profile of each part as it comes off the machine, and passes events on.
class PartCollector final : public LoopListener {
public:
    /// The built-in simulated lathe's parts are taken from its shop as they are; another machine's from its
    /// trueProfile (diameters at the loop's control points).
    PartCollector(ShaftMachine& machine, LatheRunRecord& record, const LatheRunSpec& spec)
        : m_machine(machine),
          m_simulated(dynamic_cast<SimulatedLathe*>(&machine)),
          m_record(record),
          m_profileZ(spec.profileZMm),
          m_next(spec.listener),
          m_warmupParts(spec.warmupParts),
          m_nominalMm(m_simulated ? m_simulated->shop().process().nominalDiameterMm()
                                  : spec.scenario.nominalDiameterMm),
          m_pointZMm(m_simulated ? m_simulated->shop().pointZMm() : spec.plan.loop.pointZMm) {}

    void onLoopEvent(const LoopEvent& event) override {
        if (event.kind == LoopEvent::Kind::PartFinished)
            if (const std::optional<TurnedPart> part = finishedPart(event.partNumber)) take(*part);
        if (event.kind == LoopEvent::Kind::PartMeasured && event.measurement)
            for (const PointMeasurementRecord& p : event.measurement->points)
                if (!p.accepted && p.measuredMm) ++m_record.rejectedValues;
        if (event.kind == LoopEvent::Kind::PartMeasured && event.measurement)
            if (const auto verdict = event.measurement->verdict()) {
                m_record.verdicts.add(*verdict);
                if (event.partNumber <= m_warmupParts) m_record.warmupVerdicts.add(*verdict);
            }
        if (event.kind == LoopEvent::Kind::Alarm && event.alarmKind == "out-of-tolerance") ++m_record.toleranceAlarms;
        if (event.kind == LoopEvent::Kind::Alarm && event.alarmKind == kModelMismatchAlarm)
            m_record.modelAlarms.push_back({event.partNumber, event.alarmKind, event.notice});
        if (event.kind == LoopEvent::Kind::Alarm && event.alarmKind == kAdaptationAlarm) {
            m_record.adaptationNotices.push_back({event.partNumber, event.alarmKind, event.notice});
            if (event.adaptation) m_record.adaptations.push_back(*event.adaptation);
            if (event.adaptation && event.adaptation->applied) {
                ++m_record.switches;
                m_switchUntil = event.partNumber + kSwitchWatchParts;
            }
        }
        if (event.kind == LoopEvent::Kind::PartStarted) watchCorrections(event.partNumber, event.corrections);
        if (m_next) m_next->onLoopEvent(event);
    }

    void watchCorrections(std::int64_t part, const std::vector<PointCorrectionRecord>& corrections) {
        m_previous.resize(corrections.size(), 0.0);
        for (std::size_t i = 0; i < corrections.size(); ++i) {
            const double u = corrections[i].appliedMm;
            m_record.maxCorrectionMm = std::max(m_record.maxCorrectionMm, std::abs(u));
            m_record.maxCorrectionStepMm = std::max(m_record.maxCorrectionStepMm, std::abs(u - m_previous[i]));
            if (part <= m_switchUntil)
                m_record.maxSwitchStepMm = std::max(m_record.maxSwitchStepMm, std::abs(u - m_previous[i]));
            m_previous[i] = u;
        }
    }

    void take(const TurnedPart& part) {
        if (part.partNumber < 1) return;
        const auto index = static_cast<std::size_t>(part.partNumber - 1);
        if (m_record.pointDeviationMm.size() <= index) {
            m_record.pointDeviationMm.resize(index + 1);
            m_record.profileDeviationMm.resize(index + 1);
            m_record.seen.resize(index + 1, false);
        }
        const double nominal = m_nominalMm;
        const auto& points = m_pointZMm;
        Eigen::VectorXd atPoints(static_cast<Eigen::Index>(points.size()));
        for (std::size_t i = 0; i < points.size(); ++i)
            atPoints(static_cast<Eigen::Index>(i)) = part.diameterAtMm(points[i]) - nominal;
        Eigen::VectorXd profile(static_cast<Eigen::Index>(m_profileZ.size()));
        for (std::size_t i = 0; i < m_profileZ.size(); ++i)
            profile(static_cast<Eigen::Index>(i)) = part.diameterAtMm(m_profileZ[i]) - nominal;
        m_record.pointDeviationMm[index] = std::move(atPoints);
        m_record.profileDeviationMm[index] = std::move(profile);
        m_record.seen[index] = true;
    }

private:
    /// The part just finished: the simulated shop's last, or the machine's true profile of it.
    std::optional<TurnedPart> finishedPart(std::int64_t partNumber) const {
        if (m_simulated) {
            const auto& parts = m_simulated->shop().station().machinedParts();
            return parts.empty() ? std::nullopt : std::optional<TurnedPart>(parts.back());
        }
        const std::optional<TrueProfile> profile = m_machine.trueProfile(partNumber);
        if (!profile) return std::nullopt;
        TurnedPart part{partNumber, profile->zMm, {}};
        for (const double e : profile->errorMm)
            part.diameterMm.push_back(m_nominalMm + e);
        return part;
    }

    ShaftMachine& m_machine;
    SimulatedLathe* m_simulated;  // null: another machine
    LatheRunRecord& m_record;
    const std::vector<double>& m_profileZ;
    LoopListener* m_next;
    std::int64_t m_warmupParts;
    double m_nominalMm;
    std::vector<double> m_pointZMm;
    std::vector<double> m_previous;  // the last corrections sent, per point
    std::int64_t m_switchUntil = 0;  // the last part whose step counts as a controller switch's
};

/// Steps the engine on a machine whose time is the wall clock, polled every 10 ms, until the run completes,
/// faults or goes idle; `stop` ends it after the part on the machine (as runSimulation does).
SimulationOutcome pollToEnd(LoopEngine& engine, ShaftMachine& machine, const LatheRunSpec& spec) {
    SimulationOutcome outcome;
    std::optional<std::int64_t> stopAfter;  // parts finished when the stop was asked for
    for (;;) {
        engine.step();
        if (spec.machine.poll) spec.machine.poll(machine, engine);
        if (runEnds(engine, spec.stop, stopAfter, outcome)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    outcome.simulatedS = machine.clock().nowS();
    return outcome;
}

void checkSpec(const LatheRunSpec& spec) {
    if (!spec.plan.loop.lastPartNumber) throw std::invalid_argument("a headless run needs its number of parts");
    checkRunSpeed(spec.speed);
    if (*spec.plan.loop.lastPartNumber > kMaxRunParts + kMaxWarmupParts)
        throw std::invalid_argument("a run of " + std::to_string(*spec.plan.loop.lastPartNumber) +
                                    " parts is too long; the limit is " +
                                    std::to_string(kMaxRunParts + kMaxWarmupParts) + " parts");
    if (spec.machine.make && spec.resume)
        throw std::invalid_argument(
            "a run on a machine other than the built-in simulated lathe is not resumed headless");
}

/// The run on the machine LatheRunSpec::machine makes: in simulated time as on the built-in lathe, or polled.
LatheRunRecord runOnMadeMachine(const LatheRunSpec& spec) {
    const std::unique_ptr<ShaftMachine> machine = spec.machine.make(spec.scenario, spec.seed);
    if (!machine) throw std::invalid_argument("the machine of the run could not be made");
    LatheRunRecord record;
    PartCollector collector(*machine, record, spec);
    const std::unique_ptr<LoopEngine> engine = buildShaftRun(spec.scenario, spec.plan, *machine, spec.history);
    engine->setListener(&collector);
    engine->start(spec.description);
    ShaftRunStepper stepper(*engine, *machine);
    record.outcome = stepper.simulatedTime() ? stepper.runToEnd(100'000'000, spec.speed, spec.stop)
                                             : pollToEnd(*engine, *machine, spec);
    if (spec.machine.poll) spec.machine.poll(*machine, *engine);
    record.runId = engine->runId();
    return record;
}

}  // namespace

LatheRunRecord runLatheLoop(LatheRunSpec spec) {
    checkSpec(spec);
    if (spec.machine.make) return runOnMadeMachine(spec);
    SimulatedLathe lathe(spec.scenario.shopSpec(spec.seed));
    LatheRunRecord record;
    PartCollector collector(lathe, record, spec);

    const std::unique_ptr<LoopEngine> engine = buildShaftRun(spec.scenario, spec.plan, lathe, spec.history);
    engine->setListener(&collector);
    if (spec.resume) {
        if (!spec.history) throw std::invalid_argument("a resume needs the history it continues");
        // Everything stored so far, re-created exactly for the record: the simulator depends only on the
        // part number and the corrections the part received.
        for (const StoredPart& stored : spec.history->parts(spec.resume->run.runId))
            collector.take(lathe.replay(partCorrectionFor(spec.plan.loop, stored), stored.finishedS));
        resumeShaftRun(*engine, lathe, spec.plan.loop, *spec.resume);
    } else {
        engine->start(spec.description);
    }
    record.outcome = ShaftRunStepper(*engine, lathe).runToEnd(100'000'000, spec.speed, spec.stop);
    record.runId = engine->runId();
    return record;
}

Eigen::VectorXd deviationVariance(const std::vector<Eigen::VectorXd>& perPart, std::int64_t from, std::int64_t to) {
    const ProfileStatistics s = profileStatistics(perPart, from, to);
    return s.stdMm.array().square().matrix();
}

ProfileStatistics profileStatistics(const std::vector<Eigen::VectorXd>& perPart, std::int64_t from, std::int64_t to) {
    if (from < 1 || to > static_cast<std::int64_t>(perPart.size()) || to - from < 1)
        throw std::invalid_argument("statistics need at least two parts within the run (parts " + std::to_string(from) +
                                    " .. " + std::to_string(to) + " of " + std::to_string(perPart.size()) + ")");
    const Eigen::Index n = perPart[static_cast<std::size_t>(from - 1)].size();
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(n);
    for (std::int64_t k = from; k <= to; ++k)
        mean += perPart[static_cast<std::size_t>(k - 1)];
    const double count = static_cast<double>(to - from + 1);
    mean /= count;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(n);
    for (std::int64_t k = from; k <= to; ++k)
        sum += (perPart[static_cast<std::size_t>(k - 1)] - mean).array().square().matrix();
    return {mean, (sum / (count - 1.0)).cwiseSqrt()};
}

}  // namespace tt::core
