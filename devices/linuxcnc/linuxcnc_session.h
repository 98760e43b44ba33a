#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/ports/correction_output.h"
#include "core/ports/device_health.h"
#include "devices/linuxcnc/linuxcnc_controller.h"
#include "devices/linuxcnc/linuxcnc_corrections.h"

namespace tt::devices::linuxcnc {

/// Everything a session needs.
struct SessionSettings {
    ControllerOptions controller;
    CorrectionSettings corrections;
    int statusPollMs = 250;    ///< how often the machine's state is read while nothing else happens
    int partTimeoutS = 600;    ///< longest a part program may run
    int samplePeriodUs = 700;  ///< pause between two position samples while a program runs
};

/// One part LinuxCNC cuts for TrueTurn: the corrections are written and verified first, then the program runs
/// while TrueTurn samples where the tool is.
struct PartJob {
    core::PartCorrection correction;  ///< written before the part (valuesToWrite of the mode)
    std::string programPath;          ///< the program on the LinuxCNC computer; empty: only write
    bool pressCycleStart = true;      ///< false: the operator presses cycle start
    /// The cut's feed, % of the programmed one (LinuxCNC's feed override, set before the cycle start); unset: as
    /// LinuxCNC has it.
    std::optional<int> feedOverridePct;
    /// MDI lines run once per connection before the first part (tool, modes, a move to a known place) and
    /// where that place is in program coordinates (X radius, Z), mm: machine minus program is the offset
    /// between the two, measured so the samples can be given in program coordinates.
    std::vector<std::string> referenceLines;
    std::array<double, 2> referenceProgramMm{0.0, 0.0};
    /// Where the tool rests, in program coordinates, when the program has run to its end: Z within 0.001 mm, X
    /// within endXToleranceMm (a wear applied by the program moves X by the wear).
    std::optional<std::array<double, 2>> endProgramMm;
    double endXToleranceMm = 0.001;
};

/// A part LinuxCNC cut: the tool's path as sampled while the program ran.
struct PartResult {
    std::int64_t partNumber = 0;
    double finishedAtS = 0.0;  ///< steady-clock time of the end, s
    /// Program coordinates: X (radius), Z, mm, in time order; changes only, but a position read twice in a row
    /// (the tool stood still) is there twice.
    std::vector<std::array<double, 2>> samplesMm;
    WriteRecord write;  ///< the verified write the part was cut with
};

/// A program event of the part cycle.
struct CycleEvent {
    enum class Kind { Started, Finished, Aborted };
    Kind kind = Kind::Started;
    std::int64_t partNumber = 0;  ///< 0 when LinuxCNC ran a program TrueTurn did not start
    double timeS = 0.0;           ///< steady-clock time, s
    std::string message;
};

/// Counters for the Devices page and the tests.
struct SessionCounters {
    std::uint64_t writesVerified = 0;
    std::uint64_t writesRefused = 0;  ///< refused by LinuxCNC or by the limits
    std::uint64_t readBacksDiffered = 0;
    std::uint64_t writesHeld = 0;  ///< not written: E-stop, machine off, not homed, running
    std::uint64_t connectionResets = 0;
    std::uint64_t partsCut = 0;
    std::uint64_t partsAborted = 0;
};

/// What the session knows, copied out under its lock.
struct SessionSnapshot {
    core::DeviceHealth health;
    std::optional<Identity> identity;
    std::optional<MachineStatus> status;
    std::optional<std::array<double, 2>> positionMm;  ///< machine coordinates, X and Z
    SessionCounters counters;
    std::optional<WriteRecord> lastWrite;
    std::string lastProblem;  ///< the last failure, kept after recovery
    bool busy = false;        ///< a write or a part is in progress or waiting
};

/// LinuxCNC behind one connection in a thread of its own: it connects (again, with a growing pause, after
/// the connection is lost), reads the machine's state, writes corrections between parts and runs parts. The
/// calls never block the caller (they queue work and read the last state); one request at a time goes to
/// LinuxCNC. A part is held, never cut, while LinuxCNC is unreachable, in E-stop, off, not homed or busy, and
/// while its write is refused or differs; it is tried again (the write first) until it is cut. A lone write
/// (no program) is tried once. Thread-safe.
class LinuxCncSession {
public:
    explicit LinuxCncSession(SessionSettings settings);
    ~LinuxCncSession();
    LinuxCncSession(const LinuxCncSession&) = delete;
    LinuxCncSession& operator=(const LinuxCncSession&) = delete;

    /// Starts the thread (connects). Idempotent.
    void start();
    /// Stops the thread and closes the connection; queued work is dropped.
    void stop();
    /// Drops the connection and connects again at once (Test connection).
    void reconnect();

    /// Queues a part (or, without a program, a lone write).
    void submit(PartJob job);
    /// The parts cut since the last call, oldest first.
    std::vector<PartResult> takeResults();
    /// Every write tried since the last call (applied or not), oldest first: for the history.
    std::vector<WriteRecord> takeWrites();
    /// The program events since the last call.
    std::vector<CycleEvent> takeEvents();
    /// Problems worth an alarm since the last call (connection lost, a part cut off, a write refused).
    std::vector<std::string> takeIncidents();
    SessionSnapshot snapshot() const;
    const SessionSettings& settings() const { return m_settings; }

    /// Runs `work` on the session's connection between its own requests (an operator's commands, tests); the
    /// future holds the work's exception when it throws. The connection is used by nobody else meanwhile.
    std::future<void> run(std::function<void(LinuxCncController&)> work);

private:
    struct Task {
        std::function<void(LinuxCncController&)> work;
        std::promise<void> done;
    };
    void loop();
    void runTask(Task& task);
    bool ensureConnected();
    void pollStatus();
    bool doPart(PartJob& job);
    void measureReference(const PartJob& job);
    bool cutPart(PartJob& job, const WriteRecord& write);
    void sampleUntilIdle(std::vector<std::array<double, 2>>& samples, bool& sawRunning, bool waitForStart);
    void connectionFailed(const LinuxCncError& e);
    void report(const std::string& incident, core::DeviceState state);
    void setHealth(core::DeviceState state, const std::string& message);
    void recordWrite(const WriteRecord& record);
    bool waitFor(int ms, bool wakeOnJobs);
    void partFailed(const std::string& problem);
    double now() const;

    SessionSettings m_settings;
    LinuxCncController m_controller;
    CorrectionWriter m_writer;
    std::optional<std::array<double, 2>> m_reference;  ///< machine minus program, X and Z mm (this connection)

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::thread m_thread;
    bool m_running = false;
    std::atomic<bool> m_stop{false};
    bool m_reconnect = false;
    std::deque<PartJob> m_jobs;
    std::deque<Task> m_tasks;
    std::vector<PartResult> m_results;
    std::vector<WriteRecord> m_writes;
    std::vector<CycleEvent> m_events;
    std::vector<std::string> m_incidents;
    SessionSnapshot m_snapshot;
    std::atomic<int> m_backoffMs{200};
    std::string m_heldReason;    ///< why the first job waits, reported once
    std::int64_t m_cutting = 0;  ///< the part whose program runs (0: none)
};

}  // namespace tt::devices::linuxcnc
