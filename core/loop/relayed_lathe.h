#pragma once

#include <cstddef>
#include <optional>

#include "core/loop/correction_relay.h"
#include "core/loop/gauge_relay.h"
#include "core/loop/loop_clock.h"
#include "core/loop/operator_cycle.h"
#include "core/ports/shaft_machine.h"

namespace tt::core {

/// The real lathe as a ShaftMachine, seen from the loop's thread: the devices live in another thread (the
/// device thread's), joined through relays that the device side pumps (runtime/devices/lathe_link.h): the CNC output's
/// writes go through a CorrectionRelay, the gauge's readings through a GaugeRelay, and the part cycle is the operator's
/// (OperatorCycle: the Part finished button). Its time is the wall clock. Every member is thread-safe.
class RelayedLathe final : public ShaftMachine {
public:
    /// `outputNominalDiameterMm`: the diameter the CNC output writes its programs for, if it has one.
    explicit RelayedLathe(std::optional<double> outputNominalDiameterMm = std::nullopt);

    MachineCycle& cycle() override { return m_cycle; }
    CorrectionOutput& output() override { return m_output; }
    DiameterGauge& gauge() override { return m_gauge; }
    const Clock& clock() const override { return m_clock; }
    std::size_t setManualEntry(bool manual) override;
    std::optional<double> outputNominalDiameterMm() const override { return m_outputNominalMm; }
    std::optional<std::int64_t> partOnMachine() const override { return m_cycle.partOnMachine(); }
    std::optional<std::int64_t> confirmPartFinished() override { return m_cycle.finishPart(); }

    // ---- the device side (another thread) ----
    GaugeRelay& gaugeRelay() { return m_gauge; }
    CorrectionRelay& outputRelay() { return m_output; }
    OperatorCycle& operatorCycle() { return m_cycle; }

private:
    ScaledClock m_clock{1.0};
    GaugeRelay m_gauge{m_clock};
    CorrectionRelay m_output;
    OperatorCycle m_cycle{m_clock};
    std::optional<double> m_outputNominalMm;
    bool m_manual = false;
};

}  // namespace tt::core
