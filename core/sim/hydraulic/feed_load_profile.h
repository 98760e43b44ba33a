#pragma once

#include <vector>

namespace tt::core {

/// One change of the load on the carriage: from timeS the load moves linearly to forceN over
/// durationS (a step when durationS is 0).
struct FeedLoadEvent {
    double timeS = 0.0;
    double durationS = 0.0;
    double forceN = 0.0;
};

/// The load on the carriage over time (the cutting force at the set feed, paper 003's R_H + R_tp):
/// zero at first, then piecewise linear through steps and ramps that do not overlap.
class FeedLoadProfile {
public:
    static constexpr double kMaxForceN = 1.0e4;  ///< far above any finishing cut
    static constexpr double kMaxTimeS = 60.0;    ///< longer than any transient of the drive

    /// A load of zero throughout.
    FeedLoadProfile() = default;
    /// A single step to `forceN` at `timeS`.
    static FeedLoadProfile step(double timeS, double forceN);

    /// From `timeS` on, the load is `forceN`. Throws std::invalid_argument for a time outside
    /// 0 .. 60 s, a force outside 0 .. 1e4 N, or a time inside another ramp.
    void addStep(double timeS, double forceN);
    /// From `timeS` the load moves linearly to `forceN` over `durationS` (> 0, ≤ 60 s); same checks.
    void addRamp(double timeS, double durationS, double forceN);

    /// The load at `timeS` (after a step at exactly timeS), N.
    double forceAt(double timeS) const;
    /// Where the load jumps or changes slope, sorted, without duplicates, s.
    std::vector<double> breakpoints() const;
    /// The start of the last event (0 without events), s.
    double lastEventS() const;
    /// The largest load, N.
    double maxForceN() const;
    /// The events in time order.
    const std::vector<FeedLoadEvent>& events() const { return m_events; }
    bool empty() const { return m_events.empty(); }

private:
    void add(const FeedLoadEvent& event);

    std::vector<FeedLoadEvent> m_events;
};

}  // namespace tt::core
