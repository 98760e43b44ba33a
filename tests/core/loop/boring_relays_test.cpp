// The relays that let the in-process compensation run in its own thread while its devices live in
// the GUI thread (issue 11): samples and health pass through in order, an offset is handed over
// without waiting, the CNC's answer comes back, and a device side that does not take the offset in
// time makes the compensation hold rather than run ahead of the CNC. Also with two real threads.
#include "core/loop/boring_relays.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "support/fake_boring_ports.h"
#include "core/loop/loop_clock.h"
#include "core/run/boring_run.h"

namespace tt::core {
namespace {

ProbeSample bent(double timeS, double deflectionMm) {
    return test::probeSample(timeS, deflectionMm);
}

TEST(SampleRelay, PassesSamplesInOrderWithTheDevicesHealthAndDropsTheOldestWhenFull) {
    DriveRelay drive(3);
    EXPECT_EQ(drive.health().state, DeviceState::Connecting);  // before the device's side said anything
    drive.publishHealth({DeviceState::Ready, "polling"});
    for (int i = 1; i <= 4; ++i)
        drive.deliver({0.02 * i, 1.0 * i, 0.1, 0.0});
    EXPECT_EQ(drive.dropped(), 1u);
    EXPECT_EQ(drive.pending(), 3u);
    EXPECT_DOUBLE_EQ(drive.takeSample()->currentA, 2.0);  // the first was dropped
    EXPECT_DOUBLE_EQ(drive.takeSample()->currentA, 3.0);
    EXPECT_EQ(drive.health().message, "polling");
    EXPECT_THROW(ProbeRelay(0), std::invalid_argument);
}

TEST(OffsetRelay, HandsTheOffsetOverAtOnceAndKeepsWhatTheCncConfirmed) {
    ManualClock clock;
    OffsetRelay relay(clock, 0.05);
    int wakeUps = 0;
    relay.setRequestListener([&] { ++wakeUps; });
    relay.publishHealth({DeviceState::Ready, {}});
    EXPECT_TRUE(relay.sendDynamicOffset(0.010).ok);
    EXPECT_TRUE(relay.sendDynamicOffset(0.011).ok);  // the newer replaces the one not yet taken
    EXPECT_EQ(wakeUps, 2);
    EXPECT_FALSE(relay.confirmedOffsetMm().has_value());
    EXPECT_DOUBLE_EQ(*relay.takePending(), 0.011);
    EXPECT_FALSE(relay.takePending().has_value());
    relay.reply(0.011, {true, {}});
    EXPECT_DOUBLE_EQ(*relay.confirmedOffsetMm(), 0.011);
    // The device refuses the next one: the write after it says so, with the device's words.
    ASSERT_TRUE(relay.sendDynamicOffset(0.012).ok);
    relay.reply(*relay.takePending(), {false, "read-back mismatch"});
    const OutputResult refused = relay.sendDynamicOffset(0.013);
    EXPECT_FALSE(refused.ok);
    EXPECT_EQ(refused.message, "read-back mismatch");
    EXPECT_DOUBLE_EQ(*relay.confirmedOffsetMm(), 0.011);
    EXPECT_FALSE(relay.sendPartCorrection({}).ok);  // dynamic offsets only
    relay.close();
    EXPECT_EQ(relay.health().state, DeviceState::Disconnected);
    EXPECT_FALSE(relay.sendDynamicOffset(0.0).ok);
    EXPECT_EQ(wakeUps, 3);  // not woken after close
    EXPECT_THROW(OffsetRelay(clock, 0.0), std::invalid_argument);
}

TEST(OffsetRelay, AnOffsetNotTakenInTimeMakesTheOutputNotReady) {
    ManualClock clock;
    OffsetRelay relay(clock, 0.05);
    relay.publishHealth({DeviceState::Ready, {}});
    ASSERT_TRUE(relay.sendDynamicOffset(0.01).ok);
    clock.advanceBy(0.04);
    EXPECT_TRUE(relay.health().ready());
    ASSERT_TRUE(relay.sendDynamicOffset(0.011).ok);  // still counted from the first one handed over
    clock.advanceBy(0.02);
    EXPECT_EQ(relay.health().state, DeviceState::Connecting);  // 60 ms > 50 ms: the GUI thread is busy
    EXPECT_TRUE(relay.health().message.empty());               // no sentence: the kind says it
    relay.reply(*relay.takePending(), {true, {}});
    EXPECT_TRUE(relay.health().ready());
}

TEST(RelayedBoringStation, TheRunHoldsWhileTheDeviceSideIsBusyAndContinuesAfterIt) {
    ManualClock clock;
    RelayedBoringStation station(clock, false, true, 0.05);
    EXPECT_EQ(station.driveReadout(), nullptr);
    ASSERT_NE(station.probeRelay(), nullptr);
    BoringRunChoices c;
    c.method = BoringMethod::Probe;
    c.stiffnessNPerMm = 2000.0;
    c.limits = {0.5, 0.05};
    const std::unique_ptr<BoringRun> run = buildBoringRun(c, station);
    station.probeRelay()->publishHealth({DeviceState::Ready, {}});
    station.outputRelay().publishHealth({DeviceState::Ready, {}});
    // The device side (the GUI thread) answers every cycle for 10 cycles: the offset climbs.
    auto deviceSide = [&] {
        if (const std::optional<double> offset = station.outputRelay().takePending())
            station.outputRelay().reply(*offset, {true, {}});
    };
    for (int i = 0; i < 10; ++i) {
        clock.advanceBy(0.02);
        station.probeRelay()->deliver(bent(clock.nowS(), -0.1));
        run->cycle();
        deviceSide();
    }
    EXPECT_NEAR(*station.confirmedOffsetMm(), 0.010, 1e-12);
    // Then it is busy for 200 ms: after 50 ms the run holds the offset it handed over last.
    for (int i = 0; i < 10; ++i) {
        clock.advanceBy(0.02);
        station.probeRelay()->deliver(bent(clock.nowS(), -0.1));
        run->cycle();
    }
    EXPECT_NEAR(run->offsetMm(), 0.013, 1e-12);  // 3 cycles before the hold
    clock.advanceBy(0.02);
    station.probeRelay()->deliver(bent(clock.nowS(), -0.1));
    const BoringRunCycle busy = run->cycle();
    EXPECT_EQ(busy.compensation->outputProblem, OutputProblem::NotReady);
    EXPECT_EQ(busy.compensation->outputHealth.state, DeviceState::Connecting);
    deviceSide();  // the device side is back: the newest offset reaches the CNC
    EXPECT_NEAR(*station.confirmedOffsetMm(), 0.013, 1e-12);
    clock.advanceBy(0.02);
    station.probeRelay()->deliver(bent(clock.nowS(), -0.1));
    EXPECT_TRUE(run->cycle().compensation->sent);
    EXPECT_NEAR(run->offsetMm(), 0.014, 1e-12);
}

TEST(RelayedBoringStation, TwoThreadsShareItWithoutLosingASample) {
    ScaledClock clock(1.0);
    RelayedBoringStation station(clock, true, false, 1.0);
    constexpr int kSamples = 20000;
    std::atomic<bool> done = false;
    std::thread device([&] {
        for (int i = 0; i < kSamples; ++i)
            station.driveRelay()->deliver({1e-3 * i, 1.0, 0.1, 0.0});
        done = true;
    });
    int taken = 0;
    double last = -1.0;
    while (!done || station.driveRelay()->pending() > 0)
        while (const std::optional<DriveSample> s = station.driveReadout()->takeSample()) {
            EXPECT_GT(s->timeS, last);  // in order
            last = s->timeS;
            ++taken;
        }
    device.join();
    EXPECT_EQ(taken + static_cast<int>(station.driveRelay()->dropped()), kSamples);
}

}  // namespace
}  // namespace tt::core
