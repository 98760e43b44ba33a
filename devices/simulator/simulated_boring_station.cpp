#include "devices/simulator/simulated_boring_station.h"

#include "core/sim/boring/simulated_boring_pass.h"

namespace tt::devices {

SimulatedBoringStation::SimulatedBoringStation(core::BoringMethod method,
                                               std::function<core::DeviceHealth()> deviceHealth)
    : m_method(method), m_healthOfDevice(std::move(deviceHealth)) {}

SimulatedBoringStation::~SimulatedBoringStation() = default;

std::shared_ptr<core::BoringStation> SimulatedBoringStation::beginPass(const core::BoringScenario& scenario) {
    auto pass = std::make_shared<core::SimulatedBoringPass>(scenario, m_method, true);
    if (m_healthOfDevice) m_deviceHealth = m_healthOfDevice();
    apply(*pass);
    m_pass = pass;
    return pass;
}

void SimulatedBoringStation::follow(const core::DeviceHealth& deviceHealth) {
    const bool changed = deviceHealth.state != m_deviceHealth.state || deviceHealth.message != m_deviceHealth.message;
    m_deviceHealth = deviceHealth;
    if (!changed) return;
    if (const std::shared_ptr<core::SimulatedBoringPass> pass = m_pass.lock()) apply(*pass);
}

void SimulatedBoringStation::apply(core::SimulatedBoringPass& pass) const {
    pass.overrideSourceHealth(m_deviceHealth.ready() ? std::nullopt : std::optional(m_deviceHealth));
}

}  // namespace tt::devices
