#include "ui/devices/device_status_bridge.h"

#include "runtime/devices/device_hub.h"
#include "ui/app_state.h"

namespace tt::ui {

DeviceStatusBridge::DeviceStatusBridge(runtime::DeviceHub& hub, AppState& state, QObject* parent)
    : QObject(parent), m_hub(hub), m_state(state) {
    connect(&hub, &runtime::DeviceHub::devicesChanged, this, &DeviceStatusBridge::update);
    connect(&hub, &runtime::DeviceHub::deviceChanged, this, &DeviceStatusBridge::update);
    update();
}

void DeviceStatusBridge::update() {
    const runtime::DeviceSummary summary = m_hub.summary();
    AppState::Tone tone = AppState::Tone::Idle;
    switch (summary.tone) {
        case runtime::DeviceSummary::Tone::Ok:
            tone = AppState::Tone::Ok;
            break;
        case runtime::DeviceSummary::Tone::Warning:
            tone = AppState::Tone::Warning;
            break;
        case runtime::DeviceSummary::Tone::Fault:
            tone = AppState::Tone::Fault;
            break;
        case runtime::DeviceSummary::Tone::None:
            break;
    }
    m_state.setDevices(tone, summary.text);
}

}  // namespace tt::ui
