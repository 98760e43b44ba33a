#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>

#include "core/ports/clock.h"
#include "core/ports/machine_cycle.h"

namespace tt::core {

/// The part cycle of a lathe run by the operator: once the loop has put the corrections of the next part on
/// the CNC it starts the part (the operator machines it with those corrections), and the operator confirms
/// that it came off the machine (the Run page's "Part finished" button). Only one part is on the machine at
/// a time. Thread-safe: the loop's thread starts and takes parts, the GUI's thread finishes them.
class OperatorCycle final : public MachineCycle {
public:
    /// `clock`: stamps finished parts with the loop's time (thread-safe, outlives the cycle).
    explicit OperatorCycle(const Clock& clock) : m_clock(clock) {}

    // ---- the loop's side ----
    /// Always ready: the operator is the cycle-end signal.
    DeviceHealth health() const override;
    /// Puts part `partNumber` on the machine; refused while another part is on it.
    OutputResult startPart(std::int64_t partNumber) override;
    /// The oldest part the operator confirmed and the loop has not taken yet.
    std::optional<FinishedPart> takeFinishedPart() override;

    // ---- the operator's side ----
    /// The part being machined (started and not yet confirmed), if any.
    std::optional<std::int64_t> partOnMachine() const;
    /// The operator confirms the part on the machine is finished; returns its number, or nothing when no part
    /// is on the machine (a second press of the button does nothing).
    std::optional<std::int64_t> finishPart();

private:
    const Clock& m_clock;
    mutable std::mutex m_mutex;
    std::optional<std::int64_t> m_onMachine;
    std::deque<FinishedPart> m_finished;
};

}  // namespace tt::core
