#pragma once

// Test doubles for the loop engine tests: a plain integrating run-to-run controller and an in-memory
// history with the same resume rules as the SQL store.

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "core/control/run_to_run_controller.h"
#include "core/ports/history_store.h"

namespace tt::core::test {

/// u_i(n) = u_i(n-1) - g e_i / k_i for each measurement offered before part n (the textbook
/// integral run-to-run controller). Records what it was offered and when, for the tests.
class IntegratorController final : public RunToRunController {
public:
    IntegratorController(int points, double gain, double plantGain = 2.0)
        : m_u(Eigen::VectorXd::Zero(points)), m_gain(gain), m_plantGain(plantGain) {}

    std::string name() const override { return "test integrator"; }
    int pointCount() const override { return static_cast<int>(m_u.size()); }

    MeasurementVerdict addMeasurement(const PartMeasurement& m) override {
        offered.push_back({m.partNumber, m_lastCorrected});
        offeredDeviations.push_back(m.deviationMm);
        MeasurementVerdict v;
        for (Eigen::Index i = 0; i < m.deviationMm.size(); ++i) {
            const double e = m.deviationMm(i);
            const bool ok = std::isfinite(e) && std::abs(e) < gateMm;
            v.accepted.push_back(ok);
            Notice why =
                ok ? Notice() : Notice(std::isfinite(e) ? NoticeKind::ControllerRejected : NoticeKind::NotMeasured);
            if (why.kind == NoticeKind::ControllerRejected) why.cause = "outside the gate";
            v.reasons.push_back(why);
            if (ok) m_u(i) -= m_gain * e / m_plantGain;
        }
        return v;
    }

    Eigen::VectorXd nextCorrection(std::int64_t partNumber) override {
        if (m_lastCorrected != 0 && partNumber != m_lastCorrected + 1)
            throw std::invalid_argument("parts must come one after the other");
        m_lastCorrected = partNumber;
        return m_u;
    }

    ControllerState saveState() const override {
        ControllerState s{"test", {static_cast<double>(m_lastCorrected)}};
        for (Eigen::Index i = 0; i < m_u.size(); ++i)
            s.values.push_back(m_u(i));
        return s;
    }
    void restoreState(const ControllerState& s) override {
        if (s.kind != "test" || static_cast<Eigen::Index>(s.values.size()) != m_u.size() + 1)
            throw std::invalid_argument("not a state of this controller");
        m_lastCorrected = static_cast<std::int64_t>(s.values[0]);
        for (Eigen::Index i = 0; i < m_u.size(); ++i)
            m_u(i) = s.values[static_cast<std::size_t>(i + 1)];
    }

    /// (measured part, last part whose correction was computed when it was offered)
    std::vector<std::pair<std::int64_t, std::int64_t>> offered;
    std::vector<Eigen::VectorXd> offeredDeviations;
    double gateMm = 1.0;

private:
    Eigen::VectorXd m_u;
    double m_gain;
    double m_plantGain;
    std::int64_t m_lastCorrected = 0;
};

/// A controller that returns fixed corrections (for the limiter tests).
class FixedController final : public RunToRunController {
public:
    explicit FixedController(Eigen::VectorXd u) : m_u(std::move(u)) {}
    std::string name() const override { return "fixed"; }
    int pointCount() const override { return static_cast<int>(m_u.size()); }
    MeasurementVerdict addMeasurement(const PartMeasurement& m) override {
        return {std::vector<bool>(static_cast<std::size_t>(m.deviationMm.size()), true),
                std::vector<Notice>(static_cast<std::size_t>(m.deviationMm.size()))};
    }
    Eigen::VectorXd nextCorrection(std::int64_t) override { return m_u; }
    ControllerState saveState() const override { return {"fixed", {}}; }
    void restoreState(const ControllerState&) override {}

private:
    Eigen::VectorXd m_u;
};

/// The history in memory, with the resume rules of the SQL store.
class MemoryHistory final : public HistoryStore {
public:
    std::int64_t beginRun(const RunDescription& run) override {
        RunSummary s;
        s.runId = static_cast<std::int64_t>(m_runs.size()) + 1;
        s.description = run;
        s.status = "running";
        m_runs.push_back(s);
        return s.runId;
    }
    void recordPart(std::int64_t runId, const PartCompletionRecord& part) override {
        if (failWrites) throw std::runtime_error("disk full");
        auto& parts = m_parts[runId];
        for (const StoredPart& p : parts)
            if (p.partNumber == part.partNumber) throw std::runtime_error("part stored twice");
        parts.push_back({part.partNumber, part.startedS, part.finishedS, part.corrections, std::nullopt});
        if (part.usedMeasurement) store(runId, *part.usedMeasurement);
        m_state[runId] = part.controllerState;
    }
    void recordMeasurement(std::int64_t runId, const PartMeasurementRecord& m) override {
        if (failWrites) throw std::runtime_error("disk full");
        store(runId, m);
    }
    void recordAlarm(std::int64_t runId, const AlarmRecord& alarm) override { m_alarms[runId].push_back(alarm); }
    void finishRun(std::int64_t runId, const std::string& status) override {
        m_runs.at(static_cast<std::size_t>(runId - 1)).status = status;
    }
    std::vector<RunSummary> runs() override { return {m_runs.rbegin(), m_runs.rend()}; }
    std::vector<StoredPart> parts(std::int64_t runId) override { return m_parts[runId]; }
    std::vector<AlarmRecord> alarms(std::int64_t runId) override { return m_alarms[runId]; }
    void recordAdaptation(std::int64_t runId, const AdaptationRecord& a) override { m_adaptations[runId].push_back(a); }
    std::vector<AdaptationRecord> adaptations(std::int64_t runId) override { return m_adaptations[runId]; }
    std::optional<ResumePoint> resumePoint(std::optional<std::int64_t> runId) override {
        if (m_runs.empty()) return std::nullopt;
        const std::int64_t id = runId.value_or(m_runs.back().runId);
        const auto& parts = m_parts[id];
        if (parts.empty()) return std::nullopt;
        ResumePoint r;
        r.run = m_runs.at(static_cast<std::size_t>(id - 1));
        r.lastPartNumber = parts.back().partNumber;
        r.controllerState = m_state[id];
        for (const StoredPart& p : parts)
            if (p.partNumber > r.lastPartNumber - r.run.description.delayParts) r.pendingParts.push_back(p);
        return r;
    }

    Notice refusesNextPart() override { return refusal; }

    bool failWrites = false;
    Notice refusal;  ///< what refusesNextPart answers (a journal at its bound: HistoryFull)

private:
    void store(std::int64_t runId, const PartMeasurementRecord& m) {
        for (StoredPart& p : m_parts[runId])
            if (p.partNumber == m.partNumber) {
                p.measurement = m;
                return;
            }
        throw std::runtime_error("a measurement of a part that is not stored");
    }

    std::vector<RunSummary> m_runs;
    std::map<std::int64_t, std::vector<StoredPart>> m_parts;
    std::map<std::int64_t, ControllerState> m_state;
    std::map<std::int64_t, std::vector<AlarmRecord>> m_alarms;
    std::map<std::int64_t, std::vector<AdaptationRecord>> m_adaptations;
};

}  // namespace tt::core::test
