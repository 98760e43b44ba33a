#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "devices/linuxcnc/linuxcnc_link.h"

namespace tt::devices::linuxcnc {

/// How to reach and talk to the remote shell.
struct ControllerOptions {
    Endpoint endpoint;
    std::string connectPassword = "EMC";    ///< linuxcncrsh --connectpw
    std::string enablePassword = "EMCTOO";  ///< linuxcncrsh --enablepw (the right to command the machine)
    std::string clientName = "TrueTurn";    ///< how TrueTurn introduces itself (no spaces)
    int connectTimeoutMs = 2000;
    int replyTimeoutMs = 3000;  ///< a reply, a mode change, an MDI line without motion
    int joints = 2;             ///< joints that must be homed (a lathe: X and Z)
};

/// What the shell says about itself when TrueTurn connects.
struct Identity {
    std::string server;                                  ///< the server name of HELLO ACK ("EMCNETSVR")
    std::string protocol;                                ///< its protocol version ("1.1")
    LinearUnits machineUnits = LinearUnits::Millimetre;  ///< the units positions come in
};

/// The machine's state as TrueTurn checks it before every write.
struct MachineStatus {
    bool estop = true;
    bool machineOn = false;
    TaskMode mode = TaskMode::Manual;
    ProgramStatus program = ProgramStatus::Idle;
    std::vector<bool> homed;  ///< the first `joints` joints
    bool allHomed() const;
};

/// Why nothing may be written now, in the user's terms ("the E-stop is on"); empty when the machine is on,
/// homed and no program runs.
std::string notReadyReason(const MachineStatus& status);

/// The remote shell's commands as TrueTurn uses them, on one connection, blocking (one thread). At connect:
/// hello, echo off, verbose on (every set is acknowledged), enable, set_wait done with no timeout of its own
/// (linuxcncrsh 2.9 refuses every `set_wait done` command at once when it has a timeout: the link's own
/// timeouts guard against a task that never answers), then the machine's units. Every failure throws
/// LinuxCncError naming the host and the command.
class LinuxCncController {
public:
    explicit LinuxCncController(ControllerOptions options);

    /// Connects and introduces itself. Throws LinuxCncError (Unreachable, Refused for a wrong password).
    void connect();
    void disconnect() { m_link.close(); }
    bool connected() const { return m_link.connected(); }
    const Identity& identity() const { return m_identity; }
    const ControllerOptions& options() const { return m_options; }

    /// E-stop, machine power, mode, program status, homing.
    MachineStatus status();
    /// Whether a program runs (cheaper than status()).
    ProgramStatus program();
    /// Switches the task's mode (no-op when it is in it already). Throws Refused when LinuxCNC refuses.
    void setMode(TaskMode mode);
    /// Runs one MDI line and waits for it to finish (motion included, up to `timeoutMs`). Throws Refused with
    /// LinuxCNC's error message when it refuses or fails the line.
    void mdi(const std::string& line, int timeoutMs);
    /// Runs one MDI line; false (and LinuxCNC's message in `why`) when LinuxCNC refuses or fails it.
    bool tryMdi(const std::string& line, int timeoutMs, std::string& why);
    /// Where the tool is in machine coordinates: X (a radius) and Z, mm.
    std::array<double, 2> positionMm();
    /// Opens a program file on the LinuxCNC computer (absolute path).
    void openProgram(const std::string& path);
    /// The feed override, % of the programmed feed (1 .. 100). Throws Refused when LinuxCNC refuses.
    void setFeedOverride(int percent);
    /// Cycle start: runs the open program from its start and returns once LinuxCNC has the command.
    void startProgram();
    /// Stops a running program or MDI command.
    void abort();
    /// The values of `parameters` (names: "#500", "#5420") as LinuxCNC holds them, from an operator message
    /// `(DEBUG,...)`; slow (the controller takes 0.1 s to acknowledge a message). Throws Garbage when the message
    /// does not come.
    std::vector<double> readParameters(const std::vector<std::string>& parameters);
    /// Reads and forgets LinuxCNC's pending messages; returns the last error message (empty: none).
    std::string drainMessages();
    /// One request as is (tests, diagnosis).
    Reply request(const std::string& line) { return m_link.request(line, m_options.replyTimeoutMs); }

private:
    bool setCommand(const std::string& line, int timeoutMs);
    void requireAck(const std::string& line, int timeoutMs);
    std::string where() const { return "LinuxCNC at " + m_options.endpoint.text(); }
    template <typename T>
    T value(const ParseResult<T>& parsed);

    ControllerOptions m_options;
    LinuxCncLink m_link;
    Identity m_identity;
    std::uint64_t m_tag = 0;
};

}  // namespace tt::devices::linuxcnc
