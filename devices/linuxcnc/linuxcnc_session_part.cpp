// The part of a LinuxCNC session: write and verify the corrections, measure where program coordinates are in the
// machine once per connection, run the program and sample the tool's path until the program ends.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "devices/linuxcnc/linuxcnc_session.h"

namespace tt::devices::linuxcnc {

namespace {

constexpr int kMotionTimeoutMs = 60000;
constexpr double kEndToleranceMm = 0.001;
constexpr int kStartGraceMs = 3000;

std::string mm3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", v);
    return text;
}

}  // namespace

bool LinuxCncSession::doPart(PartJob& job) {
    const std::int64_t part = job.correction.partNumber;
    const WriteRecord record =
        m_writer.write(m_controller, part, valuesToWrite(job.correction, m_writer.settings().mode));
    const bool lone = job.programPath.empty();
    if (!record.applied()) {
        // A held part reports each new reason once (an E-stop is not repeated every 0.2 s).
        const bool repeated = record.message == m_heldReason;
        m_heldReason = record.message;
        if (!repeated || lone) {
            recordWrite(record);
            report(lone ? record.message : record.message + "; part " + std::to_string(part) + " waits",
                   core::DeviceState::Error);
        }
        return lone;
    }
    recordWrite(record);
    if (lone) {
        setHealth(core::DeviceState::Ready, record.message);
        return true;
    }
    if (!m_reference) measureReference(job);
    return cutPart(job, record);
}

void LinuxCncSession::measureReference(const PartJob& job) {
    m_controller.setMode(TaskMode::Mdi);
    for (const std::string& line : job.referenceLines)
        m_controller.mdi(line, kMotionTimeoutMs);
    const std::array<double, 2> machine = m_controller.positionMm();
    m_reference = std::array<double, 2>{machine[0] - job.referenceProgramMm[0], machine[1] - job.referenceProgramMm[1]};
}

bool LinuxCncSession::cutPart(PartJob& job, const WriteRecord& write) {
    const std::int64_t part = job.correction.partNumber;
    m_controller.setMode(TaskMode::Auto);
    m_controller.openProgram(job.programPath);
    m_controller.drainMessages();
    {
        std::lock_guard lock(m_mutex);
        m_cutting = part;
        m_snapshot.health = {core::DeviceState::Ready, "LinuxCNC at " + m_settings.controller.endpoint.text() +
                                                           ": cutting part " + std::to_string(part)};
    }
    if (job.feedOverridePct) m_controller.setFeedOverride(*job.feedOverridePct);
    if (job.pressCycleStart) m_controller.startProgram();
    std::vector<std::array<double, 2>> samples;
    bool sawRunning = false;
    sampleUntilIdle(samples, sawRunning, !job.pressCycleStart);
    if (m_stop) return false;
    const MachineStatus after = m_controller.status();
    const std::string error = m_controller.drainMessages();
    const std::array<double, 2> end = m_controller.positionMm();
    std::string why;
    if (!error.empty()) why = "LinuxCNC reports: " + error;
    if (why.empty() && (after.estop || !after.machineOn)) why = notReadyReason(after);
    if (why.empty() && !sawRunning) why = "the program did not start";
    if (why.empty() && job.endProgramMm) {
        const double dx = end[0] - (*m_reference)[0] - (*job.endProgramMm)[0];
        const double dz = end[1] - (*m_reference)[1] - (*job.endProgramMm)[1];
        if (std::fabs(dz) > kEndToleranceMm || std::fabs(dx) > job.endXToleranceMm)
            why = "the tool stopped at X " + mm3(end[0] - (*m_reference)[0]) + " Z " + mm3(end[1] - (*m_reference)[1]) +
                  " mm, not at the program's end";
    }
    std::lock_guard lock(m_mutex);
    m_cutting = 0;
    if (!why.empty()) {
        ++m_snapshot.counters.partsAborted;
        const std::string incident = "LinuxCNC at " + m_settings.controller.endpoint.text() + ": part " +
                                     std::to_string(part) + " was not cut to its end (" + why +
                                     "); it is not counted and is cut again";
        m_events.push_back({CycleEvent::Kind::Aborted, part, now(), incident});
        m_incidents.push_back(incident);
        m_snapshot.lastProblem = incident;
        m_snapshot.health = {core::DeviceState::Error, incident};
        return false;
    }
    ++m_snapshot.counters.partsCut;
    m_events.push_back({CycleEvent::Kind::Finished, part, now(), "part " + std::to_string(part) + " cut"});
    m_results.push_back({part, now(), std::move(samples), write});
    m_snapshot.health = {core::DeviceState::Ready, "LinuxCNC at " + m_settings.controller.endpoint.text() + ": part " +
                                                       std::to_string(part) + " cut"};
    return true;
}

void LinuxCncSession::sampleUntilIdle(std::vector<std::array<double, 2>>& samples, bool& sawRunning,
                                      bool waitForStart) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point deadline = Clock::now() + std::chrono::seconds(m_settings.partTimeoutS);
    // After cycle start LinuxCNC may show the program idle for a few task cycles (longer on a busy computer); a
    // program that stays idle this long did not start (a guard refused it, or it failed at once).
    const Clock::time_point startBy = waitForStart ? deadline : Clock::now() + std::chrono::milliseconds(kStartGraceMs);
    const std::array<double, 2> ref = *m_reference;
    for (std::uint64_t i = 0; !m_stop; ++i) {
        if (i % 16 == 0) {
            const ProgramStatus status = m_controller.program();
            if (status != ProgramStatus::Idle) {
                if (!sawRunning) {
                    std::lock_guard lock(m_mutex);
                    m_events.push_back({CycleEvent::Kind::Started, m_cutting, now(), "program started"});
                }
                sawRunning = true;
            } else if (sawRunning || Clock::now() > startBy) {
                return;
            }
            if (Clock::now() > deadline) {
                m_controller.abort();
                return;
            }
        }
        const std::array<double, 2> p = m_controller.positionMm();
        const std::array<double, 2> program{p[0] - ref[0], p[1] - ref[1]};
        // Changes only, and a position read twice in a row once more: the tool stood still there (the dwell that
        // ends the cut, where the retract starts).
        const std::size_t n = samples.size();
        if (n == 0 || samples[n - 1] != program || (n >= 2 && samples[n - 2] != program)) samples.push_back(program);
        std::this_thread::sleep_for(std::chrono::microseconds(m_settings.samplePeriodUs));
    }
}

}  // namespace tt::devices::linuxcnc
