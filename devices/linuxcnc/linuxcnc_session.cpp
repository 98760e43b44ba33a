#include "devices/linuxcnc/linuxcnc_session.h"

#include <chrono>

namespace tt::devices::linuxcnc {

namespace {

constexpr int kRetryMs = 200;
constexpr int kMaxBackoffMs = 5000;
std::string statusWords(const MachineStatus& s) {
    std::string words = s.estop ? "E-stop on" : (s.machineOn ? "machine on" : "machine off");
    words += s.allHomed() ? ", homed" : ", not homed";
    words += ", " + std::string(modeName(s.mode)) + " mode, program " + std::string(statusName(s.program));
    return words;
}

}  // namespace

LinuxCncSession::LinuxCncSession(SessionSettings settings)
    : m_settings(std::move(settings)), m_controller(m_settings.controller), m_writer(m_settings.corrections) {
    m_snapshot.health = {core::DeviceState::Disconnected,
                         "LinuxCNC at " + m_settings.controller.endpoint.text() + ": not connected"};
}

LinuxCncSession::~LinuxCncSession() {
    stop();
}

double LinuxCncSession::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void LinuxCncSession::start() {
    std::lock_guard lock(m_mutex);
    if (m_running) return;
    m_running = true;
    m_stop = false;
    m_thread = std::thread([this] { loop(); });
}

void LinuxCncSession::stop() {
    {
        std::lock_guard lock(m_mutex);
        if (!m_running) return;
        m_stop = true;
    }
    m_wake.notify_all();
    m_thread.join();
    std::lock_guard lock(m_mutex);
    m_running = false;
    m_jobs.clear();
    for (Task& t : m_tasks)
        t.done.set_exception(std::make_exception_ptr(std::runtime_error("the LinuxCNC session was stopped")));
    m_tasks.clear();
    m_controller.disconnect();
    m_snapshot.health = {core::DeviceState::Disconnected,
                         "LinuxCNC at " + m_settings.controller.endpoint.text() + ": not connected"};
    m_snapshot.busy = false;
}

void LinuxCncSession::reconnect() {
    {
        std::lock_guard lock(m_mutex);
        m_reconnect = true;
        m_backoffMs = kRetryMs;
    }
    m_wake.notify_all();
}

void LinuxCncSession::submit(PartJob job) {
    {
        std::lock_guard lock(m_mutex);
        m_jobs.push_back(std::move(job));
        m_snapshot.busy = true;
    }
    m_wake.notify_all();
}

std::future<void> LinuxCncSession::run(std::function<void(LinuxCncController&)> work) {
    Task task{std::move(work), {}};
    std::future<void> done = task.done.get_future();
    {
        std::lock_guard lock(m_mutex);
        m_tasks.push_back(std::move(task));
    }
    m_wake.notify_all();
    return done;
}

std::vector<PartResult> LinuxCncSession::takeResults() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_results, {});
}

std::vector<WriteRecord> LinuxCncSession::takeWrites() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_writes, {});
}

std::vector<CycleEvent> LinuxCncSession::takeEvents() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_events, {});
}

std::vector<std::string> LinuxCncSession::takeIncidents() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_incidents, {});
}

SessionSnapshot LinuxCncSession::snapshot() const {
    std::lock_guard lock(m_mutex);
    return m_snapshot;
}

bool LinuxCncSession::waitFor(int ms, bool wakeOnJobs) {
    std::unique_lock lock(m_mutex);
    m_wake.wait_for(lock, std::chrono::milliseconds(ms), [this, wakeOnJobs] {
        return m_stop.load() || m_reconnect || !m_tasks.empty() || (wakeOnJobs && !m_jobs.empty());
    });
    return !m_stop;
}

void LinuxCncSession::setHealth(core::DeviceState state, const std::string& message) {
    std::lock_guard lock(m_mutex);
    m_snapshot.health = {state, message};
}

void LinuxCncSession::report(const std::string& incident, core::DeviceState state) {
    std::lock_guard lock(m_mutex);
    m_incidents.push_back(incident);
    m_snapshot.lastProblem = incident;
    m_snapshot.health = {state, incident};
}

void LinuxCncSession::recordWrite(const WriteRecord& record) {
    std::lock_guard lock(m_mutex);
    m_writes.push_back(record);
    m_snapshot.lastWrite = record;
    SessionCounters& c = m_snapshot.counters;
    switch (record.outcome) {
        case WriteOutcome::Verified:
            ++c.writesVerified;
            break;
        case WriteOutcome::Differs:
            ++c.readBacksDiffered;
            break;
        case WriteOutcome::NotReady:
            ++c.writesHeld;
            break;
        case WriteOutcome::OutOfLimits:
        case WriteOutcome::Refused:
            ++c.writesRefused;
            break;
    }
}

void LinuxCncSession::connectionFailed(const LinuxCncError& e) {
    m_controller.disconnect();
    m_reference.reset();
    std::string incident = e.what();
    {
        std::lock_guard lock(m_mutex);
        ++m_snapshot.counters.connectionResets;
        if (m_cutting != 0) {
            ++m_snapshot.counters.partsAborted;
            m_events.push_back({CycleEvent::Kind::Aborted, m_cutting, now(), incident});
            incident += "; part " + std::to_string(m_cutting) +
                        " was being cut: it is not counted and is cut again when LinuxCNC is back";
        }
        m_cutting = 0;
    }
    report(incident, core::DeviceState::Error);
}

void LinuxCncSession::partFailed(const std::string& problem) {
    std::string incident = problem;
    {
        std::lock_guard lock(m_mutex);
        if (m_cutting != 0) {
            ++m_snapshot.counters.partsAborted;
            m_events.push_back({CycleEvent::Kind::Aborted, m_cutting, now(), problem});
            incident += "; part " + std::to_string(m_cutting) + " is not counted and is cut again";
        }
        m_cutting = 0;
    }
    report(incident, core::DeviceState::Error);
}

bool LinuxCncSession::ensureConnected() {
    {
        std::lock_guard lock(m_mutex);
        if (m_reconnect) {
            m_reconnect = false;
            m_controller.disconnect();
            m_reference.reset();
        }
    }
    if (m_controller.connected()) return true;
    try {
        setHealth(core::DeviceState::Connecting, "connecting to LinuxCNC at " + m_settings.controller.endpoint.text());
        m_controller.connect();
        std::lock_guard lock(m_mutex);
        m_backoffMs = kRetryMs;
        m_snapshot.identity = m_controller.identity();
        m_snapshot.health = {core::DeviceState::Ready,
                             "connected to LinuxCNC at " + m_settings.controller.endpoint.text()};
        return true;
    } catch (const LinuxCncError& e) {
        int wait = 0;
        {
            std::lock_guard lock(m_mutex);
            m_snapshot.health = {core::DeviceState::Error, e.what()};
            m_snapshot.lastProblem = e.what();
            wait = m_backoffMs;
            m_backoffMs = std::min(kMaxBackoffMs, wait * 2);
        }
        waitFor(wait, false);
        return false;
    }
}

void LinuxCncSession::pollStatus() {
    const MachineStatus s = m_controller.status();
    const std::array<double, 2> position = m_controller.positionMm();
    std::lock_guard lock(m_mutex);
    const std::optional<MachineStatus> before = m_snapshot.status;
    m_snapshot.status = s;
    m_snapshot.positionMm = position;
    const std::string reason = notReadyReason(s);
    const std::string where = "LinuxCNC " + m_controller.identity().server + " " + m_controller.identity().protocol +
                              " at " + m_settings.controller.endpoint.text() + ": ";
    const bool notReady = s.estop || !s.machineOn || !s.allHomed();
    m_snapshot.health = {notReady ? core::DeviceState::Error : core::DeviceState::Ready, where + statusWords(s)};
    // A program the operator runs (the shop's own cycle): started and finished or aborted.
    if (before && before->program == ProgramStatus::Idle && s.program != ProgramStatus::Idle)
        m_events.push_back({CycleEvent::Kind::Started, 0, now(), "a program started"});
    if (before && before->program != ProgramStatus::Idle && s.program == ProgramStatus::Idle) {
        const bool aborted = s.estop || !s.machineOn;
        m_events.push_back({aborted ? CycleEvent::Kind::Aborted : CycleEvent::Kind::Finished, 0, now(),
                            aborted ? "the program stopped: " + reason : "the program ended"});
    }
}

void LinuxCncSession::runTask(Task& task) {
    try {
        task.work(m_controller);
        task.done.set_value();
    } catch (const LinuxCncError& e) {
        task.done.set_exception(std::current_exception());
        if (e.connectionReset()) connectionFailed(e);
    } catch (...) {
        task.done.set_exception(std::current_exception());
    }
}

void LinuxCncSession::loop() {
    while (!m_stop) {
        if (!ensureConnected()) continue;
        std::optional<Task> task;
        std::optional<PartJob> job;
        {
            std::lock_guard lock(m_mutex);
            if (!m_tasks.empty()) {
                task = std::move(m_tasks.front());
                m_tasks.pop_front();
            } else if (!m_jobs.empty()) {
                job = m_jobs.front();
            }
        }
        if (task) {
            runTask(*task);
            continue;
        }
        bool held = false;
        try {
            if (job) {
                held = !doPart(*job);
                std::lock_guard lock(m_mutex);
                if (!held && !m_jobs.empty()) m_jobs.pop_front();
                if (!held) m_heldReason.clear();
                m_snapshot.busy = !m_jobs.empty();
            } else {
                pollStatus();
            }
        } catch (const LinuxCncError& e) {
            held = true;
            if (e.connectionReset()) {
                connectionFailed(e);
                waitFor(m_backoffMs, false);
                continue;
            }
            partFailed(e.what());
        } catch (const std::exception& e) {
            held = true;
            partFailed("LinuxCNC at " + m_settings.controller.endpoint.text() + ": " + e.what());
        }
        if (!job || held) waitFor(job ? kRetryMs : m_settings.statusPollMs, !job);
    }
}

}  // namespace tt::devices::linuxcnc
