#pragma once

namespace tt::core {

/// What simulated devices know about their own future, so a simulation can jump from event to event
/// instead of waiting: the next simulated time at which something changes (a part ends, a reading
/// arrives, a fault starts or stops); +infinity when nothing is scheduled.
class SimulationTimeline {
public:
    virtual ~SimulationTimeline() = default;
    /// Simulated time of the next thing that happens, s; +infinity when nothing is scheduled.
    virtual double nextEventTimeS() const = 0;
};

}  // namespace tt::core
