#pragma once

#include <memory>
#include <optional>

#include "core/run/boring_run.h"
#include "core/sim/boring/boring_machine.h"
#include "ui/boring/boring_rig.h"
#include "ui/boring/compensation_loop.h"

namespace tt::ui {

/// The built-in simulated boring station, so the compensation can be seen without a machine: the
/// boring pass of a preset (core::BoringMachine: slender bar, cross feed with friction and dither,
/// probe mandrel) with the compensation running on its ports every PLC cycle, and a twin pass of
/// the same bore without compensation, so the bore error with and without is shown side by side.
/// With the probe source the mandrel is first calibrated on the simulated stand.
class SimulatedBoringStation final : public BoringRig {
public:
    /// `settings.plcCycleS` replaces the scenario's PLC cycle. Throws std::invalid_argument for a
    /// bad scenario or settings (see CompensationLoop), core::LinearisationRefused when the
    /// mandrel's calibration fails.
    SimulatedBoringStation(core::BoringScenario scenario, const BoringRunSettings& settings);

    BoringCycleView cycle() override;
    double plcCycleS() const override { return m_scenario.plcCycleS; }
    bool finished() const override;
    void setSegment(core::SegmentKind kind) override { m_loop->setSegment(kind); }
    double offsetMm() const override { return m_loop->offsetMm(); }
    core::OutputResult zeroOffset() override;

    /// Fault switch: the source's read-out (drive or mandrel) goes silent, as an unplugged cable.
    void setSourceSilent(bool silent);
    bool sourceSilent() const { return m_silent; }
    /// The probe calibration done before a probe run.
    const std::optional<core::ProbeCalibrationSummary>& calibration() const { return m_calibration; }
    const core::BoringScenario& scenario() const { return m_scenario; }
    const core::BoringMachine& machine() const { return *m_machine; }

private:
    core::BoringScenario m_scenario;
    BoringSource m_source;
    std::unique_ptr<core::BoringMachine> m_machine;
    std::unique_ptr<core::BoringMachine> m_twin;  ///< the same pass without compensation
    std::optional<core::ProbeCalibrationSummary> m_calibration;
    std::unique_ptr<CompensationLoop> m_loop;
    bool m_silent = false;
};

}  // namespace tt::ui
