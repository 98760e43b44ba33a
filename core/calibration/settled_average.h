#pragma once

#include <limits>

namespace tt::core {

/// Where a capture that holds still and then averages stands.
enum class HoldPhase { Idle, HoldStill, Averaging };

/// "Hold still, then average" of a calibration step, on the time stamps of the samples (the device
/// clock, not the caller's): values that arrive within `settleS` of the first sample after start()
/// are not used (the load, the filter and the slide settle), then values are averaged until
/// `count` have been taken or `windowS` has passed after the settling. Pure bookkeeping, no I/O.
class SettledAverage {
public:
    enum class Phase { Idle, HoldStill, Averaging, Done };

    /// `settleS` ≥ 0, `count` ≥ 1 values, `windowS` > 0 (infinity: until `count`); throws
    /// std::invalid_argument otherwise.
    SettledAverage(double settleS, int count, double windowS = std::numeric_limits<double>::infinity());

    /// Starts a new average (HoldStill); the clock starts at the next time seen.
    void start();
    /// Back to Idle, forgetting the values.
    void stop();
    /// Time has reached `timeS` (a sample without a value to average); moves HoldStill →
    /// Averaging → Done as the time passes the settling and the window.
    void observe(double timeS);
    /// A value at `timeS`: averaged once the settling is over. Non-finite values are ignored.
    void add(double timeS, double value);

    Phase phase() const { return m_phase; }
    /// The phase as a capture shows it: Done counts as Idle.
    HoldPhase holdPhase() const;
    bool running() const { return m_phase == Phase::HoldStill || m_phase == Phase::Averaging; }
    /// Values averaged so far.
    int count() const { return m_count; }
    /// Their mean; 0 before the first.
    double mean() const { return m_count > 0 ? m_sum / m_count : 0.0; }
    /// 0..1: how far the step is (settling and averaging), for a progress bar.
    double progress() const;

private:
    double m_settleS;
    int m_target;
    double m_windowS;
    Phase m_phase = Phase::Idle;
    bool m_started = false;  ///< the first time of this step has been seen
    double m_startS = 0.0;
    double m_lastS = 0.0;
    double m_sum = 0.0;
    int m_count = 0;
};

}  // namespace tt::core
