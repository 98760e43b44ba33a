#include "core/loop/manual_gauge.h"

namespace tt::core {

std::optional<GaugeReading> ManualGauge::takeReading() {
    std::lock_guard lock(m_mutex);
    if (m_readings.empty()) return std::nullopt;
    GaugeReading r = m_readings.front();
    m_readings.pop_front();
    return r;
}

void ManualGauge::push(const GaugeReading& reading) {
    std::lock_guard lock(m_mutex);
    m_readings.push_back(reading);
}

DeviceHealth SelectableGauge::health() const {
    return m_isManual ? m_manual.health() : m_automatic.health();
}

void SelectableGauge::requestReading() {
    if (!m_isManual) m_automatic.requestReading();
}

std::optional<GaugeReading> SelectableGauge::takeReading() {
    if (auto r = m_manual.takeReading()) return r;
    if (m_isManual) return std::nullopt;
    return m_automatic.takeReading();
}

}  // namespace tt::core
