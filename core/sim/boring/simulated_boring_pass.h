#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>

#include "core/control/in_process_compensation.h"
#include "core/ports/boring_station.h"
#include "core/sim/boring/boring_machine.h"

namespace tt::core {

/// The probe calibration done on the simulator before a probe run.
struct ProbeCalibrationSummary {
    int points = 0;
    int degree = 0;
    double rmsResidualUm = 0.0;
    double maxTableErrorUm = 0.0;
    std::uint32_t imageCrc = 0;  ///< CRC-32C the loaded table image carries (format 2)
};

/// Calibrates the probe mandrel of `machine` on the simulated stand (`scenario.calibration`: loads
/// on the bar tip against a dial indicator), linearises it, and loads the table into the mandrel
/// the way an upload does: the image is encoded, then decoded with its CRC checked on the
/// mandrel's side. Throws core::LinearisationRefused when the calibration cannot be fitted.
ProbeCalibrationSummary calibrateMandrel(BoringMachine& machine, const BoringScenario& scenario);

/// One simulated boring pass as a boring station (paper 001): the machine of `scenario` (slender
/// bar, cross feed with friction, probe mandrel) with its ports, moved on one PLC cycle at a time
/// by the thread that runs the compensation, so the two stay in lock-step at any speed; optionally
/// a twin of the same pass without compensation (same scenario and seed, no dither), so the truth
/// gives the bore error with and without. With the probe method the mandrel is first calibrated
/// on the simulated stand. Used from one thread, except overrideSourceHealth().
class SimulatedBoringPass final : public BoringStation {
public:
    /// `method`: Current switches the dither on; Probe calibrates the mandrel first. Throws
    /// std::invalid_argument for a bad scenario, core::LinearisationRefused when the mandrel's
    /// calibration fails.
    SimulatedBoringPass(const BoringScenario& scenario, BoringMethod method, bool withTwin);
    ~SimulatedBoringPass() override;

    DriveCurrentReadout* driveReadout() override;
    DeflectionProbe* probe() override;
    CorrectionOutput& output() override { return m_machine.output(); }
    const Clock& clock() const override;
    void advanceCycle() override;
    bool finished() const override { return m_machine.finished(); }
    std::optional<double> plcCycleS() const override { return m_scenario.plcCycleS; }
    bool runsAheadOfTime() const override { return true; }
    std::optional<BoringPassTruth> truth() const override;

    /// Thread-safe (a fault switch in another thread): from now on the port of the method's source
    /// reports `health` (silent, unplugged) and delivers nothing; nullopt: back to the machine's own.
    void overrideSourceHealth(std::optional<DeviceHealth> health);
    /// The probe calibration done before a probe pass.
    const std::optional<ProbeCalibrationSummary>& calibration() const { return m_calibration; }
    /// The compensated machine (its state, its surface observer).
    BoringMachine& machine() { return m_machine; }
    const BoringScenario& scenario() const { return m_scenario; }
    BoringMethod method() const { return m_method; }

private:
    class SourceGate;
    template <class Port>
    class Gated;
    class PassClock;

    BoringScenario m_scenario;
    BoringMethod m_method;
    BoringMachine m_machine;
    std::unique_ptr<BoringMachine> m_twin;  ///< the same pass without compensation
    std::optional<ProbeCalibrationSummary> m_calibration;
    std::unique_ptr<SourceGate> m_gate;
    std::unique_ptr<Gated<DriveCurrentReadout>> m_drive;
    std::unique_ptr<Gated<DeflectionProbe>> m_probe;
    std::unique_ptr<PassClock> m_clock;
};

}  // namespace tt::core
