#include "core/run/shaft_run.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/loop/loop_engine.h"
#include "core/loop/shaft_run_stepper.h"
#include "core/run/run_limits.h"
#include "core/run/simulated_lathe.h"

namespace tt::core {

namespace {

/// Collects the true profile of each part as it comes off the machine, and passes events on.
class PartCollector final : public LoopListener {
public:
    PartCollector(SimulatedLathe& lathe, LatheRunRecord& record, const std::vector<double>& profileZ,
                  LoopListener* next, std::int64_t warmupParts)
        : m_shop(lathe.shop()), m_record(record), m_profileZ(profileZ), m_next(next), m_warmupParts(warmupParts) {}

    void onLoopEvent(const LoopEvent& event) override {
        if (event.kind == LoopEvent::Kind::PartFinished && !m_shop.station().machinedParts().empty())
            take(m_shop.station().machinedParts().back());
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
        const double nominal = m_shop.process().nominalDiameterMm();
        const auto& points = m_shop.pointZMm();
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
    LatheShop& m_shop;
    LatheRunRecord& m_record;
    const std::vector<double>& m_profileZ;
    LoopListener* m_next;
    std::int64_t m_warmupParts;
    std::vector<double> m_previous;  // the last corrections sent, per point
    std::int64_t m_switchUntil = 0;  // the last part whose step counts as a controller switch's
};

}  // namespace

LatheRunRecord runLatheLoop(LatheRunSpec spec) {
    if (!spec.plan.loop.lastPartNumber) throw std::invalid_argument("a headless run needs its number of parts");
    checkRunSpeed(spec.speed);
    if (*spec.plan.loop.lastPartNumber > kMaxRunParts + kMaxWarmupParts)
        throw std::invalid_argument("a run of " + std::to_string(*spec.plan.loop.lastPartNumber) +
                                    " parts is too long; the limit is " +
                                    std::to_string(kMaxRunParts + kMaxWarmupParts) + " parts");
    SimulatedLathe lathe(spec.scenario.shopSpec(spec.seed));
    LatheRunRecord record;
    PartCollector collector(lathe, record, spec.profileZMm, spec.listener, spec.warmupParts);

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
