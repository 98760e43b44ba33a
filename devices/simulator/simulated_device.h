#pragma once

#include <QTimer>
#include <cstdint>

#include "devices/api/device_base.h"
#include "devices/api/simulated_instrument.h"

namespace tt::devices {

/// Base of the built-in simulator's devices: a timer that drives them while open, the fault
/// switches (a disconnected device is in error until the switch is released, then reconnects),
/// noise, and no-op simulation inputs that each device overrides where they apply.
class SimulatedDevice : public DeviceBase, public SimulatedInstrument, public SimulationInputs {
public:
    SimulatedDevice(DeviceKind kind, const DeviceContext& context, int tickMs);
    ~SimulatedDevice() override;

    void open() override;
    void close() override;
    FaultSwitches& faultSwitches() override { return m_faults; }
    SimulationInputs& simulationInputs() override { return *this; }

    void setDiameterSource(std::function<double()>) override {}
    void setDeflectionSource(std::function<std::array<double, 2>(double)>) override {}
    void setDriveSource(std::function<core::DriveSample(double)>) override {}
    void setCorrectionSink(std::function<void(const core::PartCorrection&)>) override {}
    void setOffsetSink(std::function<void(double)>) override {}

protected:
    /// Called every tick while open and plugged in.
    virtual void tick() = 0;
    /// Called when the device (re)connects: after open() and after the unplug switch is released.
    virtual void connected() = 0;
    /// Called after every heartbeat (plugged in or not) and on close(), when the state is settled.
    virtual void stateChecked() {}
    bool isOpen() const { return m_open; }
    bool unplugged() const { return m_faults.disconnected; }
    const FaultSwitches& faults() const { return m_faults; }
    /// Uniform noise in +-noiseAmplitude when the noisy switch is on, else 0.
    double noise();
    /// "the simulated gauge", for messages.
    QString what() const;

private:
    void heartbeat();

    QTimer m_timer;
    FaultSwitches m_faults;
    bool m_open = false;
    bool m_wasUnplugged = false;
    std::uint32_t m_random = 0x2545F491u;
};

}  // namespace tt::devices
