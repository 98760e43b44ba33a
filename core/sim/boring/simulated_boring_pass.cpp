#include "core/sim/boring/simulated_boring_pass.h"

#include <atomic>
#include <utility>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/sim/rigs/probe_calibration_rig.h"

namespace tt::core {

ProbeCalibrationSummary calibrateMandrel(BoringMachine& machine, const BoringScenario& scenario) {
    ProbeCalibrationRig rig(machine.probeSensor(), 0, scenario.calibration.referenceResolutionUm,
                            scenario.calibration.referenceNoiseUm, scenario.seed * 7919ULL + 3);
    const std::vector<CalibrationPoint> points = rig.sweep(scenario.calibration);
    const Linearisation lin = linearise(points, scenario.probe.adcBits, scenario.calibration.degree);
    TableImageInfo info;
    info.degree = static_cast<std::uint8_t>(lin.fit.degree);
    const std::vector<std::uint8_t> image = encodeTableImage(lin.table, info);
    const TableImage loaded = decodeTableImage(image);
    machine.probeSensor().setTable(0, loaded.table);
    machine.probeSensor().settle(0.0, 0.0);
    ProbeCalibrationSummary summary;
    summary.points = static_cast<int>(points.size());
    summary.degree = lin.fit.degree;
    summary.rmsResidualUm = lin.fit.rmsResidualUm;
    summary.maxTableErrorUm = lin.maxTableErrorUm;
    summary.imageCrc = loaded.crc;
    return summary;
}

/// The health the source's port reports instead of the machine's (a fault switch), guarded: it is
/// set from the thread the switch lives in. Open, it costs the pass's thread one atomic load.
class SimulatedBoringPass::SourceGate {
public:
    void set(std::optional<DeviceHealth> health) {
        std::lock_guard lock(m_mutex);
        m_shut.store(health.has_value(), std::memory_order_release);
        m_health = std::move(health);
    }
    std::optional<DeviceHealth> get() const {
        if (!m_shut.load(std::memory_order_acquire)) return std::nullopt;
        std::lock_guard lock(m_mutex);
        return m_health;
    }

private:
    std::atomic<bool> m_shut = false;
    mutable std::mutex m_mutex;
    std::optional<DeviceHealth> m_health;
};

/// A port of the machine (drive read-out or probe mandrel) behind the gate: while the gate is shut
/// the port reports the gate's health and delivers nothing (the samples wait on the machine, as on
/// a silent bus).
template <class Port>
class SimulatedBoringPass::Gated final : public Port {
public:
    using Sample = decltype(std::declval<Port&>().takeSample());
    /// `gate` null: this port is not the pass's source.
    Gated(Port& port, const SourceGate* gate) : m_port(port), m_gate(gate) {}
    DeviceHealth health() const override {
        if (m_gate)
            if (std::optional<DeviceHealth> h = m_gate->get()) return *h;
        return m_port.health();
    }
    Sample takeSample() override {
        if (m_gate && m_gate->get()) return std::nullopt;
        return m_port.takeSample();
    }

private:
    Port& m_port;
    const SourceGate* m_gate;
};

/// The pass's time: the compensated machine's.
class SimulatedBoringPass::PassClock final : public Clock {
public:
    explicit PassClock(const BoringMachine& machine) : m_machine(machine) {}
    double nowS() const override { return m_machine.state().timeS; }

private:
    const BoringMachine& m_machine;
};

SimulatedBoringPass::SimulatedBoringPass(const BoringScenario& scenario, BoringMethod method, bool withTwin)
    : m_scenario(scenario),
      m_method(method),
      m_machine(scenario, method == BoringMethod::Current),
      m_gate(std::make_unique<SourceGate>()),
      m_drive(std::make_unique<Gated<DriveCurrentReadout>>(m_machine.driveReadout(),
                                                           method == BoringMethod::Current ? m_gate.get() : nullptr)),
      m_probe(std::make_unique<Gated<DeflectionProbe>>(m_machine.probe(),
                                                       method == BoringMethod::Probe ? m_gate.get() : nullptr)),
      m_clock(std::make_unique<PassClock>(m_machine)) {
    if (withTwin) m_twin = std::make_unique<BoringMachine>(scenario, false);
    if (method == BoringMethod::Probe) m_calibration = calibrateMandrel(m_machine, m_scenario);
}

SimulatedBoringPass::~SimulatedBoringPass() = default;

DriveCurrentReadout* SimulatedBoringPass::driveReadout() {
    return m_drive.get();
}

DeflectionProbe* SimulatedBoringPass::probe() {
    return m_probe.get();
}

const Clock& SimulatedBoringPass::clock() const {
    return *m_clock;
}

void SimulatedBoringPass::advanceCycle() {
    m_machine.advanceCycle();
    if (m_twin && !m_twin->finished()) m_twin->advanceCycle();
}

std::optional<BoringPassTruth> SimulatedBoringPass::truth() const {
    const BoringState& s = m_machine.state();
    BoringPassTruth t;
    t.timeS = s.timeS;
    t.zMm = s.toolZMm;
    t.cutting = s.cutting;
    t.deflectionMm = s.tipDeflectionXmm;
    t.forceN = s.radialForceN;
    t.diameterErrorMm = 2.0 * s.radiusErrorMm;
    if (m_twin) t.uncompensatedErrorMm = 2.0 * m_twin->state().radiusErrorMm;
    return t;
}

void SimulatedBoringPass::overrideSourceHealth(std::optional<DeviceHealth> health) {
    m_gate->set(std::move(health));
}

}  // namespace tt::core
