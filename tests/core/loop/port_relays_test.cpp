// The thread hand-off between devices that live in one thread (the GUI's) and the closed loop in another:
// GaugeRelay, CorrectionRelay and OperatorCycle (core/loop). Readings cross in order, health propagates,
// writes get the device's own result or a refusal with the reason, and the loop engine on these ports
// pauses and holds the last correction when the gauge is unplugged, and continues when it is back.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/loop/correction_relay.h"
#include "core/loop/gauge_relay.h"
#include "core/loop/loop_clock.h"
#include "core/loop/loop_engine.h"
#include "core/loop/operator_cycle.h"
#include "tests/core/support/loop_test_support.h"

namespace tt::core {
namespace {

using namespace std::chrono_literals;

/// Waits (polling every millisecond) until `done` holds; false after `timeout`.
template <typename F>
bool eventually(F done, std::chrono::milliseconds timeout = 10s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(1ms);
    }
    return true;
}

PartCorrection correctionOf(std::int64_t part, double mm) {
    return PartCorrection{part, {0.0, 100.0}, {mm, -mm}, CorrectionPath{{0.0, 100.0}, {mm, -mm}}};
}

// ---- GaugeRelay -------------------------------------------------------------------------------------

TEST(GaugeRelay, ReadingsCrossThreadsInTheOrderTheyWereDelivered) {
    ScaledClock clock(1.0);
    GaugeRelay relay(clock, 100000);
    relay.publishHealth({DeviceState::Ready, "gauge ready"});
    constexpr int kReadings = 20000;
    std::thread device([&] {
        for (int i = 0; i < kReadings; ++i)
            relay.deliver(27.0 + 0.001 * i);
    });
    std::vector<GaugeReading> taken;
    ASSERT_TRUE(eventually([&] {
        while (auto r = relay.takeReading())
            taken.push_back(*r);
        return taken.size() == static_cast<std::size_t>(kReadings);
    }));
    device.join();
    for (int i = 0; i < kReadings; ++i) {
        ASSERT_DOUBLE_EQ(taken[static_cast<std::size_t>(i)].diameterMm, 27.0 + 0.001 * i) << "reading " << i;
        if (i > 0) {
            EXPECT_GE(taken[static_cast<std::size_t>(i)].timeS, taken[static_cast<std::size_t>(i - 1)].timeS);
        }
    }
    EXPECT_EQ(relay.dropped(), 0u);
    EXPECT_FALSE(relay.takeReading());
}

TEST(GaugeRelay, HealthPublishedByTheDeviceIsWhatTheLoopSees) {
    ScaledClock clock(1.0);
    GaugeRelay relay(clock);
    EXPECT_EQ(relay.health().state, DeviceState::Connecting) << "nothing published yet";
    std::thread device([&] {
        relay.publishHealth({DeviceState::Ready, "gauge on /dev/ttyUSB0 ready"});
        relay.deliver(27.012);
        relay.publishHealth({DeviceState::Error, "the gauge on /dev/ttyUSB0 was unplugged"});
    });
    device.join();
    const DeviceHealth h = relay.health();
    EXPECT_EQ(h.state, DeviceState::Error);
    EXPECT_EQ(h.message, "the gauge on /dev/ttyUSB0 was unplugged");
    // A reading that arrived before the cable came out is still the loop's.
    ASSERT_TRUE(relay.takeReading());
}

TEST(GaugeRelay, KeepsAtMostTheNewestReadingsAndCountsTheRest) {
    ManualClock clock(5.0);
    GaugeRelay relay(clock, 3);
    for (double d : {1.0, 2.0, 3.0, 4.0, 5.0})
        relay.deliver(d);
    EXPECT_EQ(relay.dropped(), 2u);
    EXPECT_EQ(relay.pending(), 3u);
    EXPECT_DOUBLE_EQ(relay.takeReading()->diameterMm, 3.0);
    EXPECT_DOUBLE_EQ(relay.takeReading()->timeS, 5.0) << "stamped with the loop's clock";
    EXPECT_EQ(relay.discardPending(), 1u);
    EXPECT_FALSE(relay.takeReading());
    EXPECT_THROW(GaugeRelay(clock, 0), std::invalid_argument);
}

TEST(GaugeRelay, RequestsFromTheLoopAreCountedForTheDevice) {
    ManualClock clock;
    GaugeRelay relay(clock);
    relay.requestReading();
    relay.requestReading();
    EXPECT_EQ(relay.takeRequests(), 2);
    EXPECT_EQ(relay.takeRequests(), 0);
}

// ---- CorrectionRelay --------------------------------------------------------------------------------

/// The device's side in its own thread: serves every write with `answer` and records it.
class FakeCnc {
public:
    FakeCnc(CorrectionRelay& relay, std::function<OutputResult(const CorrectionRelay::Request&)> answer)
        : m_relay(relay), m_answer(std::move(answer)) {
        m_relay.setRequestListener([this] {
            std::lock_guard lock(m_mutex);  // only a notification, as the relay demands
            m_wake = true;
            m_cv.notify_one();
        });
        m_thread = std::thread([this] { run(); });
    }
    ~FakeCnc() {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_cv.notify_one();
        m_thread.join();
    }
    std::vector<std::int64_t> parts() {
        std::lock_guard lock(m_mutex);
        return m_parts;
    }
    std::thread::id threadId() const { return m_thread.get_id(); }
    std::vector<std::thread::id> servedOn() {
        std::lock_guard lock(m_mutex);
        return m_servedOn;
    }

private:
    void run() {
        std::unique_lock lock(m_mutex);
        while (!m_stop) {
            m_cv.wait_for(lock, 50ms, [this] { return m_wake || m_stop; });
            m_wake = false;
            lock.unlock();
            while (auto request = m_relay.takeRequest()) {
                const OutputResult result = m_answer(*request);
                {
                    std::lock_guard record(m_mutex);
                    if (const auto* part = std::get_if<PartCorrection>(&request->write))
                        m_parts.push_back(part->partNumber);
                    m_servedOn.push_back(std::this_thread::get_id());
                }
                m_relay.reply(request->id, result);
            }
            lock.lock();
        }
    }

    CorrectionRelay& m_relay;
    std::function<OutputResult(const CorrectionRelay::Request&)> m_answer;
    std::mutex m_mutex;
    std::condition_variable m_cv;
    bool m_wake = false;
    bool m_stop = false;
    std::vector<std::int64_t> m_parts;
    std::vector<std::thread::id> m_servedOn;
    std::thread m_thread;
};

TEST(CorrectionRelay, EachWriteIsDoneByTheDeviceThreadAndReturnsItsResult) {
    CorrectionRelay relay(10s);
    FakeCnc cnc(relay, [](const CorrectionRelay::Request& r) -> OutputResult {
        if (const auto* part = std::get_if<PartCorrection>(&r.write)) {
            if (part->pointCorrectionMm.front() > 0.4) return {false, "correction 0.5000 mm is beyond the limit"};
            return {true, {}};
        }
        return {false, "a G-code file cannot apply a dynamic X offset"};
    });
    for (std::int64_t part = 1; part <= 50; ++part)
        ASSERT_TRUE(relay.sendPartCorrection(correctionOf(part, 0.01)).ok) << part;
    const OutputResult refused = relay.sendPartCorrection(correctionOf(51, 0.5));
    EXPECT_FALSE(refused.ok);
    EXPECT_EQ(refused.message, "correction 0.5000 mm is beyond the limit") << "the device's own words";
    const OutputResult offset = relay.sendDynamicOffset(0.012);
    EXPECT_FALSE(offset.ok);
    EXPECT_EQ(offset.message, "a G-code file cannot apply a dynamic X offset");

    std::vector<std::int64_t> expected;
    for (std::int64_t part = 1; part <= 51; ++part)
        expected.push_back(part);
    EXPECT_EQ(cnc.parts(), expected) << "in order, each once";
    for (std::thread::id id : cnc.servedOn())
        EXPECT_EQ(id, cnc.threadId()) << "the output is only touched in its own thread";
}

TEST(CorrectionRelay, HealthIsTheDevicesAndAClosedRelayRefusesAtOnce) {
    CorrectionRelay relay(10s);
    relay.publishHealth({DeviceState::Error, "the folder /mnt/dnc does not exist"});
    EXPECT_EQ(relay.health().message, "the folder /mnt/dnc does not exist");
    relay.close("the run is over");
    EXPECT_EQ(relay.health().state, DeviceState::Disconnected);
    const OutputResult r = relay.sendPartCorrection(correctionOf(3, 0.01));
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.message, "the run is over; not sent: the corrections for part 3");
    EXPECT_FALSE(relay.takeRequest()) << "nothing reaches the device after close";
}

TEST(CorrectionRelay, AWriteNobodyTakesIsWithdrawnAsNotSent) {
    CorrectionRelay relay(100ms);
    const OutputResult r = relay.sendPartCorrection(correctionOf(7, 0.01));
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.message, "not sent: the CNC output did not take the corrections for part 7 within 0.1 s");
    EXPECT_FALSE(relay.takeRequest()) << "withdrawn: the device never writes it late";
}

TEST(CorrectionRelay, AWriteTakenButNotConfirmedSaysItMayHaveArrivedAndALateReplyIsIgnored) {
    CorrectionRelay relay(100ms);
    std::optional<CorrectionRelay::Request> taken;
    std::thread device([&] { ASSERT_TRUE(eventually([&] { return (taken = relay.takeRequest()).has_value(); })); });
    const OutputResult r = relay.sendPartCorrection(correctionOf(8, 0.01));
    device.join();
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.message,
              "the CNC output did not confirm the corrections for part 8 within 0.1 s (check on the CNC what arrived)");
    ASSERT_TRUE(taken);
    relay.reply(taken->id, {true, {}});  // too late: nobody waits for it
    FakeCnc cnc(relay, [](const CorrectionRelay::Request&) { return OutputResult{true, {}}; });
    EXPECT_TRUE(relay.sendPartCorrection(correctionOf(9, 0.01)).ok) << "the late reply is not taken for part 9's";
}

TEST(CorrectionRelay, ClosingReleasesAWaitingWriteWithTheReason) {
    CorrectionRelay relay(60s);
    OutputResult result;
    std::atomic<bool> returned{false};
    std::thread loop([&] {
        result = relay.sendPartCorrection(correctionOf(4, 0.01));
        returned = true;
    });
    ASSERT_TRUE(eventually([&] { return relay.takeRequest().has_value(); }));  // the device took it, then...
    relay.close("the Run page was closed");                                    // ...the GUI goes away
    loop.join();
    EXPECT_TRUE(returned);
    EXPECT_FALSE(result.ok);
    EXPECT_EQ(result.message,
              "the Run page was closed; not confirmed: the corrections for part 4 (check on the CNC what arrived)");
}

// ---- OperatorCycle ----------------------------------------------------------------------------------

TEST(OperatorCycle, OnePartAtATimeConfirmedByTheOperator) {
    ManualClock clock(100.0);
    OperatorCycle cycle(clock);
    EXPECT_TRUE(cycle.health().ready());
    EXPECT_FALSE(cycle.finishPart()) << "nothing on the machine";
    ASSERT_TRUE(cycle.startPart(1).ok);
    EXPECT_EQ(cycle.partOnMachine(), 1);
    const OutputResult busy = cycle.startPart(2);
    EXPECT_FALSE(busy.ok);
    EXPECT_EQ(busy.message, "part 1 is still on the machine; press Part finished first");
    EXPECT_FALSE(cycle.takeFinishedPart());
    clock.advanceTo(460.0);
    EXPECT_EQ(cycle.finishPart(), 1);
    EXPECT_FALSE(cycle.finishPart()) << "a second press does nothing";
    EXPECT_FALSE(cycle.partOnMachine());
    const auto finished = cycle.takeFinishedPart();
    ASSERT_TRUE(finished);
    EXPECT_EQ(finished->partNumber, 1);
    EXPECT_DOUBLE_EQ(finished->timeS, 460.0);
    EXPECT_TRUE(cycle.startPart(2).ok);
}

// ---- the loop engine on the relays, across threads --------------------------------------------------

/// The loop engine stepped in its own thread (as the GUI's loop worker does), with what the test needs to
/// see published under a lock.
class LoopThread {
public:
    struct Seen {
        LoopState state = LoopState::Idle;
        std::string detail;
        std::int64_t nextPart = 1;
        std::int64_t partsFinished = 0;
        std::vector<double> lastApplied;
    };

    LoopThread(LoopConfig config, LoopPorts ports) {
        m_thread = std::thread([this, config, ports] {
            LoopEngine engine(config, ports, std::make_unique<test::IntegratorController>(2, 0.5));
            engine.start({"test", "integrator", config.delayParts, 27.0, 100.0, config.pointZMm, "{}"});
            while (!m_stop) {
                engine.step();
                {
                    std::lock_guard lock(m_mutex);
                    m_seen = {engine.state(), engine.detail(), engine.nextPartNumber(), engine.partsFinished(),
                              engine.lastAppliedMm()};
                }
                std::this_thread::sleep_for(1ms);
            }
            engine.stop();
        });
    }
    ~LoopThread() {
        m_stop = true;
        m_thread.join();
    }
    Seen seen() {
        std::lock_guard lock(m_mutex);
        return m_seen;
    }

private:
    std::atomic<bool> m_stop{false};
    std::mutex m_mutex;
    Seen m_seen;
    std::thread m_thread;
};

TEST(LoopOnRelays, AnUnpluggedGaugePausesTheLoopHoldingTheCorrectionAndItContinuesWhenBack) {
    ScaledClock clock(1.0);
    GaugeRelay gauge(clock);
    CorrectionRelay output(10s);
    OperatorCycle machine(clock);
    gauge.publishHealth({DeviceState::Ready, "gauge ready"});
    output.publishHealth({DeviceState::Ready, "G-code files go to /tmp"});
    std::mutex cncMutex;
    std::vector<PartCorrection> written;  // what reached the "CNC" (in the test's thread)
    FakeCnc cnc(output, [&](const CorrectionRelay::Request& r) {
        std::lock_guard lock(cncMutex);
        written.push_back(std::get<PartCorrection>(r.write));
        return OutputResult{true, {}};
    });
    auto writtenCount = [&] {
        std::lock_guard lock(cncMutex);
        return written.size();
    };

    LoopConfig config;
    config.pointZMm = {10.0, 90.0};
    config.partLengthMm = 100.0;
    config.nominalDiameterMm = 27.0;
    config.delayParts = 1;
    LoopThread loop(config, LoopPorts{machine, output, gauge, clock, nullptr});

    // The operator machines parts 1..3 and measures each (the part is 0.020 mm oversize everywhere).
    for (std::int64_t part = 1; part <= 3; ++part) {
        ASSERT_TRUE(eventually([&] { return machine.partOnMachine() == part; })) << loop.seen().detail;
        EXPECT_EQ(writtenCount(), static_cast<std::size_t>(part)) << "corrections on the CNC before the part starts";
        ASSERT_EQ(machine.finishPart(), part);
        gauge.deliver(27.020);
        gauge.deliver(27.020);
    }
    ASSERT_TRUE(eventually([&] { return machine.partOnMachine() == 4; }));
    const std::vector<double> held = loop.seen().lastApplied;
    EXPECT_LT(held[0], -0.005) << "the loop corrects the oversize";

    // The gauge's cable comes out while part 4 is on the machine; part 4 comes off but cannot be measured.
    gauge.publishHealth({DeviceState::Error, "the gauge on /dev/ttyUSB0 was unplugged"});
    ASSERT_EQ(machine.finishPart(), 4);
    ASSERT_TRUE(eventually([&] { return loop.seen().state == LoopState::Paused; })) << loop.seen().detail;
    EXPECT_NE(loop.seen().detail.find("the gauge is not ready (the gauge on /dev/ttyUSB0 was unplugged)"),
              std::string::npos)
        << loop.seen().detail;
    std::this_thread::sleep_for(100ms);  // a hundred steps of the loop: still nothing new
    EXPECT_EQ(loop.seen().state, LoopState::Paused);
    EXPECT_EQ(writtenCount(), 4u) << "no new part, no new corrections";
    EXPECT_EQ(loop.seen().lastApplied, held) << "the CNC keeps the last correction";
    EXPECT_FALSE(machine.partOnMachine());

    // Plugged in again: the loop continues by itself, takes part 4's diameters and starts part 5.
    gauge.publishHealth({DeviceState::Ready, "gauge ready"});
    ASSERT_TRUE(eventually([&] { return loop.seen().state == LoopState::Running; })) << loop.seen().detail;
    gauge.deliver(27.010);
    gauge.deliver(27.010);
    ASSERT_TRUE(eventually([&] { return machine.partOnMachine() == 5; })) << loop.seen().detail;
    EXPECT_EQ(writtenCount(), 5u);
    std::lock_guard lock(cncMutex);
    EXPECT_EQ(written.back().partNumber, 5);
    EXPECT_LT(written.back().pointCorrectionMm[0], held[0]) << "part 4's oversize was used for part 5";
}

}  // namespace
}  // namespace tt::core
