#include "core/loop/loop_clock.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

void ManualClock::advanceTo(double timeS) {
    if (timeS > m_nowS) m_nowS = timeS;
}

ScaledClock::ScaledClock(double speed, double startS) : m_baseWall(Wall::now()), m_baseS(startS), m_speed(0.0) {
    setSpeed(speed);
}

double ScaledClock::simulatedAt(Wall::time_point wall) const {
    return m_baseS + m_speed * std::chrono::duration<double>(wall - m_baseWall).count();
}

double ScaledClock::nowS() const {
    std::lock_guard lock(m_mutex);
    return simulatedAt(Wall::now());
}

void ScaledClock::setSpeed(double speed) {
    if (!std::isfinite(speed) || speed < 0.0)
        throw std::invalid_argument("the simulation speed must be zero or positive (got " + std::to_string(speed) +
                                    ")");
    std::lock_guard lock(m_mutex);
    const auto wall = Wall::now();
    m_baseS = simulatedAt(wall);
    m_baseWall = wall;
    m_speed = speed;
}

double ScaledClock::speed() const {
    std::lock_guard lock(m_mutex);
    return m_speed;
}

}  // namespace tt::core
