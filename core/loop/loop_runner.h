#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "core/ports/shaft_machine.h"
#include "core/ports/simulation_timeline.h"

namespace tt::core {

class LoopEngine;
class ManualClock;

/// How a simulation run ended.
struct SimulationOutcome {
    bool complete = false;     ///< the run reached its last part and every part was measured
    std::string stopReason;    ///< otherwise why it stopped (fault, stuck), in the user's terms
    double simulatedS = 0.0;   ///< simulated time at the end, s
    bool interrupted = false;  ///< stopped on request (`stop`) after the part on the machine was finished
};

/// After a step of `engine`: whether the run ends now, with `outcome` filled: complete, interrupted (once `stop` is
/// set, after the part on the machine then: `stopAfter` keeps the parts finished when it was asked for), faulted or
/// stopped.
bool runEnds(const LoopEngine& engine, const std::atomic<bool>* stop, std::optional<std::int64_t>& stopAfter,
             SimulationOutcome& outcome);

/// Runs the engine on simulated devices: step, then move the clock to the next event of the devices or
/// the engine. `speed` 0 jumps at once (as fast as possible); a positive speed waits (simulated time
/// / speed) of wall time for every jump, so a part of 6 min takes 1 s at speed 360. Stops when the run
/// completes, on a fault, when nothing can happen any more (nobody will answer) or after `maxSteps`.
/// When `stop` (may be null; set from another thread or a signal handler) becomes true, the part on
/// the machine is finished without pacing and the run stops there (outcome.interrupted); what the
/// engine stored stays stored and the run can be resumed.
SimulationOutcome runSimulation(LoopEngine& engine, ManualClock& clock, const SimulationTimeline& devices,
                                std::int64_t maxSteps = 100'000'000, double speed = 0.0,
                                const std::atomic<bool>* stop = nullptr);

/// The same on a machine that lives in simulated time (ShaftMachine::jumpTo); a machine whose time is
/// the wall clock cannot be run this way (std::invalid_argument).
SimulationOutcome runSimulation(LoopEngine& engine, ShaftMachine& machine, std::int64_t maxSteps = 100'000'000,
                                double speed = 0.0, const std::atomic<bool>* stop = nullptr);

}  // namespace tt::core
