#pragma once

// The LinuxCNC the tests run against: the headless simulated lathe of scripts/start-test-linuxcnc.sh, found
// through TRUETURN_LINUXCNC_URL and TRUETURN_LINUXCNC_DIR (test.sh exports them). A test that needs it FAILS when it
// is missing (like the rs274 tests): CI must run it. The tests use it one at a time (CTest RESOURCE_LOCK linuxcnc).
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <QString>
#include <QThread>
#include <QUrl>
#include <chrono>
#include <csignal>
#include <future>
#include <optional>
#include <string>
#include <thread>

#include "devices/linuxcnc/linuxcnc_controller.h"

namespace tt::test {

/// Where the test LinuxCNC is.
struct TestLinuxCnc {
    std::string host;
    int port = 0;
    QString dir;  ///< the folder of start-test-linuxcnc.sh (its config, PID files and the nc/ folder)
    QString url() const { return QStringLiteral("linuxcnc://%1:%2").arg(QString::fromStdString(host)).arg(port); }
    QString programFolder() const { return dir + QStringLiteral("/nc"); }
    devices::linuxcnc::Endpoint endpoint() const { return {host, port}; }
};

/// The test LinuxCNC, or a failure saying how to start it.
inline std::optional<TestLinuxCnc> testLinuxCnc() {
    const QString url = qEnvironmentVariable("TRUETURN_LINUXCNC_URL");
    const QString dir = qEnvironmentVariable("TRUETURN_LINUXCNC_DIR");
    if (url.isEmpty() || dir.isEmpty()) {
        ADD_FAILURE() << "no test LinuxCNC: start it with eval \"$(scripts/start-test-linuxcnc.sh /tmp/lcnc)\" "
                         "(needs linuxcnc-uspace: scripts/install-deps.sh --with-test-tools); test.sh does this";
        return std::nullopt;
    }
    const QUrl parsed(url);
    return TestLinuxCnc{parsed.host().toStdString(), parsed.port(5007), dir};
}

#define TT_REQUIRE_LINUXCNC(name)                                                    \
    const std::optional<::tt::test::TestLinuxCnc> name = ::tt::test::testLinuxCnc(); \
    if (!name) return

/// Waits (polling every 10 ms) until `done()` or `seconds` pass; whether it became true.
template <typename Done>
bool waitUntil(Done done, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
}

/// What an operator does before production: E-stop off, machine on, all joints homed, no program running.
inline void bringUp(devices::linuxcnc::LinuxCncController& c) {
    using devices::linuxcnc::ProgramStatus;
    using devices::linuxcnc::TaskMode;
    if (c.status().program != ProgramStatus::Idle) c.abort();
    if (c.status().estop) c.request("set estop off");
    c.request("set machine on");
    if (!waitUntil([&] { return c.status().machineOn; }, 10.0))
        throw std::runtime_error("the machine does not come on");
    if (!c.status().allHomed()) {
        c.setMode(TaskMode::Manual);
        c.request("set home -1");
        if (!waitUntil([&] { return c.status().allHomed(); }, 20.0))
            throw std::runtime_error("the machine does not home");
    }
}

/// Runs `work` on the session's connection (between its own requests) and waits for it, at most `seconds`.
template <typename Session, typename Work>
bool operate(Session& session, Work work, double seconds = 60.0) {
    auto done = session.run(work);
    if (done.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
        ADD_FAILURE() << "LinuxCNC did not take the operator's commands within " << seconds << " s";
        return false;
    }
    try {
        done.get();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "the operator's commands failed: " << e.what();
        return false;
    }
    return true;
}

/// Brings the test LinuxCNC up on a connection of its own (only while no session of the test talks to it: the
/// remote shell must not parse two requests at once).
inline void bringUpNow(const TestLinuxCnc& lc) {
    devices::linuxcnc::ControllerOptions o;
    o.endpoint = lc.endpoint();
    o.clientName = "TrueTurnTestOperator";
    devices::linuxcnc::LinuxCncController c(o);
    c.connect();
    bringUp(c);
    c.disconnect();
}

/// Runs scripts/start-test-linuxcnc.sh with `arguments`; its output on failure.
inline bool runScript(const QStringList& arguments, QString* output = nullptr) {
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(QStringLiteral(TRUETURN_SOURCE_DIR "/scripts/start-test-linuxcnc.sh"), arguments);
    const bool ok = p.waitForFinished(120000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    if (output) *output = QString::fromUtf8(p.readAll());
    return ok;
}

/// Kills LinuxCNC's remote shell (SIGKILL, as a crash would; the linuxcnc script then shuts the rest down) and
/// waits until nothing is left.
inline bool killLinuxCnc(const TestLinuxCnc& lc) {
    QFile pids(lc.dir + QStringLiteral("/components.pid"));
    if (!pids.open(QIODevice::ReadOnly)) return false;
    bool killed = false;
    for (const QByteArray& line : pids.readAll().split('\n')) {
        const QList<QByteArray> words = line.split(' ');
        if (words.size() != 2 || words[1] != "linuxcncrsh") continue;
        const int pid = words[0].toInt();
        QFile comm(QStringLiteral("/proc/%1/comm").arg(pid));
        if (comm.open(QIODevice::ReadOnly) && comm.readAll().trimmed() == "linuxcncrsh")
            killed = ::kill(pid, SIGKILL) == 0;
    }
    QString output;
    return killed && runScript({QStringLiteral("--stop"), lc.dir}, &output);
}

/// Starts the test LinuxCNC again on the same folder and port (after killLinuxCnc).
inline bool restartLinuxCnc(const TestLinuxCnc& lc) {
    QString output;
    const bool ok = runScript({lc.dir, QString::number(lc.port)}, &output);
    if (!ok) ADD_FAILURE() << "restarting LinuxCNC failed: " << output.toStdString();
    return ok;
}

}  // namespace tt::test
