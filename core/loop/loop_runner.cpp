#include "core/loop/loop_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/loop/loop_clock.h"
#include "core/loop/loop_engine.h"

namespace tt::core {

namespace {

/// Waits `wallS` seconds in slices of at most 0.1 s, returning early once `stop` is set.
void pace(double wallS, const std::atomic<bool>* stop) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point end =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wallS));
    while (!(stop && stop->load())) {
        const Clock::time_point now = Clock::now();
        if (now >= end) return;
        std::this_thread::sleep_for(std::min<Clock::duration>(end - now, std::chrono::milliseconds(100)));
    }
}

}  // namespace

bool runEnds(const LoopEngine& engine, const std::atomic<bool>* stop, std::optional<std::int64_t>& stopAfter,
             SimulationOutcome& outcome) {
    if (engine.complete()) {
        outcome.complete = true;
        return true;
    }
    if (!stopAfter && stop && stop->load()) stopAfter = engine.partsFinished();
    if (stopAfter && engine.partsFinished() > *stopAfter) {
        outcome.interrupted = true;
        outcome.stopReason = "interrupted";
        return true;
    }
    if (engine.state() == LoopState::Fault || engine.state() == LoopState::Idle) {
        outcome.stopReason = engine.detail();
        return true;
    }
    return false;
}

namespace {

/// Steps `engine` and moves time on with `jump` to the next event of the devices or the engine.
template <typename Jump>
SimulationOutcome simulate(LoopEngine& engine, const Clock& clock, const SimulationTimeline& devices, Jump jump,
                           std::int64_t maxSteps, double speed, const std::atomic<bool>* stop) {
    SimulationOutcome outcome;
    int stalled = 0;
    std::optional<std::int64_t> stopAfter;  // parts finished when the stop was asked for
    for (std::int64_t i = 0; i < maxSteps; ++i) {
        engine.step();
        if (runEnds(engine, stop, stopAfter, outcome)) break;
        const double next = std::min(devices.nextEventTimeS(), engine.nextWakeS());
        if (!std::isfinite(next)) {
            outcome.stopReason = "nothing more can happen: " + engine.detail();
            break;
        }
        // An event due now that the engine did not take means it cannot make progress by waiting.
        stalled = next <= clock.nowS() ? stalled + 1 : 0;
        if (stalled > 1000) {
            outcome.stopReason = "the simulation does not advance: " + engine.detail();
            break;
        }
        if (speed > 0.0 && !stopAfter && next > clock.nowS()) pace((next - clock.nowS()) / speed, stop);
        jump(next);
    }
    if (!outcome.complete && outcome.stopReason.empty()) outcome.stopReason = "the step limit was reached";
    outcome.simulatedS = clock.nowS();
    return outcome;
}

/// A machine seen as the timeline of its devices.
class MachineTimeline final : public SimulationTimeline {
public:
    explicit MachineTimeline(const ShaftMachine& machine) : m_machine(machine) {}
    double nextEventTimeS() const override { return m_machine.nextEventTimeS(); }

private:
    const ShaftMachine& m_machine;
};

}  // namespace

SimulationOutcome runSimulation(LoopEngine& engine, ManualClock& clock, const SimulationTimeline& devices,
                                std::int64_t maxSteps, double speed, const std::atomic<bool>* stop) {
    return simulate(
        engine, clock, devices, [&clock](double t) { clock.advanceTo(t); }, maxSteps, speed, stop);
}

SimulationOutcome runSimulation(LoopEngine& engine, ShaftMachine& machine, std::int64_t maxSteps, double speed,
                                const std::atomic<bool>* stop) {
    if (!machine.jumpTo(machine.clock().nowS()))
        throw std::invalid_argument("this machine runs in real time; it cannot be simulated event by event");
    const MachineTimeline timeline(machine);
    return simulate(
        engine, machine.clock(), timeline, [&machine](double t) { machine.jumpTo(t); }, maxSteps, speed, stop);
}

}  // namespace tt::core
