#include "devices/linuxcnc/linuxcnc_controller.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

#include "devices/parsers/linuxcnc_mdi.h"

namespace tt::devices::linuxcnc {

namespace {

std::string modeWord(TaskMode mode) {
    switch (mode) {
        case TaskMode::Manual:
            return "manual";
        case TaskMode::Auto:
            return "auto";
        case TaskMode::Mdi:
            return "mdi";
    }
    return "manual";
}

void pause(int ms) {
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
}

}  // namespace

bool MachineStatus::allHomed() const {
    return !homed.empty() && std::all_of(homed.begin(), homed.end(), [](bool h) { return h; });
}

std::string notReadyReason(const MachineStatus& s) {
    if (s.estop) return "the E-stop is on";
    if (!s.machineOn) return "the machine is off";
    if (!s.allHomed()) return "the machine is not homed";
    if (s.program == ProgramStatus::Running) return "a program is running";
    if (s.program == ProgramStatus::Paused) return "a program is paused";
    return {};
}

LinuxCncController::LinuxCncController(ControllerOptions options)
    : m_options(std::move(options)), m_link(m_options.endpoint) {}

template <typename T>
T LinuxCncController::value(const ParseResult<T>& parsed) {
    if (!parsed) {
        m_link.close();
        throw LinuxCncError(FailureKind::Garbage, where() + ": " + parsed.error());
    }
    return parsed.value();
}

bool LinuxCncController::setCommand(const std::string& line, int timeoutMs) {
    return m_link.request(line, timeoutMs).kind == ReplyKind::Ack;
}

void LinuxCncController::requireAck(const std::string& line, int timeoutMs) {
    if (!setCommand(line, timeoutMs)) throw LinuxCncError(FailureKind::Refused, where() + " refused '" + line + "'");
}

void LinuxCncController::connect() {
    m_link.connect(m_options.connectTimeoutMs);
    const int t = m_options.replyTimeoutMs;
    const Reply hello = m_link.request("hello " + m_options.connectPassword + " " + m_options.clientName + " 1.0", t);
    if (hello.kind != ReplyKind::HelloAck) {
        m_link.close();
        throw LinuxCncError(FailureKind::Refused, where() + " did not accept the connect password");
    }
    m_identity.server = hello.words.at(0);
    m_identity.protocol = hello.words.at(1);
    // With echo on (the default) the shell repeats every command before answering it.
    const std::string echo = m_link.requestLine("set echo off", t);
    if (echo != "set echo off") {
        m_link.close();
        throw LinuxCncError(FailureKind::Garbage, where() + " answered 'set echo off' with '" + echo + "'");
    }
    requireAck("set verbose on", t);
    if (!setCommand("set enable " + m_options.enablePassword, t)) {
        m_link.close();
        throw LinuxCncError(FailureKind::Refused, where() + " did not accept the enable password");
    }
    requireAck("set set_wait done", t);
    requireAck("set timeout 0", t);
    m_identity.machineUnits = value(linearUnits(m_link.request("get user_linear_units", t), "USER_LINEAR_UNITS"));
    if (millimetresPer(m_identity.machineUnits) == 0.0) {
        m_link.close();
        throw LinuxCncError(FailureKind::Refused, where() + " works in custom units; positions cannot be converted");
    }
}

MachineStatus LinuxCncController::status() {
    const int t = m_options.replyTimeoutMs;
    MachineStatus s;
    s.estop = value(onOff(m_link.request("get estop", t), "ESTOP"));
    s.machineOn = value(onOff(m_link.request("get machine", t), "MACHINE"));
    s.mode = value(taskMode(m_link.request("get mode", t)));
    s.program = value(programStatus(m_link.request("get program_status", t)));
    const std::vector<bool> homed = value(jointsHomed(m_link.request("get joint_homed", t)));
    const auto joints = static_cast<std::size_t>(std::max(1, m_options.joints));
    if (homed.size() < joints) {
        m_link.close();
        throw LinuxCncError(FailureKind::Garbage, where() + " reports " + std::to_string(homed.size()) + " joints; " +
                                                      std::to_string(joints) + " must be homed");
    }
    s.homed.assign(homed.begin(), homed.begin() + static_cast<std::ptrdiff_t>(joints));
    return s;
}

ProgramStatus LinuxCncController::program() {
    return value(programStatus(m_link.request("get program_status", m_options.replyTimeoutMs)));
}

void LinuxCncController::setMode(TaskMode mode) {
    const int t = m_options.replyTimeoutMs;
    if (value(taskMode(m_link.request("get mode", t))) == mode) return;
    requireAck("set mode " + modeWord(mode), t);
    for (int i = 0; i < 100; ++i) {
        if (value(taskMode(m_link.request("get mode", t))) == mode) return;
        pause(5);
    }
    throw LinuxCncError(FailureKind::Refused, where() + " did not change to " + std::string(modeName(mode)) + " mode");
}

bool LinuxCncController::tryMdi(const std::string& line, int timeoutMs, std::string& why) {
    if (setCommand("set mdi " + line, timeoutMs)) return true;
    why = drainMessages();
    if (why.empty()) why = "no reason given";
    return false;
}

void LinuxCncController::mdi(const std::string& line, int timeoutMs) {
    std::string why;
    if (!tryMdi(line, timeoutMs, why))
        throw LinuxCncError(FailureKind::Refused, where() + " refused the MDI line '" + line + "': " + why);
}

std::array<double, 2> LinuxCncController::positionMm() {
    const std::array<double, 6> p =
        value(position(m_link.request("get abs_act_pos", m_options.replyTimeoutMs), "ABS_ACT_POS"));
    const double mm = millimetresPer(m_identity.machineUnits);
    return {p[0] * mm, p[2] * mm};
}

void LinuxCncController::openProgram(const std::string& path) {
    requireAck("set open " + path, m_options.replyTimeoutMs);
}

void LinuxCncController::setFeedOverride(int percent) {
    if (percent < 1 || percent > 100)
        throw std::invalid_argument("a feed override of " + std::to_string(percent) + " % is outside 1 .. 100 %");
    requireAck("set feed_override " + std::to_string(percent), m_options.replyTimeoutMs);
}

void LinuxCncController::startProgram() {
    const int t = m_options.replyTimeoutMs;
    // With set_wait done `set run` would return only at the program's end; TrueTurn samples the cut meanwhile.
    requireAck("set set_wait received", t);
    const bool started = setCommand("set run", t);
    requireAck("set set_wait done", t);
    if (!started) {
        const std::string why = drainMessages();
        throw LinuxCncError(FailureKind::Refused,
                            where() + " refused cycle start" + (why.empty() ? std::string() : ": " + why));
    }
}

void LinuxCncController::abort() {
    requireAck("set abort", m_options.replyTimeoutMs);
}

std::string LinuxCncController::drainMessages() {
    const int t = m_options.replyTimeoutMs;
    std::string last;
    for (int i = 0; i < 16; ++i) {
        const std::string error = value(message(m_link.request("get error", t), "ERROR"));
        const std::string display = value(message(m_link.request("get operator_display", t), "OPERATOR_DISPLAY"));
        const std::string text = value(message(m_link.request("get operator_text", t), "OPERATOR_TEXT"));
        if (!error.empty()) last = error;
        if (error.empty() && display.empty() && text.empty()) break;
    }
    return last;
}

std::vector<double> LinuxCncController::readParameters(const std::vector<std::string>& parameters) {
    drainMessages();
    const std::string tag = "TRUETURN" + std::to_string(++m_tag);
    mdi(debugLine(tag, parameters), m_options.replyTimeoutMs);
    for (int i = 0; i < 200; ++i) {
        const std::string text =
            value(message(m_link.request("get operator_display", m_options.replyTimeoutMs), "OPERATOR_DISPLAY"));
        if (text.rfind(tag + " ", 0) == 0 || text == tag) return value(taggedNumbers(text, tag, parameters.size()));
        pause(2);
    }
    throw LinuxCncError(FailureKind::Garbage, where() + " did not show the message " + tag + " with the parameters");
}

}  // namespace tt::devices::linuxcnc
