#include "core/loop/loop_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "core/loop/loop_clock.h"
#include "core/loop/loop_engine.h"

namespace tt::core {

SimulationOutcome runSimulation(LoopEngine& engine, ManualClock& clock, const SimulationTimeline& devices,
                                std::int64_t maxSteps, double speed) {
    SimulationOutcome outcome;
    int stalled = 0;
    for (std::int64_t i = 0; i < maxSteps; ++i) {
        engine.step();
        if (engine.complete()) {
            outcome.complete = true;
            break;
        }
        if (engine.state() == LoopState::Fault || engine.state() == LoopState::Idle) {
            outcome.stopReason = engine.detail();
            break;
        }
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
        if (speed > 0.0 && next > clock.nowS())
            std::this_thread::sleep_for(std::chrono::duration<double>((next - clock.nowS()) / speed));
        clock.advanceTo(next);
    }
    if (!outcome.complete && outcome.stopReason.empty()) outcome.stopReason = "the step limit was reached";
    outcome.simulatedS = clock.nowS();
    return outcome;
}

}  // namespace tt::core
