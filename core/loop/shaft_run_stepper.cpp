#include "core/loop/shaft_run_stepper.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/loop/loop_engine.h"

namespace tt::core {

ShaftRunStepper::ShaftRunStepper(LoopEngine& engine, ShaftMachine& machine)
    : m_engine(engine), m_machine(machine), m_simulated(machine.jumpTo(machine.clock().nowS())) {}

double ShaftRunStepper::nextDueS() const {
    return std::min(m_machine.nextEventTimeS(), m_engine.nextWakeS());
}

bool ShaftRunStepper::stopped() const {
    return m_engine.state() == LoopState::Idle || m_engine.state() == LoopState::Fault;
}

void ShaftRunStepper::advanceTo(double untilS, int maxSteps) {
    for (int i = 0; i < maxSteps; ++i) {
        m_engine.step();
        if (stopped()) return;
        const double next = nextDueS();
        if (!m_simulated) {
            if (!(m_machine.nextEventTimeS() <= m_machine.clock().nowS())) return;
            continue;
        }
        if (!(next <= untilS)) return;  // later than the pace allows, or never
        if (next > m_machine.clock().nowS()) m_machine.jumpTo(next);
    }
}

SimulationOutcome ShaftRunStepper::runToEnd(std::int64_t maxSteps, double speed, const std::atomic<bool>* stop) {
    return runSimulation(m_engine, m_machine, maxSteps, speed, stop);
}

WallPace::WallPace(double machineS, double wallS, double speed) : m_machineS(machineS), m_wallS(wallS), m_speed(0.0) {
    setSpeed(speed, wallS);
}

double WallPace::machineAt(double wallS) const {
    return m_machineS + m_speed * std::max(0.0, wallS - m_wallS);
}

void WallPace::setSpeed(double speed, double wallS) {
    if (!std::isfinite(speed) || speed < 0.0) return;
    m_machineS = machineAt(wallS);
    m_wallS = wallS;
    m_speed = speed;
}

}  // namespace tt::core
