#pragma once

#include <chrono>
#include <mutex>

#include "core/ports/clock.h"

namespace tt::core {

/// Simulated time that moves only when told to: the headless simulation jumps from event to event,
/// tests step it by hand. Seconds.
class ManualClock final : public Clock {
public:
    /// Starts at `startS` seconds.
    explicit ManualClock(double startS = 0.0) : m_nowS(startS) {}
    double nowS() const override { return m_nowS; }
    /// Moves to `timeS`; never backwards (an earlier time is ignored).
    void advanceTo(double timeS);
    /// Moves on by `seconds` (a negative step is ignored).
    void advanceBy(double seconds) { advanceTo(m_nowS + seconds); }

private:
    double m_nowS;
};

/// Simulated time running `speed` times faster than the wall clock (paper 000: a part takes 6 min;
/// at speed 360 a part takes a second). The speed can change at any moment without a jump in time;
/// speed 0 freezes it. Thread-safe: the GUI sets the speed while the loop thread reads the time.
class ScaledClock final : public Clock {
public:
    /// Starts at `startS` seconds running `speed` times as fast as the wall clock; throws as setSpeed.
    explicit ScaledClock(double speed = 1.0, double startS = 0.0);
    double nowS() const override;
    /// Throws std::invalid_argument for a negative or non-finite speed.
    void setSpeed(double speed);
    /// Simulated seconds per wall-clock second.
    double speed() const;

private:
    using Wall = std::chrono::steady_clock;
    double simulatedAt(Wall::time_point wall) const;

    mutable std::mutex m_mutex;
    Wall::time_point m_baseWall;
    double m_baseS;
    double m_speed;
};

}  // namespace tt::core
