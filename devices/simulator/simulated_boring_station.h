#pragma once

#include <functional>
#include <memory>

#include "core/control/in_process_compensation.h"
#include "core/ports/device_health.h"
#include "devices/api/boring_truth.h"

namespace tt::core {
class SimulatedBoringPass;
}

namespace tt::devices {

/// The simulator's boring station behind its drive read-out (current with dither) or probe
/// mandrel: each pass is a core::SimulatedBoringPass with its twin without compensation, run on
/// its own ports and PLC in lock-step with the compensation, in whatever thread runs it. The
/// device tells the station its health after every heartbeat (follow()), and the station passes
/// it on to the live pass: while the device is not ready (its fault switches: silent, unplugged)
/// the pass's source reports the device's health, with the device's own message, and delivers
/// nothing. Lives in the device's thread; only the pass leaves it.
class SimulatedBoringStation final : public BoringTruth {
public:
    /// `method`: Current (the drive read-out) or Probe (the mandrel); `deviceHealth` tells the
    /// device's health when a pass begins.
    SimulatedBoringStation(core::BoringMethod method, std::function<core::DeviceHealth()> deviceHealth);
    ~SimulatedBoringStation() override;

    std::shared_ptr<core::BoringStation> beginPass(const core::BoringScenario& scenario) override;
    /// The device's health now (from the device's thread): the live pass's source follows it.
    void follow(const core::DeviceHealth& deviceHealth);

private:
    void apply(core::SimulatedBoringPass& pass) const;

    core::BoringMethod m_method;
    std::function<core::DeviceHealth()> m_healthOfDevice;
    core::DeviceHealth m_deviceHealth{core::DeviceState::Disconnected, {}};
    std::weak_ptr<core::SimulatedBoringPass> m_pass;
};

}  // namespace tt::devices
