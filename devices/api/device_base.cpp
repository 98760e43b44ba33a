#include "devices/api/device_base.h"

#include <stdexcept>

#include "core/ports/clock.h"

namespace tt::devices {

DeviceBase::DeviceBase(DeviceKind kind, const DeviceContext& context) : m_kind(kind), m_clock(context.clock) {
    if (!m_clock) throw std::invalid_argument("device: no clock given");
}

void DeviceBase::setState(core::DeviceState state, const QString& message) {
    const std::string text = message.toStdString();
    if (state == m_health.state && text == m_health.message) return;
    m_health.state = state;
    m_health.message = text;
    // An error state is an error: the Devices page's "Last error" names it (a refused Modbus connection,
    // an unplugged device), and keeps naming it after the device recovers.
    if (state == core::DeviceState::Error && !message.isEmpty()) m_lastError = message;
    notifyChanged();
}

void DeviceBase::setLiveValue(const QString& value) {
    if (value == m_liveValue) return;
    m_liveValue = value;
    notifyChanged();
}

void DeviceBase::reportError(const QString& message) {
    m_lastError = message;
    notifyChanged();
}

double DeviceBase::now() const {
    return m_clock->nowS();
}

}  // namespace tt::devices
