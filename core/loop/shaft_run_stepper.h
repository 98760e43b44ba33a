#pragma once

#include <atomic>
#include <cstdint>

#include "core/loop/loop_runner.h"
#include "core/ports/shaft_machine.h"

namespace tt::core {

class LoopEngine;

/// The one place a shaft run's engine is driven on its machine, for the GUI's loop thread and for headless
/// runs alike. A machine in simulated time (ShaftMachine::jumpTo) is moved from event to event of the
/// machine and the engine, in the same order whether it runs as fast as possible or paced by the wall
/// clock, so a run gives the same parts either way; a machine on the wall clock is stepped as it is polled.
class ShaftRunStepper {
public:
    /// Both must outlive the stepper.
    ShaftRunStepper(LoopEngine& engine, ShaftMachine& machine);

    /// The machine lives in simulated time (its time moves only through the stepper).
    bool simulatedTime() const { return m_simulated; }

    /// Steps the engine and moves a machine in simulated time from event to event up to `untilS` of its
    /// time (no event later than that is taken); a machine on the wall clock is stepped until nothing more
    /// is due. At most `maxSteps` engine steps.
    void advanceTo(double untilS, int maxSteps);

    /// Runs until the run completes, faults or nothing can happen any more (runSimulation's outcome):
    /// `speed` 0 as fast as possible, else machine s per wall s of waiting between events; `stop` (may be
    /// null) ends the run after the part on the machine. A machine on the wall clock cannot be run this way
    /// (std::invalid_argument).
    SimulationOutcome runToEnd(std::int64_t maxSteps = 100'000'000, double speed = 0.0,
                               const std::atomic<bool>* stop = nullptr);

private:
    /// The next time something is due: the machine's next event or the engine's wake-up.
    double nextDueS() const;
    bool stopped() const;

    LoopEngine& m_engine;
    ShaftMachine& m_machine;
    bool m_simulated = false;
};

/// Pacing of a machine in simulated time by the wall clock: machine time = anchor + speed x wall time
/// since the anchor; a new speed re-anchors, so the machine's time never jumps back or ahead.
class WallPace {
public:
    /// Starts at machine time `machineS` and wall time `wallS` with `speed` machine s per wall s (>= 0).
    WallPace(double machineS, double wallS, double speed);
    /// The machine time the wall time `wallS` stands for.
    double machineAt(double wallS) const;
    /// From wall time `wallS` on, `speed` machine s per wall s (>= 0, finite; anything else is ignored).
    void setSpeed(double speed, double wallS);
    double speed() const { return m_speed; }

private:
    double m_machineS;
    double m_wallS;
    double m_speed;
};

}  // namespace tt::core
